#pragma once

#include <vector>

#include "hair/core/strand_set.h"

namespace hair {

/// Arc length of each strand: the sum of its segment lengths, metres.
///   @param[in] strands  S strands with valid offsets
///   @return #strands lengths; 0 for a strand of fewer than 2 points
std::vector<float> strand_lengths(const StrandSet& strands);

/// Unit tangent at every point, pointing from root to tip: the direction of the first
/// segment at the root, of the last segment at the tip, and the normalised sum of the
/// two adjacent segment directions inside. A zero-length segment takes the direction of
/// the nearest earlier segment of non-zero length (of the first one if none is earlier);
/// where the two directions cancel (a hairpin) the incoming one is used. A strand whose
/// points all coincide, or with a single point, gets zero tangents (never NaN).
///   @param[in] strands  S strands with valid offsets
///   @return #points x 3 tangents, rows aligned with strands.points
Points3f strand_tangents(const StrandSet& strands);

/// Every strand resampled to `points_per_strand` points spaced uniformly along its arc
/// length; the root and the tip are kept exactly.
///
/// Attributes are carried over: strand attributes are copied, per-point float and
/// Points3f attributes are interpolated linearly along the arc length, and per-point int
/// attributes take the value of the nearest original point (the root-side one at a tie).
/// A strand whose points all coincide gives coincident points. Throws hair::Error if
/// `strands` fails check_strand_set(strands, 1) (runtime) or points_per_strand < 2 (usage).
/// Deterministic whatever the number of OpenMP threads.
///   @param[in] strands  S strands, N points
///   @return S strands, S * points_per_strand points
StrandSet resample_by_count(const StrandSet& strands, int points_per_strand);

/// Every strand resampled uniformly along its arc length with max(2, ceil(L / spacing_m) + 1)
/// points, so that consecutive points are at most spacing_m apart along the strand (L: the
/// strand's length; a ratio L / spacing_m within a relative 1e-6 of a whole number counts
/// as that number, so float rounding does not add a point). Root and tip are kept exactly;
/// attributes are carried over as in resample_by_count. Throws hair::Error (usage) if
/// spacing_m is not positive and finite, or would give a strand over 1e9 points.
///   @param[in] strands    S strands, N points
///   @param[in] spacing_m  largest distance between consecutive points along a strand, metres
///   @return S strands
StrandSet resample_by_spacing(const StrandSet& strands, float spacing_m);

}  // namespace hair
