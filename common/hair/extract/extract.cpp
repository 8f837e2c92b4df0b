#include "hair/extract/extract.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <utility>

#include "hair/core/error.h"
#include "hair/extract/continuation.h"
#include "hair/extract/extract_params.h"
#include "hair/extract/group_sense.h"
#include "hair/extract/painted_streamlines.h"
#include "hair/extract/rail_paint.h"
#include "hair/extract/region_orientation.h"
#include "hair/extract/region_rails.h"
#include "hair/extract/scalp.h"
#include "hair/extract/streamline_orientation.h"
#include "hair/extract/tube_streamlines.h"
#include "hair/mesh/mesh_checks.h"
#include "hair/mesh/mesh_patches.h"
#include "hair/mesh/quad_recovery.h"

namespace hair {
namespace {

void append_rail(std::vector<Points3f>& polylines, const Points3f& vertices,
                 const std::vector<int32_t>& rail, std::vector<int32_t>& source_vertex) {
  Points3f points(static_cast<Eigen::Index>(rail.size()), 3);
  for (size_t i = 0; i < rail.size(); ++i)
    points.row(static_cast<Eigen::Index>(i)) = vertices.row(rail[i]);
  polylines.push_back(std::move(points));
  source_vertex.insert(source_vertex.end(), rail.begin(), rail.end());
}

/// The body's triangles with a vertex at or above the neck.
Triangles3i head_triangles_of(const Points3f& body_vertices, const Triangles3i& body_triangles,
                              double neck_y, const std::string& body_file) {
  Triangles3i head_triangles(body_triangles.rows(), 3);
  Eigen::Index head_triangle_count = 0;
  for (Eigen::Index t = 0; t < body_triangles.rows(); ++t) {
    double top_y = -std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k)
      top_y = std::max<double>(top_y, body_vertices(body_triangles(t, k), 1));
    if (top_y >= neck_y) head_triangles.row(head_triangle_count++) = body_triangles.row(t);
  }
  head_triangles.conservativeResize(head_triangle_count, 3);
  if (head_triangle_count == 0)
    throw Error::bad_input(body_file, "body mesh has no head above the neck");
  return head_triangles;
}

/// A patch without usable quads: one strand along its principal axis, directed by the
/// scalp distance and height of its ends. Returns the polyline and its decision.
std::pair<Points3f, OrientationDecision> triangle_soup_strand(
    const PolyMesh& hair_mesh, std::span<const int64_t> faces,
    const TriangleMeshDistance& head_distance, const OrientationThresholds& thresholds) {
  Points3f polyline = principal_axis_polyline(hair_mesh, faces);
  Eigen::Vector3d first = polyline.row(0).cast<double>().transpose();
  Eigen::Vector3d last = polyline.row(polyline.rows() - 1).cast<double>().transpose();
  double length = std::max(1e-12, (last - first).norm());
  OrientationEvidence evidence;
  evidence.scalp_distance_slope =
      (head_distance.distance(last) - head_distance.distance(first)) / length;
  evidence.height_slope = (first.y() - last.y()) / length;
  OrientationDecision decision =
      *decide_orientation(evidence, thresholds, MeshConventions{false, std::nullopt});
  if (decision.reverse) polyline = polyline.colwise().reverse().eval();
  return {std::move(polyline), decision};
}

/// The diagonal of the bounding box of the vertices of `faces`.
double patch_extent(const PolyMesh& mesh, std::span<const int64_t> faces) {
  Eigen::Vector3f low = Eigen::Vector3f::Constant(std::numeric_limits<float>::max());
  Eigen::Vector3f high = -low;
  for (int64_t face : faces)
    for (int32_t v : mesh.face(face)) {
      low = low.cwiseMin(mesh.vertices.row(v).transpose());
      high = high.cwiseMax(mesh.vertices.row(v).transpose());
    }
  return faces.empty() ? 0.0 : static_cast<double>((high - low).norm());
}

/// Tubes whose traced streamlines are not hair (tube_streamlines.h: a braid piece's strokes
/// wound round it) keep their rails: their tracing is dropped from `traced`.
void keep_braid_pieces_on_their_rails(
    const PolyMesh& mesh, const MeshPatches& patches, const std::vector<PatchTopology>& topologies,
    const std::vector<std::vector<int>>& along, const ExtractParams& params,
    std::vector<std::optional<std::vector<PaintedStreamline>>>& traced, ExtractStats& stats) {
  TubeStreamlineLimits limits;
  limits.max_extent_ratio = params.streamline_tube_max_extent_ratio;
  limits.min_length_share = params.streamline_tube_min_length_share;
  for (int32_t p = 0; p < patches.patch_count(); ++p) {
    auto& streamlines = traced[static_cast<size_t>(p)];
    if (!streamlines || patch_kind(topologies[p], along[p]) != PatchKind::tube) continue;
    double rails_m = 0;
    for (size_t r = 0; r < topologies[p].regions.size(); ++r)
      rails_m += topologies[p].regions[r].families[along[p][r]].mean_chain_length;
    rails_m /= static_cast<double>(std::max<size_t>(1, topologies[p].regions.size()));
    if (tube_streamlines_are_hair(*streamlines, patch_extent(mesh, patches.patch_faces[p]), rails_m,
                                  limits)) {
      ++stats.tubes_traced_along_paint;
    } else {
      ++stats.tubes_kept_on_rails;
      streamlines.reset();
    }
  }
}

/// Median length of the edges of `faces`.
double median_edge_length(const PolyMesh& mesh, std::span<const int64_t> faces) {
  std::vector<double> lengths;
  for (int64_t face : faces) {
    const int64_t first = mesh.face_offsets[static_cast<size_t>(face)];
    const int corners = mesh.face_size(face);
    for (int c = 0; c < corners; ++c)
      lengths.push_back((mesh.vertices.row(mesh.face_vertices[static_cast<size_t>(first + c)]) -
                         mesh.vertices.row(mesh.face_vertices[static_cast<size_t>(first + (c + 1) % corners)]))
                            .norm());
  }
  if (lengths.empty()) return 0;
  std::nth_element(lengths.begin(), lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2),
                   lengths.end());
  return lengths[lengths.size() / 2];
}

