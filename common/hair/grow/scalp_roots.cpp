// Where grown strands start: the scalp that carries their roots, the roots sampled on it
// with their reference strands, the seeds of their clusters' fields besides the input
// strands, and the way a strand that cannot leave its root lies.
#include "hair/grow/scalp_roots.h"

#include <spdlog/spdlog.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>

#include "hair/core/error.h"
#include "hair/geom/point_index.h"
#include "hair/geom/triangle_mesh_distance.h"
#include "hair/grow/painted_field_seeds.h"
#include "hair/grow/shell_field_seeds.h"
#include "hair/grow/triangle_centre.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;

/// Unit normal of body triangle `t` (right-hand rule of its vertex order).
Vec3 triangle_normal(const GrowInput& input, Eigen::Index t) {
  const Vec3 a = point_of(input.body_vertices, input.body_triangles(t, 0));
  return (point_of(input.body_vertices, input.body_triangles(t, 1)) - a)
      .cross(point_of(input.body_vertices, input.body_triangles(t, 2)) - a)
      .normalized();
}

/// The length of `offset` along the scalp: its part across the unit `normal`.
double along_the_scalp_m(const Vec3& offset, const Vec3& normal) {
  return (offset - offset.dot(normal) * normal).norm();
}

/// Whether the input strand through `row` rises off a scalp triangle of unit normal
/// `normal` at more than 45 degrees there (its segment from `row`, or into `row` at its
/// tip): hair standing on the head, like a spike card, rather than lying on it.
bool stands_off_the_scalp(const StrandSet& strands, int64_t row, const Vec3& normal) {
  const auto next = std::upper_bound(strands.offsets.begin(), strands.offsets.end(), row);
  const int64_t first = *(next - 1), last = *next - 1;
  if (last <= first) return false;
  const int64_t from = row < last ? row : row - 1;
  const Vec3 segment = point_of(strands.points, from + 1) - point_of(strands.points, from);
  if (!(segment.squaredNorm() > 0) || !(normal.squaredNorm() > 0)) return false;
  return std::abs(segment.normalized().dot(normal)) > std::sqrt(0.5);
}

/// Scalp triangles (input.scalp_triangle) whose centre lies within scalp_cover_h of the
/// input-strand point `nearest_row` gives for it (a row of input_strands.points); where
/// that point's strand stands off the scalp, only within standing_cover_h of it along
/// the scalp.
std::vector<uint8_t> scalp_under_strands(const GrowInput& input, const GrowParams& params,
                                         const std::function<int64_t(const Vec3&)>& nearest_row) {
  const StrandSet& strands = input.input_strands;
  const double h = input.head_height_m;
  std::vector<uint8_t> covered(input.scalp_triangle.size(), 0);
  const double cover_m = params.scalp_cover_h * h;
  const double standing_cover_m = std::min(params.standing_cover_h, params.scalp_cover_h) * h;
  for (Eigen::Index t = 0; t < input.body_triangles.rows(); ++t) {
    if (!input.scalp_triangle[static_cast<size_t>(t)]) continue;
    const Vec3 centre = triangle_centre<double>(input.body_vertices, input.body_triangles, t);
    const int64_t row = nearest_row(centre);
    const Vec3 offset = point_of(strands.points, row) - centre;
    if (offset.norm() > cover_m) continue;
    const Vec3 normal = triangle_normal(input, t);
    if (stands_off_the_scalp(strands, row, normal)) {
      // Along the scalp from the triangle (0 where the point lies over it), so that the
      // triangle under a spike's base carries roots however coarse the scalp.
      const Vec3 point = point_of(strands.points, row);
      std::array<Vec3, 3> corner;
      for (int k = 0; k < 3; ++k)
        corner[static_cast<size_t>(k)] = point_of(input.body_vertices, input.body_triangles(t, k));
      const Vec3 from_triangle =
          point - closest_point_on_triangle(point, corner[0], corner[1], corner[2]);
      if (along_the_scalp_m(from_triangle, normal) > standing_cover_m) continue;
    }
    covered[static_cast<size_t>(t)] = 1;
  }
  return covered;
}

