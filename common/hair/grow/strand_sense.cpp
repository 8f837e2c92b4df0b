#include "hair/grow/strand_sense.h"

#include <algorithm>
#include <cmath>
#include <numbers>
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

double longest_air_stretch_m(const Points3f& points, const AirAroundHair& air, double step_m) {
  double longest = 0, stretch = 0;
  bool in_air = false;
  Eigen::Vector3d last = Eigen::Vector3d::Zero();
  const auto visit = [&](const Eigen::Vector3d& p) {
    const bool is_air = air.is_air(p);
    if (is_air && in_air) stretch += (p - last).norm();
    if (!is_air) stretch = 0;
    in_air = is_air;
    last = p;
    longest = std::max(longest, stretch);
  };
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const Eigen::Vector3d p = point_of(points, i);
    if (i > 0) {
      const Eigen::Vector3d a = point_of(points, i - 1);
      const int pieces = static_cast<int>(std::ceil((p - a).norm() / step_m));
      for (int k = 1; k < pieces; ++k) visit(a + (p - a) * (static_cast<double>(k) / pieces));
    }
    visit(p);
  }
  return longest;
}

KinkMeasures measure_kinks(const StrandSet& grown, const TriangleMeshDistance& hair_distance,
                           const TriangleMeshDistance* body_distance, double head_height_m,
                           const KinkLimits& limits) {
  const int64_t n = grown.strand_count();
  std::vector<uint8_t> hairpin(static_cast<size_t>(n), 0), chord(static_cast<size_t>(n), 0);
  const AirAroundHair air(hair_distance, body_distance, limits.air_distance_h * head_height_m,
                          limits.covered_reach_h * head_height_m);
  const double step_m = limits.air_sample_step_h * head_height_m;
#pragma omp parallel for schedule(dynamic, 64)
  for (int64_t s = 0; s < n; ++s) {
    const Points3f points = grown.strand(s);
    hairpin[static_cast<size_t>(s)] = has_hairpin(points, limits.hairpin_turn_deg);
    chord[static_cast<size_t>(s)] =
        longest_air_stretch_m(points, air, step_m) > limits.air_chord_length_m;
  }
  KinkMeasures m;
  m.strands = n;
  for (int64_t s = 0; s < n; ++s) {
    const bool h = hairpin[static_cast<size_t>(s)] != 0, c = chord[static_cast<size_t>(s)] != 0;
    m.hairpin_strands += h;
    m.air_chord_strands += c;
    m.kinked_strands += h || c;
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