/// The strands, group (patch) by group: each region's rails in their decided direction,
/// or one strand along a patch without usable quads; the group's kind, rule and
/// confidence (those of its region with the most rails) into `result`.
void group_strands(const MeshPatches& patches, const std::vector<PatchTopology>& topologies,
                   const std::vector<std::vector<int>>& along, std::vector<RegionRails>& regions,
                   std::vector<std::optional<std::vector<PaintedStreamline>>> traced,
                   const std::vector<std::optional<double>>& rails_along_share,
                   const ExtractParams& params, double near_m,
                   const TriangleMeshDistance& head_distance,
                   const OrientationThresholds& thresholds, const EdgeFaces& edge_faces,
                   ExtractResult& result) {
  const Points3f& vertices = result.hair_mesh.vertices;
  std::vector<Points3f> polylines;
  std::vector<int32_t> strand_group, strand_rail, source_vertex;
  std::vector<bool> is_traced(traced.size());
  for (size_t p = 0; p < traced.size(); ++p) is_traced[p] = traced[p].has_value();
  const StrandEndIndex untraced_ends(vertices, regions, is_traced);
  size_t next_region = 0;
  for (int32_t p = 0; p < patches.patch_count(); ++p) {
    int32_t rail_in_patch = 0;
    size_t largest_rail_count = 0;
    OrientationDecision group_decision{false, OrientationRule::height, 0.0f};
    auto add_rail = [&](const std::vector<int32_t>& rail) {
      append_rail(polylines, vertices, rail, source_vertex);
      strand_group.push_back(p);
      strand_rail.push_back(rail_in_patch++);
    };
    const size_t first_region = next_region;
    const bool traced_patch = traced[static_cast<size_t>(p)] && !traced[static_cast<size_t>(p)]->empty();
    for (; next_region < regions.size() && regions[next_region].patch == p; ++next_region) {
      RegionRails& region = regions[next_region];
      if (!traced_patch) {
        for (auto& rail : region.open_rails) {
          if (region.decision->reverse) std::reverse(rail.begin(), rail.end());
          add_rail(rail);
        }
        for (const auto& rail : region.parted_rails) add_rail(rail);
      }
      size_t rail_count = region.open_rails.size() + region.parted_rails.size();
      if (rail_count > largest_rail_count) {
        largest_rail_count = rail_count;
        group_decision = region.open_rails.size() >= region.parted_rails.size()
                             ? *region.decision
                             : OrientationDecision{false, OrientationRule::parting, 1.0f};
      }
    }
    if (traced_patch) {
      PatchStreamlines oriented = oriented_streamlines(
          std::move(*traced[static_cast<size_t>(p)]), p, untraced_ends,
          decided_rail_segments(result.hair_mesh, result.painted_flow, edge_faces,
                                std::span<const RegionRails>(regions).subspan(
                                    first_region, next_region - first_region)),
          group_decision,
          rails_along_share[static_cast<size_t>(p)].value_or(0) >=
              params.streamline_rails_min_along_share,
          near_m, head_distance, thresholds);
      for (Points3f& polyline : oriented.polylines) {
        source_vertex.insert(source_vertex.end(), static_cast<size_t>(polyline.rows()), -1);
        polylines.push_back(std::move(polyline));
        strand_group.push_back(p);
        strand_rail.push_back(rail_in_patch++);
      }
      group_decision = oriented.decision;
    }
    PatchKind kind = patch_kind(topologies[p], along[p]);
    if (rail_in_patch == 0 || kind == PatchKind::triangle_soup) {
      kind = PatchKind::triangle_soup;
      auto [polyline, decision] =
          triangle_soup_strand(result.hair_mesh, patches.patch_faces[p], head_distance, thresholds);
      group_decision = decision;
      source_vertex.insert(source_vertex.end(), static_cast<size_t>(polyline.rows()), -1);
      polylines.push_back(std::move(polyline));
      strand_group.push_back(p);
      strand_rail.push_back(rail_in_patch++);
    }
    result.group_first_strand.push_back(static_cast<int32_t>(polylines.size()));
    result.group_kind.push_back(kind);
    result.group_rule.push_back(group_decision.rule);
    result.group_confidence.push_back(group_decision.confidence);
    result.group_face_count.push_back(static_cast<int32_t>(patches.patch_faces[p].size()));
    ++result.stats.groups_by_rule[static_cast<size_t>(group_decision.rule)];
    ++result.stats.groups_by_kind[static_cast<size_t>(kind)];
  }
  result.strands = strand_set_from_polylines(polylines);
  result.strands.strand_attributes["group"] = std::move(strand_group);
  result.strands.strand_attributes["rail"] = std::move(strand_rail);
  result.strands.point_attributes["source_vertex"] = std::move(source_vertex);
  check_strand_set(result.strands);
}

