#pragma once
// Which edge family of a quad region runs along the hair the artist painted: the rails of
// a region are the chains of one of its two families, and on a cap meshed in rings around
// the head, or on a square card, the longer chains need not be the ones along the hair.

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "hair/extract/painted_flow.h"
#include "hair/mesh/patch_rails.h"
#include "hair/mesh/poly_mesh.h"

namespace hair {

/// The faces on each edge of a mesh (at most two: a third adds nothing to a vote).
class EdgeFaces {
 public:
  explicit EdgeFaces(const PolyMesh& mesh);
  /// The faces on the edge between vertices a and b (either order); -1 for none.
  std::array<int64_t, 2> faces(int32_t a, int32_t b) const;

 private:
  std::unordered_map<uint64_t, std::array<int64_t, 2>> faces_;
};

/// How the chains of one edge family lie against the painted flow of their faces.
struct FamilyPaint {
  /// Share of the family's chain edges (by length) beside a face whose painted flow is
  /// clear (coherence >= kClearFlowCoherence).
  double judged_share = 0;
  /// Of the judged edge length, the share within kFlowAgreementAngleDeg of the flow's axis.
  double along_share = 0;
};

/// Per patch, per region, per family: how its chains lie against the painted flow. Each
/// chain edge is compared with the flow of every face it borders (one or two).
std::vector<std::vector<std::array<FamilyPaint, 2>>> family_paint(
    const PolyMesh& mesh, const PaintedFlow& flow, const EdgeFaces& edge_faces,
    const std::vector<PatchTopology>& topologies);

/// The family (0 or 1) that the paint says runs along the hair, or -1 where it does not
/// decide: both families judged on at least `min_judged_share` of their length, and the
/// one's along share ahead of the other's by at least `min_along_gap`.
int family_along_paint(const std::array<FamilyPaint, 2>& paint, double min_judged_share,
                       double min_along_gap);

/// What the alpha fade of the faces along some rails says about their direction.
struct AlphaFade {
  /// Over the rails' edges beside faces with a clear flow: sum of the alpha's fall along
  /// the edge's direction (the face's fall times the cosine between edge and flow) (positive: the
  /// alpha falls from the rail's first point towards its last, the tips lie that way) over the sum
  /// of its magnitude, in [-1, 1].
  double vote = 0;
  /// Mean magnitude of the fall per judged edge (alpha, 0 to 1, across one face).
  double mean_fall = 0;
  /// Mean magnitude of the fall along a whole rail (the sum over its judged edges),
  /// over the rails with at least one judged edge: how much the alpha fades from one end
  /// of the hair to the other, whatever the number of faces along it.
  double mean_rail_fall = 0;
  int64_t judged_edges = 0;
  int64_t judged_rails = 0;
};

/// The alpha fade along `rails` (vertex ids of `mesh`, in their order).
AlphaFade rails_alpha_fade(const PolyMesh& mesh, const PaintedFlow& flow,
                           const EdgeFaces& edge_faces,
                           const std::vector<std::vector<int32_t>>& rails);

}  // namespace hair
