#pragma once
// The grower of one strand from its root: along its cluster's orientation field, then along
// the input strands group after group, bridged from one to the next.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "hair/geom/body_sdf.h"
#include "hair/grow/growing_context.h"
#include "hair/grow/orientation_field.h"
#include "hair/grow/strand_growing.h"

namespace hair {

/// One strand being grown: its points and the rule of each.
struct GrowingStrand {
  std::vector<Eigen::Vector3d> points;
  std::vector<GrowRule> rules;
  std::vector<int32_t> clusters, groups;  ///< per point, as GrowResult::point_cluster, _group
  int64_t pushed_out = 0;
  int64_t continued_same = 0, continued_other = 0;
  int64_t joined = 0;  ///< times it joined the cards feeding a continuation (joined_feeder())
  bool ended_at_body = false;  ///< its last steps tried ran into the body (kBlockedAdvance)
  bool ended_at_fold = false;  ///< its next step, off the field, would have folded it back
  int64_t field_air_stops = 0;  ///< its field phase ran into air and was taken back
  int blocked_steps = 0;       ///< steps in a row that hardly advanced
};

/// The strand grown from `root` (StrandGrower in strand_grower.cpp): `field` is the root
/// cluster's orientation field (null when the cluster has none), `reference_row` the
/// input-strand point nearest the root (GrowingContext::reference_row()).
GrowingStrand grow_strand(const GrowingContext& context, const OrientationField* field,
                          const BodySdf& body, int32_t root_cluster, const Eigen::Vector3d& root,
                          int64_t reference_row);

}  // namespace hair
