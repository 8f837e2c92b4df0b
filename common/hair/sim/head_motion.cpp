#include "hair/sim/head_motion.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <string_view>
#include <utility>

#include "hair/core/error.h"

namespace hair {
namespace {

constexpr double kPi = std::numbers::pi;

/// Columns a keyframe CSV may name, in the order of HeadKeyframe's fields.
constexpr std::array<std::string_view, 7> kColumns = {
    "time_s", "yaw_deg", "pitch_deg", "roll_deg", "offset_x_m", "offset_y_m", "offset_z_m"};

/// Rotations of a pose within this angle (rad) and offsets within this distance (m) are
/// the same pose for is_still().
constexpr double kSamePoseTolerance = 1e-12;

double radians(double angle_deg) { return angle_deg * kPi / 180.0; }

/// R = Ry(yaw) * Rx(pitch) * Rz(roll).
Eigen::Quaterniond rotation_of(const HeadKeyframe& pose) {
  Eigen::Quaterniond rotation =
      Eigen::AngleAxisd(radians(pose.yaw_deg), Eigen::Vector3d::UnitY()) *
      Eigen::AngleAxisd(radians(pose.pitch_deg), Eigen::Vector3d::UnitX()) *
      Eigen::AngleAxisd(radians(pose.roll_deg), Eigen::Vector3d::UnitZ());
  return rotation.normalized();
}

/// Smootherstep ramp from 0 at t = 0 to 1 at t = ramp_s, with zero first and second
/// derivatives at both ends.
double ramp(double time_s, double ramp_s) {
  double u = std::clamp(time_s / ramp_s, 0.0, 1.0);
  return u * u * u * (u * (6 * u - 15) + 10);
}

/// The integral of ramp() from 0 to `time_s`, seconds: the distance covered at unit speed
/// reached through the ramp.
double ramp_integral_s(double time_s, double ramp_s) {
  if (time_s >= ramp_s) return time_s - ramp_s / 2;
  double u = std::max(time_s / ramp_s, 0.0);
  double u4 = u * u * u * u;
  return ramp_s * u4 * (u * (u - 3) + 2.5);
}

/// amplitude * sin(2 pi frequency t), ramped in over half a period.
double ramped_sine(double time_s, double amplitude, double frequency_hz) {
  return amplitude * ramp(time_s, 0.5 / frequency_hz) * std::sin(2 * kPi * frequency_hz * time_s);
}

HeadKeyframe still_pose(double) { return {}; }

HeadKeyframe nod_pose(double time_s) {
  HeadKeyframe pose;
  pose.pitch_deg = ramped_sine(time_s, 20.0, 1.0);
  return pose;
}

HeadKeyframe shake_pose(double time_s) {
  HeadKeyframe pose;
  pose.yaw_deg = ramped_sine(time_s, 30.0, 1.5);
  return pose;
}

HeadKeyframe turn_pose(double time_s) {
  HeadKeyframe pose;
  pose.yaw_deg = 30.0 * (1 - std::cos(2 * kPi * time_s / 4.0));
  return pose;
}

HeadKeyframe walk_pose(double time_s) {
  constexpr double kSpeed_m_per_s = 1.2, kStartRamp_s = 0.5;
  HeadKeyframe pose;
  double r = ramp(time_s, kStartRamp_s);
  pose.offset_m.z() = kSpeed_m_per_s * ramp_integral_s(time_s, kStartRamp_s);
  pose.offset_m.y() = 0.015 * r * std::sin(2 * kPi * 2.0 * time_s);
  pose.offset_m.x() = 0.02 * r * std::sin(2 * kPi * 1.0 * time_s);
  pose.pitch_deg = 3.0 * r * std::sin(2 * kPi * 2.0 * time_s);
  return pose;
}

HeadKeyframe violent_shake_pose(double time_s) {
  HeadKeyframe pose;
  pose.yaw_deg = ramped_sine(time_s, 45.0, 4.0);
  return pose;
}

/// A preset: its name, pose and natural duration.
struct Preset {
  std::string_view name;
  HeadKeyframe (*pose)(double time_s);
  double natural_duration_s;
};

constexpr std::array<Preset, 6> kPresets = {{
    {"still", still_pose, 1.0},
    {"nod", nod_pose, 2.0},
    {"shake", shake_pose, 2.0},
    {"turn", turn_pose, 4.0},
    {"walk", walk_pose, 2.0},
    {"violent_shake", violent_shake_pose, 1.0},
}};

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

void check_pivot(const Eigen::Vector3d& pivot_m) {
  if (!pivot_m.allFinite()) throw Error::usage("head motion pivot is not finite");
}

/// `number` with as many significant digits as it needs.
std::string shown(double number) {
  std::array<char, 32> text{};
  auto [end, error] = std::to_chars(text.data(), text.data() + text.size(), number);
  return error == std::errc() ? std::string(text.data(), end) : std::to_string(number);
}

/// Checks that keyframes are usable; `fail(i, reason)` makes the error for keyframe i.
void check_keyframes(const std::vector<HeadKeyframe>& keyframes,
                     const std::function<Error(size_t, const std::string&)>& fail) {
  for (size_t i = 0; i < keyframes.size(); ++i) {
    const HeadKeyframe& key = keyframes[i];
    if (!std::isfinite(key.time_s) || !std::isfinite(key.yaw_deg) ||
        !std::isfinite(key.pitch_deg) || !std::isfinite(key.roll_deg) || !key.offset_m.allFinite())
      throw fail(i, "a value is not finite");
    if (i == 0 && key.time_s < 0)
      throw fail(i, "time_s " + shown(key.time_s) + " is negative (the first time must be >= 0)");
    if (i > 0 && !(key.time_s > keyframes[i - 1].time_s))
      throw fail(i, "time_s " + shown(key.time_s) + " is not after the previous keyframe's " +
                        shown(keyframes[i - 1].time_s) + " (times must increase strictly)");
  }
}

/// `text` without spaces, tabs or carriage returns at either end.
std::string_view trimmed(std::string_view text) {
  constexpr std::string_view kSpace = " \t\r\n\f\v";
  size_t first = text.find_first_not_of(kSpace);
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(kSpace) - first + 1);
}

/// The trimmed comma-separated cells of a line.
std::vector<std::string_view> split_cells(std::string_view line) {
  std::vector<std::string_view> cells;
  size_t start = 0;
  for (size_t comma = line.find(','); comma != std::string_view::npos;
       comma = line.find(',', start)) {
    cells.push_back(trimmed(line.substr(start, comma - start)));
    start = comma + 1;
  }
  cells.push_back(trimmed(line.substr(start)));
  return cells;
}

/// The number filling `cell` (an optional leading '+' allowed), infinity for a number out
/// of the range of double; none otherwise.
std::optional<double> parsed_number(std::string_view cell) {
  if (!cell.empty() && cell.front() == '+') cell.remove_prefix(1);
  double value = 0;
  auto [end, error] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
  if (cell.empty() || end != cell.data() + cell.size()) return std::nullopt;
  if (error == std::errc::result_out_of_range) return std::numeric_limits<double>::infinity();
  if (error != std::errc()) return std::nullopt;
  return value;
}

/// The field of `key` that column `column` (an index into kColumns) fills.
double& field(HeadKeyframe& key, size_t column) {
  switch (column) {
    case 0:
      return key.time_s;
    case 1:
      return key.yaw_deg;
    case 2:
      return key.pitch_deg;
    case 3:
      return key.roll_deg;
    default:
      return key.offset_m[static_cast<Eigen::Index>(column - 4)];
  }
}

std::string column_list() {
  std::string text;
  for (std::string_view column : kColumns) text += (text.empty() ? "" : ", ") + std::string(column);
  return text;
}

}  // namespace

