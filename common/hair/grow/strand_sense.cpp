#include "hair/grow/strand_sense.h"

#include "hair/core/error.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

namespace hair {
namespace {

constexpr double kNoLengthM = 1e-9;

/// Points of `points` every `step_m` of arc length from the first (the last point is
/// dropped unless it falls on a step).
std::vector<Eigen::Vector3d> resampled(const Points3f& points, double step_m) {
  std::vector<Eigen::Vector3d> out;
  if (points.rows() == 0) return out;
  out.push_back(point_of(points, 0));
  double to_next = step_m;  // arc length left to the next sample
  for (Eigen::Index i = 0; i + 1 < points.rows(); ++i) {
    const Eigen::Vector3d a = point_of(points, i), b = point_of(points, i + 1);
    const double length = (b - a).norm();
    double at = 0;  // arc length along this segment already passed
    while (length - at >= to_next) {
      at += to_next;
      out.push_back(a + (b - a) * (at / length));
      to_next = step_m;
    }
    to_next -= length - at;
  }
  return out;
}

}  // namespace

bool has_hairpin(const Points3f& points, double turn_deg) {
  // A turn of exactly turn_deg is not sharper than it, whatever the rounding of cos.
  const double cos_limit = std::cos(turn_deg * std::numbers::pi / 180.0) - 1e-9;
  Eigen::Vector3d previous = Eigen::Vector3d::Zero();
  for (Eigen::Index i = 0; i + 1 < points.rows(); ++i) {
    const Eigen::Vector3d d = point_of(points, i + 1) - point_of(points, i);
    const double length = d.norm();
    if (length < kNoLengthM) continue;
    const Eigen::Vector3d direction = d / length;
    if (previous.squaredNorm() > 0 && previous.dot(direction) < cos_limit) return true;
    previous = direction;
  }
  return false;
}

bool AirAroundHair::is_air(const Eigen::Vector3d& point) const {
  if (hair_.is_within(point, air_m_)) return false;
  if (body_ == nullptr) return true;
  const TriangleMeshDistance::Nearest nearest = body_->nearest(point);
  const Eigen::Vector3d out = point - nearest.closest_point;
  if (out.norm() < kNoLengthM) return true;
  const Eigen::Vector3d direction = out.normalized();
  for (double along = air_m_; along <= reach_m_; along += air_m_)
    if (hair_.is_within(point + along * direction, air_m_)) return false;
  return true;
}

AirStretch longest_air_stretch(const Points3f& points, const AirAroundHair& air, double step_m) {
  AirStretch longest;
  const size_t segments = points.rows() > 1 ? static_cast<size_t>(points.rows() - 1) : 0;
  longest.length_by_segment_m.assign(segments, 0.0);
  // The stretch being walked: its length and its length along each segment it touched.
  double stretch = 0;
  std::vector<std::pair<size_t, double>> stretch_segments;
  bool in_air = false;
  Eigen::Vector3d last = Eigen::Vector3d::Zero();
  const auto visit = [&](const Eigen::Vector3d& p, size_t segment) {
    const bool is_air = air.is_air(p);
    if (is_air && in_air) {
      const double piece = (p - last).norm();
      stretch += piece;
      if (!stretch_segments.empty() && stretch_segments.back().first == segment)
        stretch_segments.back().second += piece;
      else
        stretch_segments.emplace_back(segment, piece);
    }
    if (!is_air) {
      stretch = 0;
      stretch_segments.clear();
    }
    in_air = is_air;
    last = p;
    if (stretch > longest.length_m) {
      longest.length_m = stretch;
      std::fill(longest.length_by_segment_m.begin(), longest.length_by_segment_m.end(), 0.0);
      for (const auto& [s, length] : stretch_segments) longest.length_by_segment_m[s] = length;
    }
  };
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const Eigen::Vector3d p = point_of(points, i);
    // The samples of the segment ending at point i belong to segment i - 1.
    const size_t segment = i > 0 ? static_cast<size_t>(i - 1) : 0;
    if (i > 0) {
      const Eigen::Vector3d a = point_of(points, i - 1);
      const int pieces = static_cast<int>(std::ceil((p - a).norm() / step_m));
      for (int k = 1; k < pieces; ++k)
        visit(a + (p - a) * (static_cast<double>(k) / pieces), segment);
    }
    visit(p, segment);
  }
  return longest;
}

