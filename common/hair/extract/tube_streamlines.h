#pragma once
// Whether the streamlines traced along the paint of a tube (a patch of quads closed on
// itself across its rails) are hair. Two kinds of patch are meshed as tubes: braid pieces,
// whose strokes are painted round the piece (each lobe of a braid at its own slant), and
// shells wrapped over the head, whose quads need not run with the hair at all. On a braid
// piece the streamlines wind round and round the piece, many times longer than the piece
// is wide, or stop within a few faces at the lobes' turns; on a shell they run across it
// like combed hair. The first keeps its rails, the second is cut into strands along its
// paint like a cap.

#include <vector>

#include "hair/extract/painted_streamlines.h"

namespace hair {

struct TubeStreamlineLimits {
  /// The longest streamline at most this many times the patch's extent (the diagonal of
  /// its bounding box): longer ones wind round it.
  double max_extent_ratio = 3;
  /// The streamlines' mean length at least this share of the rails' mean length.
  double min_length_share = 0.5;
};

/// Whether `streamlines`, traced over a tube whose bounding box has the diagonal
/// `patch_extent_m` and whose rails are `rails_mean_length_m` long on average, are hair
/// by `limits`: none winds round the patch, and they are not much shorter than its rails.
/// False for no streamlines.
bool tube_streamlines_are_hair(const std::vector<PaintedStreamline>& streamlines,
                               double patch_extent_m, double rails_mean_length_m,
                               const TubeStreamlineLimits& limits);

}  // namespace hair
