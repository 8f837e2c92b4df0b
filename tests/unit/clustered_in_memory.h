#pragma once

// Extract, typeify and both clusterings of a hair mesh in memory with the default
// parameters (extract's may be given), as the stages chain them: the start of the synthetic-truth
// tests. A mesh with materials (painted synthetic presets) has its embedded textures read, as the
// extract stage reads a mesh's textures.

#include <string>
#include <utility>
#include <vector>

#include "hair/cluster/group_scalp_distance.h"
#include "hair/cluster/hair_clustering.h"
#include "hair/cluster/typeify.h"
#include "hair/extract/extract.h"

namespace hair::testing {

struct ClusteredInMemory {
  ExtractResult extract;
  GroupTypes types;  ///< with start_scalp_distance_m, as typeify writes it
  MiddleClustering middle;
  HairClustering clusters;
  double head_height_m = 0;
};

/// typeify of an extract result in memory, as the stage runs it: with the distance from
/// every group's start to the body's scalp.
inline GroupTypes typeify_in_memory(const ExtractResult& extract,
                                    const TypeifyParams& params = TypeifyParams{}) {
  StrandSet centres =
      centre_strands(extract.strands, extract.group_first_strand, params.centre_points);
  std::vector<double> start_scalp_distance_m = start_scalp_distances(
      centres, extract.body_vertices, extract.body_triangles, extract.scalp_triangle);
  return group_types_from_centres(std::move(centres), std::move(start_scalp_distance_m),
                                  extract.head.head_height, params);
}

inline ClusteredInMemory cluster_in_memory(const PolyMesh& mesh, const PolyMesh& body,
                                           const std::string& name,
                                           const ExtractParams& params = ExtractParams{}) {
  ClusteredInMemory run;
  run.extract = extract_strands(mesh, body, params, name, "body",
                                load_painted_textures(mesh.materials, params.painted_flow, name));
  run.head_height_m = run.extract.head.head_height;
  const double h = run.head_height_m;
  run.types = typeify_in_memory(run.extract);
  run.middle =
      cluster_middle_groups(run.types.centre_strands, run.types.type, h, GraphClusteringParams{});
  run.clusters = cluster_hair(run.types.centre_strands, run.types.type, run.middle.middle_cluster,
                              h, HairClusteringParams{}, run.types.start_scalp_distance_m);
  return run;
}

}  // namespace hair::testing
