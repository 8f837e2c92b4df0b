#pragma once
// The rails of each quad region of a hair mesh: the edge family that runs along the hair,
// its chains (fragments dropped; closed, draped and folded rails parted) and what they say
// about their direction.

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "hair/extract/circling_rails.h"
#include "hair/extract/extract.h"
#include "hair/extract/painted_flow.h"
#include "hair/extract/rail_paint.h"
#include "hair/extract/strand_orientation.h"
#include "hair/geom/triangle_mesh_distance.h"
#include "hair/mesh/patch_rails.h"
#include "hair/mesh/poly_mesh.h"

namespace hair {

/// The rails of one quad region, before and after orientation.
struct RegionRails {
  int32_t patch = 0;
  size_t region_in_patch = 0;
  std::vector<std::vector<int32_t>> open_rails;    ///< consistently oriented chains
  std::vector<std::vector<int32_t>> parted_rails;  ///< halves of parted rails, root to tip
  OrientationEvidence evidence;
  std::optional<OrientationDecision> decision;
};

/// The share of observations that are true, or nullopt with fewer than 3.
std::optional<double> share_true(const std::vector<bool>& observations);

/// The length of a rail, the polyline through its vertices `rail` (ids in `vertices`).
double rail_length(const Points3f& vertices, const std::vector<int32_t>& rail);

/// Picks the family of each quad region that runs along the hair: where the painted
/// flow decides (family_along_paint()), the family along the paint; else, where the
/// paint is not clear and one family circles the axis from `head_centre` through the region
/// (family_across_rings()), the other; else the family with clearly longer chains; where
/// the two are alike (square cards, caps), the family that follows the mesh's texture
/// axis, learnt from the clear regions.
std::vector<std::vector<int>> along_families(
    const Points3f& vertices, const std::vector<PatchTopology>& topologies,
    const std::vector<std::vector<std::array<FamilyPaint, 2>>>& paint,
    const Eigen::Vector3d& head_centre, double head_height_m, const ExtractParams& params,
    ExtractStats& stats);

/// The rails of every region of every patch (the chains of its along family; short
/// fragments dropped, closed, draped and folded rails parted), and what they say about their
/// direction.
std::vector<RegionRails> region_rails(const PolyMesh& mesh, const PaintedFlow& flow,
                                      const EdgeFaces& edge_faces,
                                      const std::vector<PatchTopology>& topologies,
                                      const std::vector<std::vector<int>>& along,
                                      const TriangleMeshDistance& head_distance,
                                      const ExtractParams& params, double head_height_m,
                                      ExtractStats& stats);

}  // namespace hair