/// Area in m^2 of the body triangles flagged in `flags`.
double flagged_area_m2(const GrowInput& input, const std::vector<uint8_t>& flags) {
  double area_m2 = 0;
  for (Eigen::Index t = 0; t < input.body_triangles.rows(); ++t) {
    if (!flags[static_cast<size_t>(t)]) continue;
    const Vec3 a = point_of(input.body_vertices, input.body_triangles(t, 0));
    const Vec3 b = point_of(input.body_vertices, input.body_triangles(t, 1));
    const Vec3 c = point_of(input.body_vertices, input.body_triangles(t, 2));
    area_m2 += 0.5 * (b - a).cross(c - a).norm();
  }
  return area_m2;
}

/// The seeds under the root-carrying strands where they lie off the head
/// (GrowParams::field_shell_seeds, shell_field_seeds.h), with strand attribute "cluster"
/// (int32), that of the strand each lies under.
StrandSet shell_seeds(const GrowInput& input, const GrowingContext& context,
                      const GrowParams& params, const TriangleMeshDistance& body,
                      const PointIndex& hair) {
  const StrandSet& strands = input.input_strands;
  std::vector<Points3f> over;
  std::vector<int32_t> over_cluster;
  for (int64_t s = 0; s < strands.strand_count(); ++s)
    if (context.carries_roots(s)) {
      over.emplace_back(strands.strand(s));
      over_cluster.push_back(context.cluster_of_strand(s));
    }
  ShellSeedParams shell_params;
  shell_params.spacing_m = params.field_band_h * input.head_height_m;
  shell_params.max_height_m = params.shell_max_height_h * input.head_height_m;
  // Over the scalp and the neck under it: no lower than the scalp's lowest triangle
  // centre by more than max_height_m.
  double lowest_scalp_y = std::numeric_limits<double>::infinity();
  for (Eigen::Index t = 0; t < input.body_triangles.rows(); ++t) {
    if (!input.scalp_triangle[static_cast<size_t>(t)]) continue;
    lowest_scalp_y = std::min(
        lowest_scalp_y, triangle_centre<double>(input.body_vertices, input.body_triangles, t).y());
  }
  shell_params.min_foot_y_m = lowest_scalp_y - shell_params.max_height_m;
  StrandSet seeds = seeds_under_strands(over, body, hair, shell_params);
  const auto& under = std::get<std::vector<int32_t>>(seeds.strand_attributes.at("strand"));
  std::vector<int32_t> cluster(under.size());
  for (size_t k = 0; k < under.size(); ++k)
    cluster[k] = over_cluster[static_cast<size_t>(under[k])];
  seeds.strand_attributes["cluster"] = std::move(cluster);
  return seeds;
}

/// Flags in `covered` the scalp triangles whose centre lies within scalp_cover_h of a seed
/// of the lowest level under the hair (shell_seeds()): the scalp under a shell of hair.
void cover_scalp_under_shells(const GrowInput& input, const GrowParams& params,
                              const StrandSet& seeds, std::vector<uint8_t>& covered) {
  const auto& level = std::get<std::vector<int32_t>>(seeds.strand_attributes.at("level"));
  std::vector<Eigen::RowVector3f> lowest;
  for (int64_t s = 0; s < seeds.strand_count(); ++s)
    if (level[static_cast<size_t>(s)] == 0)
      for (int64_t row = seeds.offsets[s]; row < seeds.offsets[s + 1]; ++row)
        lowest.push_back(seeds.points.row(row));
  if (lowest.empty()) return;
  Points3f points(static_cast<Eigen::Index>(lowest.size()), 3);
  for (size_t k = 0; k < lowest.size(); ++k) points.row(static_cast<Eigen::Index>(k)) = lowest[k];
  const PointIndex index(points);
  const auto cover_m = static_cast<float>(params.scalp_cover_h * input.head_height_m);
  for (Eigen::Index t = 0; t < input.body_triangles.rows(); ++t) {
    if (!input.scalp_triangle[static_cast<size_t>(t)] || covered[static_cast<size_t>(t)]) continue;
    const Eigen::Vector3f centre =
        triangle_centre<float>(input.body_vertices, input.body_triangles, t);
    if (index.any_within(centre, cover_m)) covered[static_cast<size_t>(t)] = 1;
  }
}

