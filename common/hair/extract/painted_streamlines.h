#pragma once
// Strands traced along the painted flow over a patch whose quads do not run along the hair
// (a cap meshed in rings, or with its strokes painted diagonally across its quads): the
// rails of such a patch would cross the hair, so the patch is cut into strands along the
// paint instead, like the evenly spaced streamlines of Jobard and Lefer (1997) on the
// patch's surface.

#include <span>
#include <vector>

#include "hair/extract/painted_flow.h"
#include "hair/mesh/poly_mesh.h"

namespace hair {

struct StreamlineParams {
  double spacing_m = 0.005;     ///< distance kept between neighbouring streamlines (d_sep)
  double min_length_m = 0.01;   ///< shorter streamlines are dropped
  double max_turn_deg = 60;     ///< a streamline stops where the flow turns more in one face
  int64_t max_crossings = 4000; ///< faces crossed per direction at most (loops end there)
};

/// One streamline: its points and what the painted alpha says about its direction.
struct PaintedStreamline {
  Points3f points;  ///< #points x 3, resampled at about the spacing
  /// Over the faces it crosses, the alpha's fall along it (each face's fall times the
  /// cosine between the streamline and the flow, weighted by the length crossed) over
  /// its magnitude, in [-1, 1]: positive where the alpha falls towards its last point.
  double fade_vote = 0;
  double fade_mean_fall = 0;  ///< mean magnitude of that fall per face crossed
};

/// Streamlines of the painted flow over `faces` of `mesh` (face ids): seeded at the
/// faces' triangles in order, each traced both ways through the faces while the flow is
/// clear (coherence >= kClearFlowCoherence), stopped at the patch's border, at a sharp
/// turn, or on coming within half the spacing of an earlier streamline; a seed within the
/// spacing of an earlier streamline is skipped. Their direction is arbitrary (the caller
/// orients them). Deterministic.
std::vector<PaintedStreamline> painted_streamlines(const PolyMesh& mesh, const PaintedFlow& flow,
                                                   std::span<const int64_t> faces,
                                                   const StreamlineParams& params);

}  // namespace hair
