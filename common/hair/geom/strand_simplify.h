#pragma once
// Fewer points where the shape does not need them: each strand kept within a distance
// of itself (Douglas-Peucker), so a straight strand keeps its two ends and a curl the
// points of its bends. hair-export uses it (--tolerance_m).

#include <cstdint>
#include <vector>

#include "hair/core/strand_set.h"

namespace hair {

/// The rows of `strands.points` that keep every strand within `tolerance_m` of itself:
/// its root and tip, and between them the points the Douglas-Peucker recursion needs so
/// that each dropped point lies within tolerance_m of the segment joining the kept points
/// on either side of it. Ascending. tolerance_m = 0 keeps every point but those exactly on
/// the segment between their neighbours. Throws hair::Error (usage) for a negative or
/// non-finite tolerance.
std::vector<int64_t> rows_within_tolerance(const StrandSet& strands, double tolerance_m);

/// The largest distance of a point of `points` (a strand set's points, or a frame of
/// them) from the segment joining the kept rows `rows` (from rows_within_tolerance()) on
/// either side of it, metres: the error of drawing the strands by the kept points alone.
/// 0 where every row is kept.
double largest_deviation(const Points3f& points, const std::vector<int64_t>& rows);

/// The rows `rows` of `points` (ascending), in order.
Points3f select_rows(const Points3f& points, const std::vector<int64_t>& rows);

/// `strands` with only the point rows `rows` (from rows_within_tolerance(): ascending, every
/// strand's root and tip among them): per-point attributes keep the kept points' values,
/// strand attributes are copied.
StrandSet select_points(const StrandSet& strands, const std::vector<int64_t>& rows);

}  // namespace hair
