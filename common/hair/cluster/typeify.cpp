#include "hair/cluster/typeify.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <utility>

#include "hair/cluster/typeify_params.h"
#include "hair/core/error.h"
#include "hair/geom/point_index.h"
#include "hair/geom/strand_geometry.h"

namespace hair {
namespace {

/// Unit direction from point `from` to point `to` of a centre strand.
Eigen::Vector3f direction(const StrandSet& centres, int64_t group, int64_t from, int64_t to) {
  auto strand = centres.strand(group);
  Eigen::Vector3f d = (strand.row(to) - strand.row(from)).transpose();
  float norm = d.norm();
  return norm > 0 ? Eigen::Vector3f(d / norm) : Eigen::Vector3f::Zero();
}

}  // namespace

StrandSet centre_strands(const StrandSet& strands, const std::vector<int32_t>& first_strand,
                         int points) {
  StrandSet resampled = resample_by_count(strands, points);
  std::vector<Points3f> centres;
  for (size_t g = 0; g + 1 < first_strand.size(); ++g) {
    Points3f centre = Points3f::Zero(points, 3);
    int32_t count = first_strand[g + 1] - first_strand[g];
    for (int32_t s = first_strand[g]; s < first_strand[g + 1]; ++s) centre += resampled.strand(s);
    if (count > 0) centre /= static_cast<float>(count);
    centres.push_back(centre);
  }
  return strand_set_from_polylines(centres);
}

std::optional<double> connection_angle_threshold(const std::vector<double>& angles_rad,
                                                 double min_rad, double max_rad) {
  constexpr int bins = 90;
  if (angles_rad.size() < 4) return std::nullopt;
  std::vector<double> histogram(bins, 0);
  for (double angle : angles_rad) {
    int bin = std::clamp(static_cast<int>(angle / std::numbers::pi * bins), 0, bins - 1);
    histogram[bin] += 1;
  }
  double total = static_cast<double>(angles_rad.size()), sum_all = 0;
  for (int b = 0; b < bins; ++b) sum_all += b * histogram[b];
  // Otsu: the split maximising the between-class variance. Splits inside an empty gap
  // between the classes tie; the middle of the tied ones is taken.
  std::vector<double> variance(bins - 1, -1);
  double weight_low = 0, sum_low = 0, best_variance = -1;
  for (int b = 0; b < bins - 1; ++b) {
    weight_low += histogram[b];
    sum_low += b * histogram[b];
    double weight_high = total - weight_low;
    if (weight_low == 0 || weight_high == 0) continue;
    double mean_low = sum_low / weight_low, mean_high = (sum_all - sum_low) / weight_high;
    variance[b] = weight_low * weight_high * (mean_low - mean_high) * (mean_low - mean_high);
    best_variance = std::max(best_variance, variance[b]);
  }
  if (best_variance <= 0) return std::nullopt;
  int first = -1, last = -1;
  for (int b = 0; b < bins - 1; ++b)
    if (variance[b] >= best_variance * (1 - 1e-12)) {
      if (first < 0) first = b;
      last = b;
    }
  double threshold = ((first + last) / 2.0 + 1.0) / bins * std::numbers::pi;
  return std::clamp(threshold, min_rad, max_rad);
}

GroupTypes group_types(const StrandSet& strands, const std::vector<int32_t>& first_strand,
                       double head_height_m, const TypeifyParams& params) {
  return group_types_from_centres(centre_strands(strands, first_strand, params.centre_points), {},
                                  head_height_m, params);
}

GroupTypes group_types_from_centres(StrandSet centres_in,
                                    std::vector<double> start_scalp_distance_m,
                                    double head_height_m, const TypeifyParams& params) {
  check_typeify_params(params);
  auto group_count = static_cast<int64_t>(centres_in.strand_count());
  if (!start_scalp_distance_m.empty() &&
      start_scalp_distance_m.size() != static_cast<size_t>(group_count))
    throw Error::bad_input("", "scalp distances (" + std::to_string(start_scalp_distance_m.size()) +
                                   ") do not match the groups (" + std::to_string(group_count) +
                                   ")");
  if (centres_in.point_count() != group_count * params.centre_points)
    throw Error::bad_input("", "centre strands of " + std::to_string(params.centre_points) +
                                   " points expected (" + std::to_string(centres_in.point_count()) +
                                   " points for " + std::to_string(group_count) + " groups)");
  GroupTypes result;
  result.centre_strands = std::move(centres_in);
  result.start_scalp_distance_m = std::move(start_scalp_distance_m);
  const StrandSet& centres = result.centre_strands;
  int points = params.centre_points;
  int half = points / 2;
  float radius = static_cast<float>(params.neighbour_distance_h * head_height_m);

  // Halves of every centre strand in k-d trees: proximal points [0, half), distal
  // points [half, points), each labelled with its group.
  Points3f proximal(group_count * half, 3), distal(group_count * (points - half), 3);
  for (int64_t g = 0; g < group_count; ++g) {
    auto centre = centres.strand(g);
    proximal.middleRows(g * half, half) = centre.topRows(half);
    distal.middleRows(g * (points - half), points - half) = centre.bottomRows(points - half);
  }
  PointIndex proximal_index(proximal), distal_index(distal);
  auto groups_near = [&](const PointIndex& index, int per_group, const Eigen::Vector3f& point,
                         int64_t self) {
    std::vector<int32_t> groups;
    for (int32_t id : index.within(point, radius)) {
      int32_t group = id / per_group;
      if (group != self && std::find(groups.begin(), groups.end(), group) == groups.end())
        groups.push_back(group);
    }
    std::sort(groups.begin(), groups.end());
    return groups;
  };
  result.before.resize(static_cast<size_t>(group_count));
  result.after.resize(static_cast<size_t>(group_count));
  result.after_angle_rad.resize(static_cast<size_t>(group_count));
  double root_scalp_distance_m = params.root_scalp_distance_h * head_height_m;
  for (int64_t g = 0; g < group_count; ++g) {
    auto centre = centres.strand(g);
    Eigen::Vector3f start = centre.row(0).transpose();
    result.before[g] = groups_near(distal_index, points - half, start, g);
    // Rooted on the scalp: only a group ending at g's start leads into it; one that
    // merely passes over it (g lies under its lower half) does not.
    if (!result.start_scalp_distance_m.empty() &&
        result.start_scalp_distance_m[static_cast<size_t>(g)] < root_scalp_distance_m)
      std::erase_if(result.before[g], [&](int32_t other) {
        Eigen::Vector3f end = centres.strand(other).row(points - 1).transpose();
        return (end - start).norm() > radius;
      });
    result.after[g] = groups_near(proximal_index, half, centre.row(points - 1).transpose(), g);
    // Angle between g's distal direction (its last segment pointing on) and each
    // nearby group's proximal direction.
    Eigen::Vector3f leaving = direction(centres, g, points - 2, points - 1);
    for (int32_t other : result.after[g]) {
      Eigen::Vector3f entering = direction(centres, other, 0, 1);
      result.after_angle_rad[g].push_back(
          static_cast<float>(std::acos(std::clamp(leaving.dot(entering), -1.0f, 1.0f))));
    }
  }

  // The angle threshold: given, or from the distribution over root groups (section 4.1).
  std::vector<double> root_angles;
  for (int64_t g = 0; g < group_count; ++g)
    if (result.before[g].empty())
      for (float angle : result.after_angle_rad[g]) root_angles.push_back(angle);
  double degrees = std::numbers::pi / 180.0;
  std::optional<double> from_distribution;
  if (params.connect_angle_deg <= 0)
    from_distribution =
        connection_angle_threshold(root_angles, params.min_connect_angle_deg * degrees,
                                   params.max_connect_angle_deg * degrees);
  result.threshold_from_distribution = from_distribution.has_value();
  result.connect_angle_threshold_rad =
      from_distribution ? *from_distribution
                        : (params.connect_angle_deg > 0 ? params.connect_angle_deg
                                                        : params.max_connect_angle_deg) *
                              degrees;

  // Algorithm 1.
  result.type.resize(static_cast<size_t>(group_count));
  for (int64_t g = 0; g < group_count; ++g) {
    if (result.before[g].empty()) {
      bool connectable =
          std::any_of(result.after_angle_rad[g].begin(), result.after_angle_rad[g].end(),
                      [&](float angle) { return angle <= result.connect_angle_threshold_rad; });
      result.type[g] = connectable ? GroupType::root_connected : GroupType::root_free;
    } else if (result.after[g].empty()) {
      result.type[g] = GroupType::tip;
    } else {
      result.type[g] = GroupType::middle;
    }
  }
  return result;
}

}  // namespace hair
