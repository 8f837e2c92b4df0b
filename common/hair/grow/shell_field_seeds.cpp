#include "hair/grow/shell_field_seeds.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace hair {

namespace {

using Vec3 = Eigen::Vector3d;

Vec3 point_of(const Points3f& points, Eigen::Index row) {
  return points.row(row).cast<double>().transpose();
}

/// One strand's points over the body: where each lies above it, and how many levels fit
/// under it.
struct PointOverBody {
  Vec3 foot = Vec3::Zero();    ///< nearest body point
  Vec3 normal = Vec3::Zero();  ///< from the foot to the point, unit
  int levels = 0;
};

std::vector<PointOverBody> points_over_body(const Points3f& strand,
                                            const TriangleMeshDistance& body,
                                            const ShellSeedParams& params) {
  const Eigen::Index count = strand.rows();
  std::vector<PointOverBody> over(static_cast<size_t>(count));
  for (Eigen::Index i = 0; i < count; ++i) {
    const Vec3 p = point_of(strand, i);
    const TriangleMeshDistance::Nearest nearest = body.nearest(p);
    PointOverBody& o = over[static_cast<size_t>(i)];
    if (!(nearest.distance > 0) || nearest.distance > params.max_height_m ||
        nearest.closest_point.y() < params.min_foot_y_m)
      continue;
    o.foot = nearest.closest_point;
    o.normal = (p - nearest.closest_point) / nearest.distance;
    // The strand's direction here (central difference; one-sided at its ends).
    const Vec3 along = point_of(strand, std::min(i + 1, count - 1)) -
                       point_of(strand, std::max<Eigen::Index>(i - 1, 0));
    if (!(along.norm() > 0) || std::abs(along.normalized().dot(o.normal)) > params.max_rise_cosine)
      continue;
    // Levels at spacing/2 + j spacing, up to half a spacing under the point.
    o.levels = static_cast<int>(std::floor(nearest.distance / params.spacing_m));
  }
  return over;
}

}  // namespace

StrandSet seeds_under_strands(const std::vector<Points3f>& strands,
                              const TriangleMeshDistance& body, const PointIndex& hair,
                              const ShellSeedParams& params) {
  const auto inner_m = static_cast<float>(0.5 * params.spacing_m);
  std::vector<Points3f> polylines;
  std::vector<int32_t> level_of, strand_of;
  std::vector<Eigen::RowVector3f> run;
  for (size_t index = 0; index < strands.size(); ++index) {
    const std::vector<PointOverBody> over = points_over_body(strands[index], body, params);
    int top = 0;
    for (const PointOverBody& o : over) top = std::max(top, o.levels);
    for (int level = 0; level < top; ++level) {
      const double height_m = params.spacing_m * (0.5 + level);
      run.clear();
      const auto flush = [&] {
        if (run.size() >= 2) {
          Points3f points(static_cast<Eigen::Index>(run.size()), 3);
          for (size_t k = 0; k < run.size(); ++k) points.row(static_cast<Eigen::Index>(k)) = run[k];
          polylines.push_back(std::move(points));
          level_of.push_back(level);
          strand_of.push_back(static_cast<int32_t>(index));
        }
        run.clear();
      };
      for (const PointOverBody& o : over) {
        if (o.levels <= level) {
          flush();
          continue;
        }
        const Eigen::Vector3f seed = (o.foot + height_m * o.normal).cast<float>();
        if (hair.any_within(seed, inner_m)) {
          flush();
          continue;
        }
        run.push_back(seed.transpose());
      }
      flush();
    }
  }
  StrandSet seeds = strand_set_from_polylines(polylines);
  seeds.strand_attributes["level"] = level_of;
  seeds.strand_attributes["strand"] = strand_of;
  return seeds;
}

}  // namespace hair