/// The way a strand that cannot leave its root takes its one step: along the input strand
/// `strand` at its point `row` (the root's reference; nearly always its tip, where the
/// hair the mesh shows ends on the scalp: a cap's streamlines at the hairline, 93-100% of
/// such roots on short01, short02, bob01, afro01), less any part into the scalp (`normal`,
/// unit, outward), so it lies along the hair as the hair's ends there do; along the normal
/// where the strand runs straight into the scalp.
Vec3 stub_direction(const StrandSet& strands, int32_t strand, int64_t row, const Vec3& normal) {
  const int64_t first = strands.offsets[static_cast<size_t>(strand)];
  const int64_t last = strands.offsets[static_cast<size_t>(strand) + 1] - 1;
  if (last <= first) return normal;
  const int64_t from = std::min(row, last - 1);
  Vec3 along = point_of(strands.points, from + 1) - point_of(strands.points, from);
  if (!(along.norm() > 0)) return normal;
  along.normalize();
  if (along.dot(normal) < 0) along -= along.dot(normal) * normal;
  // Within about 25 degrees of straight into the scalp, what is left says little.
  if (!(along.norm() > 0.4)) return normal;
  return along.normalized();
}

/// A stub's `direction` (stub_direction()) turned onto the painted flow there: `flow`
/// (unit axis, either sense) less its part along the scalp's `normal`, in the sense of
/// `direction`, where `direction` is not the normal itself (it then says nothing of the
/// sense) and the paint does not run within about 65 degrees of straight into the scalp;
/// else `direction` as it was.
Vec3 along_paint(const Vec3& direction, const Vec3& normal, const std::optional<Vec3>& flow) {
  if (!flow) return direction;
  Vec3 tangent = *flow - flow->dot(normal) * normal;
  const double tangent_norm = tangent.norm();
  const double sense = tangent.dot(direction);
  if (!(tangent_norm > 0.4) || direction.dot(normal) > 0.999 || sense == 0) return direction;
  return (sense > 0 ? tangent : -tangent) / tangent_norm;
}

}  // namespace

RootingScalp rooting_scalp(const GrowInput& input, const GrowParams& params) {
  RootingScalp rooting;
  rooting.context = std::make_unique<GrowingContext>(input, params, false);
  rooting.covered = scalp_under_strands(input, params, [&](const Vec3& point) {
    return rooting.context->nearest_root_point(point);
  });
  rooting.typed_root_scalp_share = 1.0;
  if (!rooting.context->any_type_roots() && params.min_typed_root_scalp_share > 0) {
    // The scalp under the hair whatever its types: where root-type strands cover too
    // little of it, the types do not say where the roots are.
    PointIndex all_points(input.input_strands.points);
    std::vector<uint8_t> covered_by_any =
        scalp_under_strands(input, params, [&](const Vec3& point) {
          return static_cast<int64_t>(all_points.nearest(point.cast<float>(), 1).front());
        });
    const double any_area_m2 = flagged_area_m2(input, covered_by_any);
    if (any_area_m2 > 0)
      rooting.typed_root_scalp_share = flagged_area_m2(input, rooting.covered) / any_area_m2;
    if (rooting.typed_root_scalp_share < params.min_typed_root_scalp_share) {
      spdlog::warn(
          "{}: root-type strands cover {:.0f}% of the scalp under the hair (under {:.0f}%); "
          "roots take the cluster of the nearest strand of any type",
          input.source, 100 * rooting.typed_root_scalp_share,
          100 * params.min_typed_root_scalp_share);
      rooting.context = std::make_unique<GrowingContext>(input, params, true);
      rooting.covered = std::move(covered_by_any);
    }
  } else if (rooting.context->any_type_roots()) {
    rooting.typed_root_scalp_share = 0.0;
    spdlog::warn("{}: no root-type strand group; roots take the cluster of the nearest strand",
                 input.source);
  }
  return rooting;
}

