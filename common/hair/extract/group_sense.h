#pragma once
// The strands of one group (a patch of the mesh) run the same way: the hair a patch shows
// flows smoothly across it. A strand that runs against the others of its group over its
// length was oriented wrongly on its own (a rail whose region was decided by a rule that
// read the other rails right, a streamline turned by a vote at one of its ends) and is
// turned round: a cap's rail read from the nape up to the crown among rails that run down
// would grow a strand down the back and up again.

#include <cstdint>
#include <span>

#include "hair/core/strand_set.h"

namespace hair {

/// How strongly a strand must run against its neighbours to be turned.
struct GroupSenseParams {
  /// Neighbouring strands are those with a segment midpoint within this distance of one
  /// of the strand's segment midpoints (metres).
  double radius_m = 0;
  /// Each segment is judged against the nearest segment of each of up to this many other
  /// strands of the group (so that one wrong neighbour lying on it, a card's other layer,
  /// does not decide).
  int neighbours = 4;
  /// Of those, only the ones running along the segment's axis (|cosine| at least this)
  /// say which way it runs; one crossing it (a ring of a cap beside a strand down it)
  /// says nothing.
  double min_axis_cosine = 0.5;
  /// A strand is turned when the mean cosine of its judged segments with their
  /// neighbours' is at most minus this, over at least `min_judged` segments.
  double min_mean_cosine = 0.3;
  int min_judged = 3;
  /// Rounds of turning (each from the senses after the one before).
  int max_rounds = 4;
};

/// The mean cosine of strand `s`'s segments with the nearest segments of up to
/// params.neighbours other strands among `group` (strand ids of `strands`), over the
/// segments that have any within params.radius_m; `judged` receives their count. Exposed
/// for tests.
double mean_cosine_with_group(const StrandSet& strands, std::span<const int64_t> group, int64_t s,
                              const GroupSenseParams& params, int& judged);

/// Turns round, in place (points and point attributes), each strand of each group that
/// runs against its group (groups: strand ranges [group_first_strand[g],
/// group_first_strand[g + 1])). Returns how many strands were turned.
int64_t turn_strands_against_their_group(StrandSet& strands,
                                         std::span<const int32_t> group_first_strand,
                                         const GroupSenseParams& params);

}  // namespace hair
