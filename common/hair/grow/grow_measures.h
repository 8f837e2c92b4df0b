#pragma once

#include <cstdint>
#include <vector>

#include "hair/core/strand_set.h"
#include "hair/geom/triangle_mesh_distance.h"

namespace hair {

/// How well grown strands reproduce the hair mesh they were grown from (issue 5's
/// measures); distances in head heights H.
struct GrowMeasures {
  int64_t mesh_samples = 0;   ///< points sampled on the hair mesh, uniformly by area
  int64_t strand_points = 0;  ///< grown points measured
  /// Coverage: from each mesh sample to the nearest grown strand segment.
  double coverage_mean_h = 0, coverage_p95_h = 0;
  /// Fidelity: from each grown point (roots excluded) to the hair mesh.
  double fidelity_mean_h = 0, fidelity_p95_h = 0;
  /// Share of grown points inside the body (the exact distance to the body's surface
  /// signed by the nearest triangle's side).
  double inside_body_share = 0;
  /// Largest and mean distance of a root from the scalp triangles.
  double root_distance_max_h = 0, root_distance_mean_h = 0;
  /// Coverage per group of hair triangles (when groups are given): the group whose
  /// samples lie farthest from the grown strands on average, among groups with at least
  /// kMinGroupSamples samples, so that a lost layer shows; -1 without groups.
  int32_t worst_group = -1;
  double worst_group_coverage_mean_h = 0;
  int64_t worst_group_samples = 0;
  static constexpr int64_t kMinGroupSamples = 20;
};

/// Measures `grown` against the hair mesh (triangles) and the body with its scalp flags;
/// `hair_triangle_group` (per hair triangle, its group; may be empty) gives the coverage
/// of the worst group.
/// Deterministic: the mesh samples come from a fixed seed.
GrowMeasures measure_grown_strands(const StrandSet& grown, const Points3f& hair_vertices,
                                   const Triangles3i& hair_triangles, const Points3f& body_vertices,
                                   const Triangles3i& body_triangles,
                                   const std::vector<uint8_t>& scalp_triangle, double head_height_m,
                                   int64_t mesh_sample_count = 20000,
                                   const std::vector<int32_t>& hair_triangle_group = {});

/// Per cluster of the input, where the grown strands that touch it come from and go:
/// whether a cap's strands run on into the tail or bun its hair gathers into (a grown
/// strand's points carry the cluster they run through, point attribute "cluster").
struct ClusterPassage {
  int64_t rooted = 0;         ///< strands rooted in the cluster
  int64_t rooted_leaving = 0;  ///< of those, strands whose tip lies in another cluster
  int64_t passing_in = 0;     ///< strands rooted in another cluster with points in this one
};

/// ClusterPassage of every cluster, from the strands' "cluster" strand attribute (the
/// root's) and point attribute; `cluster_count` clusters (ids outside are ignored).
std::vector<ClusterPassage> cluster_passages(const StrandSet& grown, int64_t cluster_count);

}  // namespace hair