StrandSet seeds_under_shells(const GrowInput& input, const GrowingContext& context,
                             const GrowParams& params, std::vector<uint8_t>& covered) {
  if (!params.field_shell_seeds) return StrandSet();
  std::vector<Eigen::RowVector3f> rows;
  for (int64_t s = 0; s < input.input_strands.strand_count(); ++s)
    if (context.carries_roots(s))
      for (int64_t row = input.input_strands.offsets[s]; row < input.input_strands.offsets[s + 1];
           ++row)
        rows.push_back(input.input_strands.points.row(row));
  Points3f points(static_cast<Eigen::Index>(rows.size()), 3);
  for (size_t k = 0; k < rows.size(); ++k) points.row(static_cast<Eigen::Index>(k)) = rows[k];
  const PointIndex seeding_hair(points);  // the points of the root-carrying strands
  // The body's distance, for the seeds under hair that lies off the head.
  std::unique_ptr<TriangleMeshDistance> own_body;
  if (!context.layered())
    own_body = std::make_unique<TriangleMeshDistance>(input.body_vertices, input.body_triangles);
  StrandSet under_shells =
      shell_seeds(input, context, params, context.layered() ? context.body_distance() : *own_body,
                  seeding_hair);
  cover_scalp_under_shells(input, params, under_shells, covered);
  return under_shells;
}

SurfaceSamples sample_roots(const GrowInput& input, const GrowingContext& context,
                            const GrowParams& params, const std::vector<uint8_t>& covered,
                            int64_t covered_count) {
  const StrandSet& strands = input.input_strands;
  const double standing_cover_m =
      std::min(params.standing_cover_h, params.scalp_cover_h) * input.head_height_m;
  // Within a covered triangle, a root beside a standing strand lies within
  // standing_cover_h of it along the scalp (the triangles are coarser than that).
  const SampleAcceptance standing_base_only = [&](const Vec3& root, int32_t t) {
    const int64_t row = context.nearest_root_point(root);
    const Vec3 normal = triangle_normal(input, t);
    return !stands_off_the_scalp(strands, row, normal) ||
           along_the_scalp_m(point_of(strands.points, row) - root, normal) <= standing_cover_m;
  };
  if (covered_count == 0)
    throw Error::bad_input(input.source,
                           "no scalp triangle lies under a root-type input strand: nothing to "
                           "grow from (is scalp_cover_h too small?)");
  return poisson_disk_samples(input.body_vertices, input.body_triangles, covered,
                              params.strand_count, static_cast<uint64_t>(params.seed), 5,
                              standing_base_only);
}

RootReferences root_references(const GrowingContext& context, const Points3f& root_positions) {
  auto root_count = static_cast<int64_t>(root_positions.rows());
  std::vector<int64_t> reference_row(static_cast<size_t>(root_count));
  std::vector<int32_t> root_cluster(static_cast<size_t>(root_count));
#pragma omp parallel for schedule(dynamic, 256)
  for (int64_t r = 0; r < root_count; ++r) {
    reference_row[static_cast<size_t>(r)] = context.reference_row(point_of(root_positions, r), r);
    root_cluster[static_cast<size_t>(r)] =
        context.cluster_of_strand(context.strand_of_point(reference_row[static_cast<size_t>(r)]));
  }
  return {std::move(reference_row), std::move(root_cluster)};
}

StrandSet field_paint_seeds(const GrowInput& input, const GrowingContext& context,
                            const GrowParams& params) {
  const StrandSet& strands = input.input_strands;
  std::vector<uint8_t> seeding_group(input.group_cluster.size(), 0);
  for (int64_t s = 0; s < strands.strand_count(); ++s)
    if (context.carries_roots(s))
      seeding_group[static_cast<size_t>(context.group_of_strand(s))] = 1;
  if (!params.field_paint_seeds || input.hair_triangle_flow.rows() != input.hair_triangles.rows()) {
    StrandSet none;
    none.strand_attributes["group"] = std::vector<int32_t>{};
    return none;
  }
  PaintedFieldSeedParams seed_params;
  seed_params.spacing_m = 0.5 * params.field_voxel_h * input.head_height_m;
  seed_params.sign_radius_m = params.field_band_h * input.head_height_m;
  return painted_field_seeds(input.hair_vertices, input.hair_triangles, input.hair_triangle_group,
                             input.hair_triangle_flow, seeding_group, strands, seed_params);
}

Vec3 stub_step_direction(const GrowingContext& context, int64_t reference_row, const Vec3& normal,
                         const Vec3& root) {
  const Vec3 direction = stub_direction(context.input().input_strands,
                                        context.strand_of_point(reference_row), reference_row,
                                        normal);
  return along_paint(direction, normal, context.painted_flow_near(root));
}

}  // namespace hair
