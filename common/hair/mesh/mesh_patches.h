#pragma once

#include <cstdint>
#include <vector>

#include "hair/mesh/poly_mesh.h"

namespace hair {

/// The patches of a hair mesh: connected components of faces that share a vertex.
struct MeshPatches {
  std::vector<int32_t> face_patch;                ///< #faces patch id
  std::vector<std::vector<int64_t>> patch_faces;  ///< #patches lists of face ids, ascending
  int32_t patch_count() const { return static_cast<int32_t>(patch_faces.size()); }
};

/// Splits a mesh into patches. Patches are numbered in the order of their lowest
/// face id, so the numbering depends only on the mesh.
MeshPatches mesh_patches(const PolyMesh& mesh);

}  // namespace hair
