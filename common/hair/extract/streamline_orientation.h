#pragma once
// The orientation of the strands traced along a patch's paint: which patches are traced,
// and the sense each streamline takes from the patch's rails, the strands of other patches
// at its ends, its neighbours or its own ends.

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "hair/extract/continuation.h"
#include "hair/extract/extract.h"
#include "hair/extract/painted_flow.h"
#include "hair/extract/painted_streamlines.h"
#include "hair/extract/rail_paint.h"
#include "hair/extract/region_rails.h"
#include "hair/extract/strand_orientation.h"
#include "hair/geom/point_index.h"
#include "hair/geom/triangle_mesh_distance.h"
#include "hair/mesh/patch_rails.h"
#include "hair/mesh/poly_mesh.h"

namespace hair {

/// The strands of a patch traced along its paint, oriented, and the group's decision.
struct PatchStreamlines {
  std::vector<Points3f> polylines;
  OrientationDecision decision;
};

/// The share of patch `p`'s chosen rails' judged length that runs along its faces' paint
/// (weighted by each region's quads), or nothing where the paint is clear on less than
/// `params.along_paint_min_judged_share` of it.
std::optional<double> rails_along_paint_share(const PatchTopology& topology,
                                              const std::vector<std::array<FamilyPaint, 2>>& paint,
                                              const std::vector<int>& along,
                                              const ExtractParams& params);

/// Whether the median distance of the vertices of `faces` from the head is at most
/// `max_distance_m`: a cap or wig lying on the scalp, not a card or braid hanging off it.
bool lies_on_the_head(const PolyMesh& mesh, std::span<const int64_t> faces,
                      const TriangleMeshDistance& head_distance, double max_distance_m);

/// Oriented strand segments (unit directions, each with the strand it belongs to) and an
/// index of their midpoints, to ask which way the hair runs near a point.
class SegmentIndex {
 public:
  /// Adds the segments of `points`, turned round when `sense` is negative.
  void add(const Points3f& points, int sense, size_t owner);
  /// Indexes what was added; call once, after the last add().
  void build();
  bool empty() const { return !index_.has_value(); }

  /// Sum over the segments of `points` of the cosine with the nearest indexed segment
  /// within `radius` that does not belong to `skip_owner`; `judged` receives how many
  /// segments had one.
  double agreement(const Points3f& points, float radius, int& judged,
                   std::optional<size_t> skip_owner = std::nullopt) const;

 private:
  std::vector<Eigen::Vector3f> direction_, midpoints_;
  std::vector<size_t> owner_;
  std::optional<PointIndex> index_;
};

/// The segments of a patch's decided rails, oriented root to tip, where they run along the
/// paint (within kFlowAgreementAngleDeg of the clear painted flow of a face they border):
/// rails that cross the paint (rings round a cap, a grid that pays no heed to its hair) are
/// not the hair, and the sense their vertex ids or parting give them says nothing of it.
SegmentIndex decided_rail_segments(const PolyMesh& mesh, const PaintedFlow& flow,
                                   const EdgeFaces& edge_faces,
                                   std::span<const RegionRails> patch_regions);

/// The streamlines of a patch whose rails cross its paint, oriented, in this order:
///  0. where the patch's rails were decided by a confident rule (vertex order, head
///     distance, continuation, parting), a streamline runs the way its nearest rail
///     segments do (mean cosine at least 0.3, within `near_m`);
///  1. continuation at its ends: other patches' strand ends there (`other_ends`, as for
///     rails, decide_by_continuation_once()), kept only where neighbouring votes agree;
///  2. spread through the patch: a streamline runs the way its decided neighbours do;
///  3. the patch's rails decided by weaker rules;
///  4. its own ends (head distance, alpha fade, height: own_orientation()).
/// The group's decision is continuation, the rails' decision or the most common own rule,
/// whichever oriented most streamlines.
PatchStreamlines oriented_streamlines(std::vector<PaintedStreamline> lines, int32_t patch,
                                      const StrandEndIndex& other_ends, const SegmentIndex& rails,
                                      const OrientationDecision& rails_decision,
                                      bool rails_run_along_the_hair, double near_m,
                                      const TriangleMeshDistance& head_distance,
                                      const OrientationThresholds& thresholds);

}  // namespace hair
