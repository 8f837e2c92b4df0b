#include "hair/grow/strand_growing.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <numeric>
#include <optional>

#include "hair/core/error.h"
#include "hair/geom/body_sdf.h"
#include "hair/grow/grow_params.h"
#include "hair/grow/growing_context.h"
#include "hair/grow/orientation_field.h"
#include "hair/grow/scalp_roots.h"
#include "hair/grow/strand_grower.h"

namespace hair {

const char* grow_rule_name(GrowRule rule) {
  switch (rule) {
    case GrowRule::root:
      return "root";
    case GrowRule::field:
      return "field";
    case GrowRule::input_strand:
      return "input_strand";
    case GrowRule::bridge:
      return "bridge";
  }
  return "?";
}

namespace {

using Vec3 = Eigen::Vector3d;
using ClusterFields = std::vector<std::optional<OrientationField>>;

/// Throws hair::Error: usage for parameters out of their ranges (check_grow_params()),
/// bad_input for a head height that is not positive, no input strands, or scalp flags
/// that are not one per body triangle.
void check_grow_input(const GrowInput& input, const GrowParams& params) {
  check_grow_params(params);
  const double h = input.head_height_m;
  if (!(h > 0)) throw Error::bad_input(input.source, "head height is not positive");
  if (input.input_strands.strand_count() == 0)
    throw Error::bad_input(input.source, "no input strands to grow from");
  if (input.scalp_triangle.size() != static_cast<size_t>(input.body_triangles.rows()))
    throw Error::bad_input(input.source, "scalp flags do not match the body's triangles");
}

/// One field per cluster with roots (`root_cluster`, per root), from its root-carrying
/// strands, then the paint seeds of its groups (field_paint_seeds()), then the seeds
/// under its shells (`under_shells`, seeds_under_shells()); `clusters` (one per cluster)
/// gets each cluster's roots and field voxels.
ClusterFields cluster_fields(const GrowInput& input, const GrowingContext& context,
                             const GrowParams& params, const std::vector<int32_t>& root_cluster,
                             const StrandSet& under_shells, std::vector<GrownCluster>& clusters) {
  const double h = input.head_height_m;
  const StrandSet& strands = input.input_strands;
  int32_t cluster_count = 0;
  for (int32_t c : input.group_cluster) cluster_count = std::max(cluster_count, c + 1);
  clusters.resize(static_cast<size_t>(cluster_count));
  for (int32_t c : root_cluster) ++clusters[static_cast<size_t>(c)].strand_count;
  ClusterFields fields(static_cast<size_t>(cluster_count));
  OrientationFieldParams field_params{params.field_voxel_h * h, params.field_band_h * h};
  const StrandSet paint_seeds = field_paint_seeds(input, context, params);
  const auto& seed_group =
      std::get<std::vector<int32_t>>(paint_seeds.strand_attributes.at("group"));
  for (int32_t c = 0; c < cluster_count; ++c) {
    if (clusters[static_cast<size_t>(c)].strand_count == 0) continue;
    std::vector<Points3f> seeding;  // the cluster's root-carrying strands, then its paint seeds
    for (int64_t s = 0; s < strands.strand_count(); ++s)
      if (context.cluster_of_strand(s) == c && context.carries_roots(s))
        seeding.emplace_back(strands.strand(s));
    if (seeding.empty()) continue;
    for (int64_t s = 0; s < paint_seeds.strand_count(); ++s)
      if (context.cluster_of_group(seed_group[static_cast<size_t>(s)]) == c)
        seeding.emplace_back(paint_seeds.strand(s));
    if (params.field_shell_seeds) {
      const auto& under_cluster =
          std::get<std::vector<int32_t>>(under_shells.strand_attributes.at("cluster"));
      for (int64_t s = 0; s < under_shells.strand_count(); ++s)
        if (under_cluster[static_cast<size_t>(s)] == c)
          seeding.emplace_back(under_shells.strand(s));
    }
    std::vector<int64_t> ids(seeding.size());
    std::iota(ids.begin(), ids.end(), int64_t{0});
    fields[static_cast<size_t>(c)] =
        OrientationField::build(strand_set_from_polylines(seeding), ids, field_params);
    clusters[static_cast<size_t>(c)].field_voxel_count =
        fields[static_cast<size_t>(c)]->band_voxel_count();
    clusters[static_cast<size_t>(c)].field_seeded_voxels =
        fields[static_cast<size_t>(c)]->seeded_voxel_count();
  }
  return fields;
}

/// The body's signed distance, over the region the strands can reach: the input strands
/// and the roots (`root_positions`), with a margin.
BodySdf body_around_hair(const GrowInput& input, const GrowParams& params,
                         const Points3f& root_positions) {
  const double h = input.head_height_m;
  const StrandSet& strands = input.input_strands;
  double margin_m = (params.continue_radius_h + params.field_band_h + params.step_h) * h;
  Vec3 low = strands.points.colwise().minCoeff().cast<double>().transpose().array() - margin_m;
  Vec3 high = strands.points.colwise().maxCoeff().cast<double>().transpose().array() + margin_m;
  Vec3 root_low = root_positions.colwise().minCoeff().cast<double>().transpose();
  Vec3 root_high = root_positions.colwise().maxCoeff().cast<double>().transpose();
  low = low.cwiseMin(root_low);
  high = high.cwiseMax(root_high);
  return BodySdf(input.body_vertices, input.body_triangles, low, high, params.body_voxel_h * h,
                 4 * params.body_voxel_h * h, input.source);
}

/// Grows each strand on its own (grow_strand()), from its root in `root_positions`.
std::vector<GrowingStrand> grow_each_strand(const GrowingContext& context,
                                            const ClusterFields& fields, const BodySdf& body,
                                            const Points3f& root_positions,
                                            const RootReferences& references) {
  const std::vector<int64_t>& reference_row = references.row;
  const std::vector<int32_t>& root_cluster = references.cluster;
  auto root_count = static_cast<int64_t>(root_positions.rows());
  std::vector<GrowingStrand> grown(static_cast<size_t>(root_count));
#pragma omp parallel for schedule(dynamic, 64)
  for (int64_t r = 0; r < root_count; ++r) {
    auto i = static_cast<size_t>(r);
    const auto& field = fields[static_cast<size_t>(root_cluster[i])];
    grown[i] = grow_strand(context, field ? &*field : nullptr, body, root_cluster[i],
                           point_of(root_positions, r), reference_row[i]);
  }
  return grown;
}

/// A strand that could not leave its root gets a second point one step out along the
/// hair there (stub_step_direction()), pushed out of the body, so every strand is a
/// polyline; `normal` is the root's (unit, outward).
void add_stub_step(GrowingStrand& strand, const GrowingContext& context, const BodySdf& body,
                   const Vec3& normal, int64_t reference_row) {
  const GrowParams& params = context.params();
  const double h = context.input().head_height_m;
  const Vec3 direction =
      stub_step_direction(context, reference_row, normal, strand.points.front());
  Vec3 step_end = strand.points.front() + params.step_h * h * direction;
  if (body.push_out(step_end, params.body_clearance_h * h)) ++strand.pushed_out;
  strand.points.push_back(step_end);
  strand.rules.push_back(GrowRule::field);
  strand.clusters.push_back(strand.clusters.front());
  strand.groups.push_back(-1);
}

/// Adds what happened to `strand` on its way to the counts of `result`.
void count_strand_outcomes(const GrowingStrand& strand, GrowResult& result) {
  result.points_pushed_out += strand.pushed_out;
  result.continuations_same_cluster += strand.continued_same;
  result.continuations_other_cluster += strand.continued_other;
  result.strands_joining_continued_flow += strand.joined > 0 ? 1 : 0;
  result.strands_ended_at_body += strand.ended_at_body ? 1 : 0;
  result.strands_ended_at_fold += strand.ended_at_fold ? 1 : 0;
  result.strands_stopped_at_air += strand.field_air_stops > 0 ? 1 : 0;
}

/// The grown strands into result.strands with their attributes, point_rule and the
/// counts; a strand that could not leave its root gets its stub step first
/// (add_stub_step()).
void assemble_strands(std::vector<GrowingStrand>& grown, const GrowingContext& context,
                      const BodySdf& body, const SurfaceSamples& roots,
                      const RootReferences& references, GrowResult& result) {
  std::vector<Points3f> polylines;
  polylines.reserve(grown.size());
  std::vector<GrowRule>& rules = result.point_rule;
  std::vector<int32_t> point_cluster, point_group;
  for (size_t i = 0; i < grown.size(); ++i) {
    GrowingStrand& strand = grown[i];
    if (strand.points.size() < 2) {
      Vec3 normal = roots.normals.row(static_cast<Eigen::Index>(i)).cast<double>().transpose();
      add_stub_step(strand, context, body, normal, references.row[i]);
    }
    Points3f polyline(static_cast<Eigen::Index>(strand.points.size()), 3);
    for (size_t k = 0; k < strand.points.size(); ++k)
      polyline.row(static_cast<Eigen::Index>(k)) = strand.points[k].cast<float>().transpose();
    polylines.push_back(std::move(polyline));
    rules.insert(rules.end(), strand.rules.begin(), strand.rules.end());
    point_cluster.insert(point_cluster.end(), strand.clusters.begin(), strand.clusters.end());
    point_group.insert(point_group.end(), strand.groups.begin(), strand.groups.end());
    count_strand_outcomes(strand, result);
  }
  result.strands = strand_set_from_polylines(polylines);
  result.strands.strand_attributes["cluster"] = references.cluster;
  result.strands.strand_attributes["root_triangle"] = roots.triangle;
  result.strands.strand_attributes["root_normal"] = roots.normals;
  result.strands.point_attributes["cluster"] = std::move(point_cluster);
  result.strands.point_attributes["group"] = std::move(point_group);
  check_strand_set(result.strands);
}

}  // namespace

GrowResult grow_strands(const GrowInput& input, const GrowParams& params) {
  check_grow_input(input, params);
  GrowResult result;
  // 1. The scalp that carries roots, and the roots on it.
  RootingScalp scalp = rooting_scalp(input, params);
  result.typed_root_scalp_share = scalp.typed_root_scalp_share;
  const GrowingContext& context = *scalp.context;
  result.roots_from_any_type = context.any_type_roots();
  const StrandSet under_shells = seeds_under_shells(input, context, params, scalp.covered);
  for (uint8_t flag : scalp.covered) result.scalp_triangles_used += flag;
  const SurfaceSamples roots =
      sample_roots(input, context, params, scalp.covered, result.scalp_triangles_used);
  result.scalp_area_m2 = roots.area_m2;
  result.root_spacing_m = roots.min_spacing_m;
  const RootReferences references = root_references(context, roots.positions);
  // 2. One field per cluster with roots.
  const ClusterFields fields =
      cluster_fields(input, context, params, references.cluster, under_shells, result.clusters);
  // 3. and 4. Each strand grown along its field and the input strands, out of the body.
  const BodySdf body = body_around_hair(input, params, roots.positions);
  std::vector<GrowingStrand> grown =
      grow_each_strand(context, fields, body, roots.positions, references);
  assemble_strands(grown, context, body, roots, references, result);
  return result;
}

}  // namespace hair
