#pragma once

#include <cstdint>

#include "hair/mesh/poly_mesh.h"

namespace hair {

/// What quad recovery did.
struct QuadRecovery {
  PolyMesh mesh;                     ///< triangles paired into quads; other faces unchanged
  int64_t triangles_paired = 0;      ///< triangles merged (twice the quads made)
  int64_t triangles_left = 0;        ///< triangles that found no partner
  std::vector<int64_t> source_face;  ///< #faces of `mesh`: a face of the input it came from
};

/// Pairs adjacent triangles back into the quads a triangulated hair card was made of,
/// so that its rails can be read (section 4.1 reads strands from edges). Two
/// triangles sharing an edge with consistent winding are candidates when the shared
/// edge is the longest edge of one of them (the diagonal a triangulation adds), or, with
/// texture coordinates, the longest of both in UV (a twisted or sheared card, such as a
/// ringlet's tube, may be split along its shorter diagonal in 3D; its quads are still
/// rectangles in its texture). Pairs are taken greedily by how close the quad's corners
/// are to right angles, measured in UV where the mesh has texture coordinates and in 3D
/// otherwise, and a pair whose worst corner in 3D is off by more than
/// `max_corner_deviation_deg` is not taken. Deterministic: ties are broken by face id.
QuadRecovery quads_from_triangles(const PolyMesh& mesh, double max_corner_deviation_deg = 60.0);

}  // namespace hair