Eigen::Vector3d RigidTransform::apply(const Eigen::Vector3d& point_m) const {
  return rotation * point_m + translation_m;
}

Eigen::Vector3d RigidTransform::apply_inverse(const Eigen::Vector3d& point_m) const {
  return rotation.conjugate() * (point_m - translation_m);
}

Eigen::Vector3d RigidTransform::rotate(const Eigen::Vector3d& direction) const {
  return rotation * direction;
}

Eigen::Matrix4d RigidTransform::matrix() const {
  Eigen::Matrix4d matrix = Eigen::Matrix4d::Identity();
  matrix.topLeftCorner<3, 3>() = rotation.toRotationMatrix();
  matrix.topRightCorner<3, 1>() = translation_m;
  return matrix;
}

const std::vector<std::string>& HeadMotion::preset_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> result;
    for (const Preset& preset : kPresets) result.emplace_back(preset.name);
    return result;
  }();
  return names;
}

HeadMotion HeadMotion::preset(const std::string& name, const Eigen::Vector3d& pivot_m) {
  for (const Preset& preset : kPresets) {
    if (preset.name != name) continue;
    check_pivot(pivot_m);
    HeadMotion motion;
    motion.name_ = name;
    motion.pivot_m_ = pivot_m;
    motion.preset_pose_ = preset.pose;
    motion.natural_duration_s_ = preset.natural_duration_s;
    motion.still_ = preset.pose == still_pose;
    return motion;
  }
  throw Error::usage("unknown head motion '" + name + "' (expected one of " +
                     joined(preset_names()) + ")");
}

HeadMotion HeadMotion::from_keyframes(std::vector<HeadKeyframe> keyframes,
                                      const Eigen::Vector3d& pivot_m, const std::string& source) {
  check_pivot(pivot_m);
  if (keyframes.empty()) throw Error(ErrorKind::usage, source, {}, "no keyframes");
  check_keyframes(keyframes, [&](size_t i, const std::string& reason) {
    return Error(ErrorKind::usage, source, "keyframe " + std::to_string(i), reason);
  });

  HeadMotion motion;
  motion.name_ = source;
  motion.pivot_m_ = pivot_m;
  motion.natural_duration_s_ = keyframes.back().time_s;
  motion.still_ = true;
  for (const HeadKeyframe& key : keyframes) {
    motion.key_time_s_.push_back(key.time_s);
    motion.key_rotation_.push_back(rotation_of(key));
    motion.key_offset_m_.push_back(key.offset_m);
    if (motion.key_rotation_.back().angularDistance(motion.key_rotation_.front()) >
            kSamePoseTolerance ||
        (key.offset_m - keyframes.front().offset_m).norm() > kSamePoseTolerance)
      motion.still_ = false;
  }
  return motion;
}

