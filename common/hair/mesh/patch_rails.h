#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "hair/mesh/poly_mesh.h"

namespace hair {

/// The kind of a hair-mesh patch, as artists build them.
enum class PatchKind : int8_t {
  strip = 0,          ///< one row of quads: two rails
  grid = 1,           ///< rows and columns of quads (cards, caps without poles)
  tube = 2,           ///< a quad cylinder (braid pieces): rings across, rails along
  cap = 3,            ///< quads with poles (vertices where more or fewer than 4 quads meet)
  triangle_soup = 4,  ///< mostly faces that are not quads even after pairing triangles
};

/// The chains of one edge family of a quad region (see patch_topology()).
struct EdgeFamily {
  /// Vertex ids along each chain, oriented consistently across the region.
  std::vector<std::vector<int32_t>> chains;
  int32_t closed_chain_count = 0;  ///< chains that close on themselves (rings)
  double mean_chain_length = 0;    ///< mean arc length of the chains, mesh units
  /// Mean over the family's edges of |dv| / (|du| + |dv|) in texture space: near 1
  /// when the family runs along the texture's v axis; negative when there are no UVs.
  double v_alignment = -1;
  /// Mean of the signed dv along the chain direction, per unit of |du|+|dv|: its sign
  /// tells whether v grows along the oriented chains; 0 when there are no UVs.
  double v_growth = 0;
};

/// One region of a patch whose quads are connected through edges. Its edges fall in
/// two families: in every quad, opposite edges share a family and adjacent edges do
/// not. One family runs along the hair (its chains are the rails), the other across.
struct QuadRegion {
  std::array<EdgeFamily, 2> families;
  int64_t quad_count = 0;
};

/// The edge structure of one patch.
struct PatchTopology {
  std::vector<QuadRegion> regions;
  int64_t face_count = 0;
  int64_t non_quad_faces = 0;
  int32_t family_conflicts = 0;  ///< quads whose edges could not be coloured consistently
  int32_t interior_poles = 0;    ///< interior vertices where other than 4 quads meet
};

/// Reads the edge families and their chains of the patch made of `faces` (face ids
/// of `mesh`). Chains pass straight through regular vertices and end at boundary
/// corners and at poles.
PatchTopology patch_topology(const PolyMesh& mesh, std::span<const int64_t> faces);

/// Classifies a patch from its topology and the family chosen as along.
PatchKind patch_kind(const PatchTopology& topology, std::span<const int> along_family);

/// A strand for a patch without usable quads: the polyline through the centroids of
/// slices of its vertices along their principal axis, #points x 3 (unoriented).
Points3f principal_axis_polyline(const PolyMesh& mesh, std::span<const int64_t> faces);

}  // namespace hair
