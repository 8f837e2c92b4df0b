#pragma once
// Which grown strands the simulate stage simulates (paper section 5.2): guide strands
// spread over the clusters of the normal and short styles, and one wisp per braided
// cluster; fixed clusters are not simulated.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "hair/core/strand_set.h"
#include "hair/style/hair_style.h"

namespace hair {

/// A guide: grown strand `strand` from point `anchor_point` to its tip. The anchor point
/// is the strand's root, or the last point of a fixed cluster before the strand enters
/// `cluster` (a ponytail's tail hangs from its band): it moves with the head, the points
/// after it are simulated.
struct GuideStrand {
  int64_t strand = 0;
  int64_t anchor_point = 0;  ///< index within the strand
  int32_t cluster = 0;       ///< the simulated cluster the guide was chosen for
  HairStyle style = HairStyle::normal;
};

/// A braided cluster's wisp: its member strands' runs through the cluster, and the point
/// each member hangs from.
struct WispPlan {
  int32_t cluster = 0;
  std::vector<int64_t> member_strand;
  std::vector<int64_t> member_first_point;  ///< first point of the run in the cluster
  std::vector<int64_t> member_end_point;    ///< one past its last point
  std::vector<Eigen::Vector3d> anchor_m;    ///< point before the run, or the root
  /// Members whose point before the run is not held by the head (it belongs to a cluster
  /// that is simulated): their anchors are still moved with the head, an approximation.
  int64_t loose_anchor_count = 0;
};

/// What simulate does with every cluster, and its guides and wisps.
struct GuidePlan {
  std::vector<GuideStrand> guides;
  std::vector<WispPlan> wisps;
  /// Per cluster: candidate strands (those that enter it from the root or from a fixed
  /// cluster), and guides given to it.
  std::vector<int64_t> cluster_candidates;
  std::vector<int32_t> cluster_guides;
};

/// Plans the guides of `strands` (grown strands with the point attribute "cluster") whose
/// clusters have the styles `cluster_style` (-1 for a cluster without strands).
///
/// Guides go to the normal and short clusters, `guide_count` in all, in proportion to
/// their candidates (largest remainders; every cluster with candidates gets one while
/// there are guides to give), and within a cluster by farthest-point sampling of the
/// candidates' anchor points, starting from the candidate nearest their centroid
/// (deterministic: ties go to the lower strand index). A strand that runs from one
/// simulated cluster into another is simulated whole by a guide of the first.
/// Every braided cluster gets one wisp of all the strands that run through it.
GuidePlan plan_guides(const StrandSet& strands, const std::vector<int8_t>& cluster_style,
                      int guide_count);

/// Indices of `count` of `points` by farthest-point sampling: the first is the point
/// nearest the centroid, each next one the point farthest from those taken (ties: lowest
/// index). All of them, in that order, when count >= #points.
std::vector<int64_t> farthest_point_sample(const std::vector<Eigen::Vector3d>& points,
                                           int64_t count);

}  // namespace hair