/// The middle of the extent of the body's vertices above `neck_y` (the head region); the
/// origin when there are none.
Eigen::Vector3d head_region_centre(const Points3f& body_vertices, double neck_y) {
  Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector3d high = -low;
  for (Eigen::Index v = 0; v < body_vertices.rows(); ++v) {
    if (body_vertices(v, 1) < neck_y) continue;
    const Eigen::Vector3d p = body_vertices.row(v).cast<double>().transpose();
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  return low.x() <= high.x() ? Eigen::Vector3d(0.5 * (low + high)) : Eigen::Vector3d::Zero();
}

}  // namespace

ExtractResult extract_strands(PolyMesh hair_mesh, PolyMesh body_mesh, const ExtractParams& params,
                              const std::string& hair_file, const std::string& body_file,
                              const PaintedTextures& textures) {
  check_extract_params(params);
  ExtractResult result;
  MeshCleanup cleanup = clean_mesh(hair_mesh, hair_file);
  clean_mesh(body_mesh, body_file);
  hair_mesh.vertices *= static_cast<float>(params.unit_scale);
  body_mesh.vertices *= static_cast<float>(params.unit_scale);
  result.stats.degenerate_faces_removed = cleanup.degenerate_faces_removed;

  // The body: head height H, head region, triangles.
  result.head = head_measures(body_mesh, body_file);
  if (params.head_height_m > 0) {
    result.head.head_height = params.head_height_m;
    result.head.neck_y = result.head.head_top_y - params.head_height_m;
  }
  const double head_height_m = result.head.head_height;
  result.body_vertices = body_mesh.vertices;
  result.body_triangles = fan_triangulation(body_mesh.face_offsets, body_mesh.face_vertices);
  TriangleMeshDistance head_distance(
      result.body_vertices, head_triangles_of(result.body_vertices, result.body_triangles,
                                              result.head.neck_y, body_file));

  // The hair: quads, patches, edge families.
  QuadRecovery recovered = quads_from_triangles(hair_mesh, params.max_quad_corner_deviation_deg);
  result.stats.triangles_paired = recovered.triangles_paired;
  result.stats.triangles_left = recovered.triangles_left;
  result.hair_mesh = std::move(recovered.mesh);
  const Points3f& vertices = result.hair_mesh.vertices;
  MeshPatches patches = mesh_patches(result.hair_mesh);
  result.face_group = patches.face_patch;
  std::vector<PatchTopology> topologies(static_cast<size_t>(patches.patch_count()));
#pragma omp parallel for schedule(dynamic)
  for (int32_t p = 0; p < patches.patch_count(); ++p)
    topologies[p] = patch_topology(result.hair_mesh, patches.patch_faces[p]);

  // The painted flow, and the family of each region that runs along the hair.
  result.painted_flow = painted_flow(result.hair_mesh, textures, params.painted_flow);
  const PaintedFlow no_flow;
  const PaintedFlow& guiding_flow = params.paint_guides_strands ? result.painted_flow : no_flow;
  const EdgeFaces edge_faces(result.hair_mesh);
  const auto paint = family_paint(result.hair_mesh, guiding_flow, edge_faces, topologies);
  std::vector<std::vector<int>> along = along_families(
      vertices, topologies, paint, head_region_centre(result.body_vertices, result.head.neck_y),
      head_height_m, params, result.stats);

  // Rails, their directions, and the strands group by group.
  std::vector<RegionRails> regions =
      region_rails(result.hair_mesh, guiding_flow, edge_faces, topologies, along,
                   head_distance, params, head_height_m, result.stats);
  OrientationThresholds thresholds;
  thresholds.vertex_order_min_vote = params.vertex_order_min_vote;
  thresholds.scalp_distance_min_slope = params.scalp_distance_min_slope;
  thresholds.scalp_distance_lean_slope = params.scalp_distance_lean_slope;
  thresholds.uv_min_growth = params.uv_min_growth;
  thresholds.height_min_slope = params.height_min_slope;
  thresholds.height_min_head_distance_m = params.height_min_head_distance_h * head_height_m;
  thresholds.alpha_fade_min_fall = params.alpha_fade_min_fall;
  thresholds.alpha_fade_min_rail_fall = params.alpha_fade_min_rail_fall;

  // Patches whose rails would cross the paint are cut into strands along it instead;
  // their rails still take part in deciding directions, and orient the strands. Only
  // patches on the head are traced (caps, wigs and shells, their quads in rings); cards and
  // braid pieces hanging off it keep their rails, and so does a tube on the head whose
  // streamlines are not hair (a cornrow's pieces, with strokes painted round them).
  std::vector<std::optional<std::vector<PaintedStreamline>>> traced(topologies.size());
  std::vector<std::optional<double>> rails_along_share(topologies.size());
  for (int32_t p = 0; p < patches.patch_count(); ++p)
    rails_along_share[static_cast<size_t>(p)] =
        rails_along_paint_share(topologies[p], paint[p], along[p], params);
#pragma omp parallel for schedule(dynamic)
  for (int32_t p = 0; p < patches.patch_count(); ++p)
    if (rails_along_share[static_cast<size_t>(p)] &&
        *rails_along_share[static_cast<size_t>(p)] < params.streamline_max_along_share &&
        lies_on_the_head(result.hair_mesh, patches.patch_faces[p], head_distance,
                         params.streamline_max_head_distance_h * head_height_m)) {
      StreamlineParams streamline_params;
      streamline_params.spacing_m =
          std::max(1e-6, median_edge_length(result.hair_mesh, patches.patch_faces[p]));
      streamline_params.min_length_m = 2 * streamline_params.spacing_m;
      traced[p] = painted_streamlines(result.hair_mesh, result.painted_flow,
                                      patches.patch_faces[p], streamline_params);
    }
  keep_braid_pieces_on_their_rails(result.hair_mesh, patches, topologies, along, params, traced,
                                   result.stats);
  for (int32_t p = 0; p < patches.patch_count(); ++p)
    if (traced[static_cast<size_t>(p)]) {
      ++result.stats.patches_traced_along_paint;
      spdlog::debug(
          "{}: patch {} ({} faces, rails along the paint on {:.2f} of their length) traced along "
          "its paint: {} strands",
          hair_file, p, patches.patch_faces[p].size(), *rails_along_share[static_cast<size_t>(p)],
          traced[static_cast<size_t>(p)]->size());
    }
  decide_directions(vertices, regions, thresholds, params, head_height_m, result.stats);
  group_strands(patches, topologies, along, regions, std::move(traced), rails_along_share, params,
                params.continuation_radius_h * head_height_m, head_distance, thresholds, edge_faces,
                result);
  // Last, a strand that runs against the rest of its group turns round (the hair a patch
  // shows flows smoothly across it), within twice the continuation radius.
  GroupSenseParams sense;
  sense.radius_m = 2 * params.continuation_radius_h * head_height_m;
  result.stats.strands_turned_to_their_group =
      turn_strands_against_their_group(result.strands, result.group_first_strand, sense);

  ScalpParams scalp;
  scalp.neck_y = result.head.neck_y;
  scalp.max_distance_m = params.scalp_distance_h * head_height_m;
  scalp.under_hair_m = params.scalp_under_hair_h * head_height_m;
  scalp.under_hair_min_height_m = params.scalp_under_hair_min_height_h * head_height_m;
  scalp.face_below_y = result.head.head_top_y - params.scalp_face_below_top_h * head_height_m;
  scalp.face_radius_m = kFaceRadiusH * head_height_m;
  scalp.face_depth_m = kFaceDepthH * head_height_m;
  scalp.face_half_width_m = kFaceHalfWidthH * head_height_m;
  scalp.ear_thickness_m = kEarThicknessH * head_height_m;
  result.scalp_triangle =
      scalp_triangles(result.body_vertices, result.body_triangles, result.hair_mesh, scalp);
  return result;
}

}  // namespace hair
