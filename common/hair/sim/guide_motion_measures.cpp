#include "hair/sim/guide_motion_measures.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "hair/geom/polyline.h"

namespace hair {

std::vector<GuideDrift> guide_drift(const SimulatedGuides& guides) {
  const StrandSet& rest = guides.rest;
  const int64_t points = rest.point_count();
  std::vector<GuideDrift> drift(static_cast<size_t>(rest.strand_count()));
  auto at = [&](int32_t frame, int64_t row) {
    const size_t base = (static_cast<size_t>(frame) * static_cast<size_t>(points) + static_cast<size_t>(row)) * 3;
    const Eigen::Vector3d world(guides.guide_points_m[base], guides.guide_points_m[base + 1],
                                guides.guide_points_m[base + 2]);
    return guides.head[static_cast<size_t>(frame)].apply_inverse(world);
  };
  for (int64_t g = 0; g < rest.strand_count(); ++g) {
    const int64_t begin = rest.offsets[static_cast<size_t>(g)], end = rest.offsets[static_cast<size_t>(g) + 1];
    GuideDrift& d = drift[static_cast<size_t>(g)];
    if (end - begin < 2) continue;
    for (int64_t row = begin; row + 1 < end; ++row)
      d.length_m += (point_of(rest.points, row + 1) - point_of(rest.points, row)).norm();
    if (!(d.length_m > 0)) continue;
    const Eigen::Vector3d tip_rest = point_of(rest.points, end - 1);
    const Eigen::Vector3d first_rest = point_of(rest.points, begin + 1) - point_of(rest.points, begin);
    for (int32_t frame = 0; frame < guides.frame_count; ++frame) {
      const double share = (at(frame, end - 1) - tip_rest).norm() / d.length_m;
      d.largest_share = std::max(d.largest_share, share);
      if (frame == guides.frame_count - 1) d.final_share = share;
      if ((at(frame, begin + 1) - at(frame, begin)).dot(first_rest) < 0) d.flipped = true;
    }
  }
  return drift;
}

DriftSummary summarise_drift(const std::vector<GuideDrift>& drift) {
  DriftSummary summary;
  std::vector<double> finals;
  for (const GuideDrift& d : drift) {
    if (!(d.length_m > 0)) continue;
    finals.push_back(d.final_share);
    summary.largest_any_frame = std::max(summary.largest_any_frame, d.largest_share);
    summary.flipped += d.flipped ? 1 : 0;
  }
  summary.guides = static_cast<int64_t>(finals.size());
  if (finals.empty()) return summary;
  std::sort(finals.begin(), finals.end());
  double sum = 0;
  for (double f : finals) sum += f;
  summary.mean = sum / static_cast<double>(finals.size());
  summary.p95 = finals[std::min(finals.size() - 1, static_cast<size_t>(0.95 * static_cast<double>(finals.size())))];
  summary.largest = finals.back();
  return summary;
}

BundleSpread bundle_spread(const SimulatedGuides& guides, int32_t cluster, double fraction) {
  BundleSpread spread;
  const StrandSet& rest = guides.rest;
  const auto& clusters = std::get<std::vector<int32_t>>(rest.strand_attributes.at("cluster"));
  if (cluster < 0) {
    std::map<int32_t, int64_t> count;
    for (int32_t c : clusters) ++count[c];
    int64_t most = 0;
    for (const auto& [c, n] : count)
      if (n > most) most = n, cluster = c;
  }
  spread.cluster = cluster;
  const int64_t points = rest.point_count();
  auto at = [&](int32_t frame, int64_t row) {
    const size_t base = (static_cast<size_t>(frame) * static_cast<size_t>(points) + static_cast<size_t>(row)) * 3;
    return guides.head[static_cast<size_t>(frame)].apply_inverse(Eigen::Vector3d(
        guides.guide_points_m[base], guides.guide_points_m[base + 1], guides.guide_points_m[base + 2]));
  };
  std::vector<int64_t> members;
  std::vector<double> length_m;
  for (int64_t g = 0; g < rest.strand_count(); ++g)
    if (clusters[static_cast<size_t>(g)] == cluster &&
        rest.offsets[static_cast<size_t>(g) + 1] - rest.offsets[static_cast<size_t>(g)] >= 2) {
      members.push_back(g);
      double length = 0;
      for (int64_t row = rest.offsets[static_cast<size_t>(g)];
           row + 1 < rest.offsets[static_cast<size_t>(g) + 1]; ++row)
        length += (point_of(rest.points, row + 1) - point_of(rest.points, row)).norm();
      length_m.push_back(length);
    }
  if (!length_m.empty()) {  // the tail's guides: at least half the median length
    std::vector<double> sorted = length_m;
    std::nth_element(sorted.begin(),
                     sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
    const double shortest_m = 0.5 * sorted[sorted.size() / 2];
    std::vector<int64_t> kept;
    for (size_t m = 0; m < members.size(); ++m)
      if (length_m[m] >= shortest_m) kept.push_back(members[m]);
    members = std::move(kept);
  }
  spread.guides = static_cast<int64_t>(members.size());
  if (members.size() < 2) return spread;
  std::vector<Eigen::Vector3d> line;
  auto spread_at = [&](int32_t frame) {
    std::vector<Eigen::Vector3d> sample;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (int64_t g : members) {
      line.clear();
      for (int64_t row = rest.offsets[static_cast<size_t>(g)];
           row < rest.offsets[static_cast<size_t>(g) + 1]; ++row)
        line.push_back(at(frame, row));
      sample.push_back(point_at_arc_fraction(line, fraction));
      mean += sample.back();
    }
    mean /= static_cast<double>(sample.size());
    double sum = 0;
    for (const Eigen::Vector3d& p : sample) sum += (p - mean).squaredNorm();
    return std::sqrt(sum / static_cast<double>(sample.size()));
  };
  spread.rest_spread_m = spread_at(0);
  for (int32_t frame = 0; frame < guides.frame_count; ++frame)
    spread.ratio.push_back(spread_at(frame) / spread.rest_spread_m);
  std::vector<double> sorted = spread.ratio;
  std::sort(sorted.begin(), sorted.end());
  spread.median = sorted[sorted.size() / 2];
  spread.largest = sorted.back();
  return spread;
}

}  // namespace hair
