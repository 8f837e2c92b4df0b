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
/// so that its rails can be read (section 4.1 reads strands from edges). Exporters split
/// a card's quads along either diagonal (glTF, game engines and "beauty" triangulations
/// often along the shorter one), so which edge was added cannot be told from one pair
/// alone; the whole card can: its triangles pair up completely. Two triangles sharing an
/// edge with consistent winding, the same material and the same texture coordinates along
/// the edge are candidates when the quad they make has no corner in 3D off a right angle
/// by more than `max_corner_deviation_deg`. First, greedily by how close the quad's
/// corners are to right angles (in UV where the mesh has texture coordinates, where a
/// card's quads are near rectangles whatever it does in 3D; in 3D otherwise), the pairs
/// whose shared edge is the longest of one triangle in 3D, or of both in UV: the diagonal
/// of a near-rectangular quad. Then Edmonds' augmenting paths (Boost.Graph) over every
/// candidate pair the triangles left alone with their neighbours' partners, until the
/// matching is maximum. Deterministic: ties are broken by face id.
QuadRecovery quads_from_triangles(const PolyMesh& mesh, double max_corner_deviation_deg = 60.0);

}  // namespace hair
