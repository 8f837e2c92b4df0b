#pragma once
// Where a braided cluster's strands gather into a bundle (simulate stage, paper section
// 5.2: "only a center strand is physically simulated"), and the wisp's centre strand.

#include <Eigen/Core>
#include <vector>

#include "hair/core/strand_set.h"
#include "hair/geom/body_sdf.h"
#include "hair/sim/guide_selection.h"

namespace hair {

/// The centre strand of the wisp of `wisp`'s cluster at rest, root end first, or empty
/// when its strands do not gather into a bundle.
///
/// The members whose tips end together are the wisp: those within twice `gather_radius_m`
/// of the densest tip, then of their mean, until it settles. The others end away from
/// the braid (a cluster can hold the hair that leads into a braid as well); they are left
/// out of `wisp` and returned in `loose` as normal-hair guide candidates of its cluster.
///
/// Each kept member's run through the cluster is sampled every `step_m` of arc length
/// from its tip back. At each sample the members long enough give a mean point and a
/// spread (mean distance from it). The bundle is the longest stretch of samples where at
/// least half the members reach and the spread stays within `gather_radius_m`; the
/// centre strand is the mean points over it, pushed out of `body` to `clearance_m`. Each
/// member then enters the wisp at its first point within the bundle's length from its
/// tip and hangs from the point before that (or its root): `wisp`'s members, first points
/// and anchors are updated.
///
/// Empty, with `wisp` and `loose` untouched, when fewer than two tips end together, when
/// no stretch of three samples gathers (two make no tetrahedron of the wisp's chain), or
/// when a centre point stays inside the body.
std::vector<Eigen::Vector3d> gather_wisp(const StrandSet& strands, WispPlan& wisp, double step_m,
                                         double gather_radius_m, const BodySdf& body,
                                         double clearance_m, std::vector<GuideStrand>& loose);

}  // namespace hair
