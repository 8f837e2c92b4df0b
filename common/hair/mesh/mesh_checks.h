#pragma once

#include <string>

#include "hair/mesh/poly_mesh.h"

namespace hair {

/// What clean_mesh() removed.
struct MeshCleanup {
  int64_t degenerate_faces_removed = 0;  ///< faces with fewer than 3 distinct vertices
  int64_t repeated_corners_removed = 0;  ///< consecutive repeats of a vertex in a face
};

/// Rejects meshes no stage can use, naming `file` and the first problem: no vertices,
/// no faces, a non-finite coordinate (names the vertex), a face index out of range.
/// Throws hair::Error (bad_input).
void check_mesh(const PolyMesh& mesh, const std::string& file);

/// Drops repeated consecutive corners and faces left with fewer than 3 distinct
/// vertices; the mesh is then checked again with check_mesh().
MeshCleanup clean_mesh(PolyMesh& mesh, const std::string& file);

}  // namespace hair
