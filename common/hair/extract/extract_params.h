#pragma once

#include <string>

#include "hair/core/params.h"
#include "hair/extract/extract.h"
#include "hair/mesh/mesh_io.h"

namespace hair {

/// The extract stage's settings: the algorithm's and how meshes are read.
struct ExtractStageParams {
  ExtractParams extract;
  std::string mesh_reader = "auto";  ///< "auto" or "assimp"; see MeshReader
  /// The most triangles a hair or body mesh may have (docs/extract.md, "Limits": extract
  /// needs about 0.6 kB and 0.03 ms a triangle, docs/bench/stage_resources_big.md).
  int max_mesh_triangles = 4'000'000;

  MeshReader reader() const {
    return mesh_reader == "assimp" ? MeshReader::assimp : MeshReader::automatic;
  }
  MeshLimit mesh_limit() const { return {max_mesh_triangles, "max_mesh_triangles"}; }
};

/// Registers every extract parameter with its description and range.
void declare_extract_params(ParamSet& params, ExtractStageParams& values);

/// Holds `params` to the ranges declare_extract_params() gives them (check_params());
/// extract_strands() calls it. Throws hair::Error (usage) naming the first bad value.
void check_extract_params(const ExtractParams& params);

}  // namespace hair
