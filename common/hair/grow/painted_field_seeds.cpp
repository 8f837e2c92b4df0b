#include "hair/grow/painted_field_seeds.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "hair/geom/point_index.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;

/// The input strands' segments: midpoints in an index, directions and groups.
struct GroupSegments {
  std::vector<Vec3> direction;
  std::vector<int32_t> group;
  std::vector<int64_t> strand;
  std::optional<PointIndex> index;

  explicit GroupSegments(const StrandSet& strands) {
    const auto& strand_group =
        std::get<std::vector<int32_t>>(strands.strand_attributes.at("group"));
    Points3f midpoints(strands.point_count(), 3);
    Eigen::Index count = 0;
    for (int64_t s = 0; s < strands.strand_count(); ++s)
      for (int64_t row = strands.offsets[s]; row + 1 < strands.offsets[s + 1]; ++row) {
        const Vec3 d = point_of(strands.points, row + 1) - point_of(strands.points, row);
        if (!(d.norm() > 0)) continue;
        midpoints.row(count++) = (0.5 * (strands.points.row(row) + strands.points.row(row + 1)));
        direction.push_back(d.normalized());
        group.push_back(strand_group[static_cast<size_t>(s)]);
        strand.push_back(s);
      }
    midpoints.conservativeResize(count, 3);
    if (count > 0) index.emplace(midpoints);
  }

  /// The sign `axis` takes from the nearest segment of each of the `count` strands of
  /// `wanted` nearest `point` (within `radius_m`): +1 or -1 where each runs along it
  /// (|cosine| at least `min_cosine`) the same way, 0 where there are none or they
  /// disagree (a parting, where a card's halves run apart; a whorl).
  int sign_of_axis(const Vec3& point, const Vec3& axis, int32_t wanted, double radius_m, int count,
                   double min_cosine) const {
    if (!index) return 0;
    int sign = 0;
    bool disagree = false;
    std::vector<int64_t> seen;
    index->visit_within(point.cast<float>(), static_cast<float>(radius_m), [&](int32_t id) {
      const auto i = static_cast<size_t>(id);
      if (group[i] != wanted || std::find(seen.begin(), seen.end(), strand[i]) != seen.end())
        return true;
      const double cosine = axis.dot(direction[i]);
      const int this_sign = cosine > 0 ? 1 : -1;
      if (std::abs(cosine) < min_cosine || (sign != 0 && this_sign != sign)) {
        disagree = true;
        return false;
      }
      sign = this_sign;
      seen.push_back(strand[i]);
      return static_cast<int>(seen.size()) < count;
    });
    return disagree ? 0 : sign;
  }
};

}  // namespace

StrandSet painted_field_seeds(const Points3f& vertices, const Triangles3i& triangles,
                              const std::vector<int32_t>& triangle_group,
                              const Points3f& triangle_flow,
                              const std::vector<uint8_t>& seeding_group,
                              const StrandSet& input_strands,
                              const PaintedFieldSeedParams& params) {
  std::vector<Points3f> segments;
  std::vector<int32_t> segment_group;
  const GroupSegments group_segments(input_strands);
  const double half_m = 0.25 * params.spacing_m;
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    const int32_t g = triangle_group[static_cast<size_t>(t)];
    if (g < 0 || static_cast<size_t>(g) >= seeding_group.size() || !seeding_group[g]) continue;
    const Vec3 axis = triangle_flow.row(t).cast<double>().transpose();
    if (!(axis.norm() > 0.5)) continue;
    const Vec3 a = point_of(vertices, triangles(t, 0)), b = point_of(vertices, triangles(t, 1)),
               c = point_of(vertices, triangles(t, 2));
    const Vec3 centroid = (a + b + c) / 3;
    const int sign = group_segments.sign_of_axis(centroid, axis, g, params.sign_radius_m,
                                                 params.sign_strands, params.min_axis_cosine);
    if (sign == 0) continue;
    const Vec3 signed_axis = sign * axis;
    // The centroids of the k x k triangles of the face's regular subdivision, k so that
    // they lie about `spacing_m` apart.
    const double longest_m = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    const int k = std::clamp(static_cast<int>(std::ceil(longest_m / params.spacing_m)), 1, 64);
    auto add = [&](const Vec3& centre) {
      Points3f segment(2, 3);
      segment.row(0) = (centre - half_m * signed_axis).cast<float>().transpose();
      segment.row(1) = (centre + half_m * signed_axis).cast<float>().transpose();
      segments.push_back(std::move(segment));
      segment_group.push_back(g);
    };
    for (int i = 0; i < k; ++i)
      for (int j = 0; i + j < k; ++j) {
        // Upward sub-triangle (i, j), (i + 1, j), (i, j + 1), and the downward one beside it.
        auto corner = [&](double u, double v) { return a + (u / k) * (b - a) + (v / k) * (c - a); };
        add(corner(i + 1.0 / 3, j + 1.0 / 3));
        if (i + j + 1 < k) add(corner(i + 2.0 / 3, j + 2.0 / 3));
      }
  }
  StrandSet seeds = strand_set_from_polylines(segments);
  seeds.strand_attributes["group"] = std::move(segment_group);
  return seeds;
}

}  // namespace hair