KinkMeasures measure_kinks(const StrandSet& grown, const TriangleMeshDistance& hair_distance,
                           const TriangleMeshDistance* body_distance, double head_height_m,
                           const KinkLimits& limits, const std::vector<int8_t>* point_rule) {
  const int64_t n = grown.strand_count();
  if (point_rule != nullptr) {
    if (static_cast<int64_t>(point_rule->size()) != grown.point_count())
      throw Error::bad_input("measure_kinks", std::to_string(point_rule->size()) +
                                                    " point rules for " + std::to_string(grown.point_count()) + " points");
    for (const int8_t rule : *point_rule)
      if (rule < 0 || rule > 3)
        throw Error::bad_input("measure_kinks",
                               "a point rule outside 0-3: " + std::to_string(rule));
  }
  std::vector<uint8_t> hairpin(static_cast<size_t>(n), 0), chord(static_cast<size_t>(n), 0),
      chord_rule(static_cast<size_t>(n), 0);
  const AirAroundHair air(hair_distance, body_distance, limits.air_distance_h * head_height_m,
                          limits.covered_reach_h * head_height_m);
  const double step_m = limits.air_sample_step_h * head_height_m;
#pragma omp parallel for schedule(dynamic, 64)
  for (int64_t s = 0; s < n; ++s) {
    const Points3f points = grown.strand(s);
    hairpin[static_cast<size_t>(s)] = has_hairpin(points, limits.hairpin_turn_deg);
    const AirStretch stretch = longest_air_stretch(points, air, step_m);
    chord[static_cast<size_t>(s)] = stretch.length_m > limits.air_chord_length_m;
    if (chord[static_cast<size_t>(s)] && point_rule != nullptr) {
      // The rule of a segment is its end point's.
      std::array<double, 4> by_rule{};
      const int64_t first = grown.offsets[static_cast<size_t>(s)];
      for (size_t k = 0; k < stretch.length_by_segment_m.size(); ++k)
        by_rule[static_cast<size_t>((*point_rule)[static_cast<size_t>(first) + k + 1])] +=
            stretch.length_by_segment_m[k];
      chord_rule[static_cast<size_t>(s)] = static_cast<uint8_t>(
          std::max_element(by_rule.begin(), by_rule.end()) - by_rule.begin());
    }
  }
  KinkMeasures m;
  m.strands = n;
  for (int64_t s = 0; s < n; ++s) {
    const bool h = hairpin[static_cast<size_t>(s)] != 0, c = chord[static_cast<size_t>(s)] != 0;
    m.hairpin_strands += h;
    m.air_chord_strands += c;
    m.kinked_strands += h || c;
    if (h || c) m.kinked.push_back(s);
    if (c) ++m.air_chord_strands_by_rule[chord_rule[static_cast<size_t>(s)]];
  }
  return m;
}

double mean_curvature_per_m(const StrandSet& strands, double step_m) {
  double turning = 0, length = 0;
  for (int64_t s = 0; s < strands.strand_count(); ++s) {
    const std::vector<Eigen::Vector3d> p = resampled(strands.strand(s), step_m);
    if (p.size() < 4) continue;
    for (size_t i = 1; i + 1 < p.size(); ++i) {
      const Eigen::Vector3d a = (p[i] - p[i - 1]).normalized(), b = (p[i + 1] - p[i]).normalized();
      turning += std::acos(std::clamp(a.dot(b), -1.0, 1.0));
    }
    length += step_m * static_cast<double>(p.size() - 2);
  }
  return length > 0 ? turning / length : 0.0;
}

}  // namespace hair
