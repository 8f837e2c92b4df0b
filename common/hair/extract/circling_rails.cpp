#include "hair/extract/circling_rails.h"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

namespace hair {

FamilyCircling family_circling(const Points3f& vertices, const EdgeFamily& family,
                               const Eigen::Vector3d& axis_point,
                               const Eigen::Vector3d& axis_direction) {
  const Eigen::Vector3d& a = axis_direction;
  // Two unit vectors across the axis, for the azimuth round it.
  const Eigen::Vector3d e1 =
      (std::abs(a.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY())
          .cross(a)
          .normalized();
  const Eigen::Vector3d e2 = a.cross(e1);
  const auto across = [&](const Eigen::Vector3d& p) {
    const Eigen::Vector3d q = p - axis_point;
    return Eigen::Vector3d(q - q.dot(a) * a);
  };
  FamilyCircling c;
  double length = 0, round = 0, sweep_sum = 0;
  int chains = 0;
  for (const std::vector<int32_t>& chain : family.chains) {
    if (chain.size() < 2) continue;
    double sweep = 0;  // signed winding of this chain, radians
    for (size_t i = 1; i < chain.size(); ++i) {
      const Eigen::Vector3d p0 = vertices.row(chain[i - 1]).cast<double>().transpose();
      const Eigen::Vector3d p1 = vertices.row(chain[i]).cast<double>().transpose();
      const Eigen::Vector3d d = p1 - p0;
      length += d.norm();
      // The tangent of the circle about the axis through the edge's middle.
      const Eigen::Vector3d radial = across(0.5 * (p0 + p1));
      const double r = radial.norm();
      if (r > 0) round += std::abs(a.cross(radial).dot(d)) / r;
      // Winding: the change of azimuth from p0 to p1, taken the short way.
      const Eigen::Vector3d q0 = across(p0), q1 = across(p1);
      double turn = std::atan2(q1.dot(e2), q1.dot(e1)) - std::atan2(q0.dot(e2), q0.dot(e1));
      if (turn > std::numbers::pi) turn -= 2 * std::numbers::pi;
      if (turn < -std::numbers::pi) turn += 2 * std::numbers::pi;
      sweep += turn;
    }
    sweep_sum += std::abs(sweep) * 180 / std::numbers::pi;
    ++chains;
  }
  if (length > 0) c.circling_share = round / length;
  if (chains > 0) {
    c.mean_sweep_deg = sweep_sum / chains;
    c.mean_chain_length = length / chains;
  }
  return c;
}

Eigen::Vector3d region_axis_direction(const Points3f& vertices, const EdgeFamily& family,
                                      const Eigen::Vector3d& head_centre) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int64_t count = 0;
  for (const std::vector<int32_t>& chain : family.chains)
    for (const int32_t v : chain) {
      sum += vertices.row(v).cast<double>().transpose();
      ++count;
    }
  if (count == 0) return Eigen::Vector3d::UnitY();
  const Eigen::Vector3d out = sum / static_cast<double>(count) - head_centre;
  return out.norm() > 1e-9 ? Eigen::Vector3d(out.normalized()) : Eigen::Vector3d::UnitY();
}

int family_across_rings(const std::array<FamilyCircling, 2>& families,
                        const CirclingLimits& limits) {
  const auto circles = [&](const FamilyCircling& f) {
    return f.circling_share >= limits.min_circling_share &&
           f.mean_sweep_deg >= limits.min_sweep_deg;
  };
  for (int rings = 0; rings < 2; ++rings) {
    const FamilyCircling& other = families[static_cast<size_t>(1 - rings)];
    if (circles(families[static_cast<size_t>(rings)]) && !circles(other) &&
        other.circling_share <= limits.max_other_circling_share &&
        other.mean_chain_length >= limits.other_min_length_m)
      return 1 - rings;
  }
  return -1;
}

}  // namespace hair