HeadMotion HeadMotion::from_keyframes_csv(const std::string& path, const Eigen::Vector3d& pivot_m) {
  check_pivot(pivot_m);
  std::ifstream in(path);
  if (!in) throw Error::bad_input(path, "cannot open the head motion keyframes");
  auto fail = [&](int64_t line, const std::string& reason) {
    return Error::bad_dataset(path, "line " + std::to_string(line), reason);
  };

  std::vector<size_t> column_of_cell;  // index into kColumns of each cell of a row
  int64_t header_line = 0;
  std::vector<HeadKeyframe> keyframes;
  std::vector<int64_t> line_of_keyframe;
  int64_t line_number = 0;
  for (std::string text; std::getline(in, text);) {
    ++line_number;
    std::string_view line = trimmed(text);
    if (line.empty() || line.front() == '#') continue;
    std::vector<std::string_view> cells = split_cells(line);
    if (header_line == 0) {
      std::array<bool, kColumns.size()> seen{};
      for (std::string_view cell : cells) {
        auto found = std::find(kColumns.begin(), kColumns.end(), cell);
        if (found == kColumns.end())
          throw fail(line_number,
                     "unknown column '" + std::string(cell) + "' (expected " + column_list() + ")");
        auto column = static_cast<size_t>(found - kColumns.begin());
        if (seen[column]) throw fail(line_number, "column " + std::string(cell) + " repeated");
        seen[column] = true;
        column_of_cell.push_back(column);
      }
      if (!seen[0]) throw fail(line_number, "the header has no time_s column");
      header_line = line_number;
      continue;
    }
    if (cells.size() != column_of_cell.size())
      throw fail(line_number, "expected " + std::to_string(column_of_cell.size()) +
                                  " cells as in the header, found " + std::to_string(cells.size()));
    HeadKeyframe key;
    for (size_t c = 0; c < cells.size(); ++c) {
      std::string_view column = kColumns[column_of_cell[c]];
      std::optional<double> value = parsed_number(cells[c]);
      if (!value)
        throw fail(line_number,
                   std::string(column) + " '" + std::string(cells[c]) + "' is not a number");
      if (!std::isfinite(*value))
        throw fail(line_number, std::string(column) + " '" + std::string(cells[c]) +
                                    "' is not a finite number in the range of double");
      field(key, column_of_cell[c]) = *value;
    }
    keyframes.push_back(key);
    line_of_keyframe.push_back(line_number);
  }
  if (in.bad()) throw Error::runtime(path, "read error");
  if (header_line == 0)
    throw Error::bad_input(path, "no header line (columns among " + column_list() + ")");
  if (keyframes.empty())
    throw fail(header_line, "the header is followed by no keyframe (at least 1 needed)");
  check_keyframes(keyframes, [&](size_t i, const std::string& reason) {
    return fail(line_of_keyframe[i], reason);
  });
  return from_keyframes(std::move(keyframes), pivot_m, path);
}

RigidTransform HeadMotion::at(double time_s) const {
  if (!std::isfinite(time_s))
    throw Error::usage("head motion " + name_ + ": time " + shown(time_s) + " is not finite");
  time_s = std::max(time_s, 0.0);

  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d offset_m = Eigen::Vector3d::Zero();
  if (preset_pose_ != nullptr) {
    HeadKeyframe pose = preset_pose_(time_s);
    rotation = rotation_of(pose);
    offset_m = pose.offset_m;
  } else if (time_s <= key_time_s_.front()) {
    rotation = key_rotation_.front();
    offset_m = key_offset_m_.front();
  } else if (time_s >= key_time_s_.back()) {
    rotation = key_rotation_.back();
    offset_m = key_offset_m_.back();
  } else {
    // The keyframes [next - 1, next] bracket the time.
    auto next = static_cast<size_t>(
        std::upper_bound(key_time_s_.begin(), key_time_s_.end(), time_s) - key_time_s_.begin());
    size_t previous = next - 1;
    double u = (time_s - key_time_s_[previous]) / (key_time_s_[next] - key_time_s_[previous]);
    rotation = key_rotation_[previous].slerp(u, key_rotation_[next]).normalized();
    offset_m = (1 - u) * key_offset_m_[previous] + u * key_offset_m_[next];
  }

  RigidTransform transform;
  transform.rotation = rotation;
  transform.translation_m = pivot_m_ + offset_m - rotation * pivot_m_;
  return transform;
}

bool HeadMotion::is_still() const { return still_; }

const std::string& HeadMotion::name() const { return name_; }

double HeadMotion::natural_duration_s() const { return natural_duration_s_; }

}  // namespace hair
