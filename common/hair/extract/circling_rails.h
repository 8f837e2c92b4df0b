#pragma once
// Hair does not go round the head. A one-piece shell or wig cap meshed in rings (latitudes
// round the crown, as an afro's sphere is often modelled, or rings round a wig's whorl) has
// one edge family that circles the axis from the head's centre through the piece, and one
// that runs from the crown or whorl out to the hairline. Without paint to say which, the
// longer family is the rings; but a strand grows from its root outwards, and a chain that
// winds round the head is a contour of the shell, not a strand (docs/extract.md, step 7).

#include <array>
#include <vector>

#include "hair/core/strand_set.h"
#include "hair/mesh/patch_rails.h"

namespace hair {

/// How one edge family's chains run about an axis.
struct FamilyCircling {
  /// Of the chains' length, the share that runs round the axis: the sum over edges of the
  /// edge's component along the tangent of the circle about the axis through the edge's
  /// middle, over the sum of edge lengths. 1 for a ring about the axis, 0 for a meridian
  /// (a chain in a plane through the axis).
  double circling_share = 0;
  /// The mean over chains of the angle each winds about the axis (degrees, unsigned):
  /// 360 for a closed ring, about 0 for a chain that goes down or across the head without
  /// winding round it.
  double mean_sweep_deg = 0;
  /// The mean arc length of the chains (the family's own, mesh units).
  double mean_chain_length = 0;
};

/// `family`'s chains (ids in `vertices`) about the axis through `axis_point` along the unit
/// vector `axis_direction`.
FamilyCircling family_circling(const Points3f& vertices, const EdgeFamily& family,
                               const Eigen::Vector3d& axis_point,
                               const Eigen::Vector3d& axis_direction);

/// The axis a region's rings would circle: from `head_centre` through the mean of the
/// region's chain vertices (either family's); straight up when that mean is at the centre.
Eigen::Vector3d region_axis_direction(const Points3f& vertices, const EdgeFamily& family,
                                      const Eigen::Vector3d& head_centre);

/// What makes a family circle the head.
struct CirclingLimits {
  double min_circling_share = 0.7;        ///< of its length running round the axis
  double min_sweep_deg = 120;             ///< winding at least this far round it, on average
  double max_other_circling_share = 0.3;  ///< the other family runs across the rings
  double other_min_length_m = 0.06;       ///< and its chains are strands, not a strip's width
};

/// The family (0 or 1) that runs along the hair because the other circles the head, or -1
/// where neither or both do, or where the other family's chains are too short to be
/// strands (a braid wound round the head, whose across chains are the braid's width).
int family_across_rings(const std::array<FamilyCircling, 2>& families,
                        const CirclingLimits& limits);

}  // namespace hair
