#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "hair/core/strand_set.h"

namespace hair {

/// Segments judged against the flow, and those of them that run along it.
struct FlowTally {
  int64_t judged = 0;
  int64_t along = 0;
};

/// How the segments of grown strands run along the flow, by how each was grown
/// (`hair-grow-report --by-rule`, docs/grow.md).
struct FlowByRule {
  /// Per GrowRule of the segment's end point: [1] field, [2] input strand, [3] bridge
  /// ([0], the root, stays empty).
  std::array<FlowTally, 4> by_rule;
  /// The field's segments by their place from the root: [0] the first (from the root),
  /// [1] the second, [2] the third, [3] the fourth and later.
  std::array<FlowTally, 4> field_by_step;
};

/// Tallies `along_per_point`, segments_along_painted_flow()'s answer for `strands` (per
/// point, 1 for a segment within the angle of the flow, 0 across it, -1 not judged), by
/// `point_rule` (the grow stage's /strands/point_rule, GrowRule values 0-3). Each segment
/// is counted once, at its end point: a root's entry, which judges the same first segment
/// as the next point's, is left out. Throws hair::Error (bad input) when the arrays do not
/// have one entry per point or a rule lies outside 0-3.
FlowByRule flow_agreement_by_rule(const StrandSet& strands,
                                  const std::vector<int8_t>& along_per_point,
                                  const std::vector<int8_t>& point_rule);

}  // namespace hair
