#include "hair/extract/tube_streamlines.h"

#include <algorithm>

namespace hair {
namespace {

double length_of(const Points3f& points) {
  double length_m = 0;
  for (Eigen::Index i = 1; i < points.rows(); ++i)
    length_m += (points.row(i) - points.row(i - 1)).cast<double>().norm();
  return length_m;
}

}  // namespace

bool tube_streamlines_are_hair(const std::vector<PaintedStreamline>& streamlines,
                               double patch_extent_m, double rails_mean_length_m,
                               const TubeStreamlineLimits& limits) {
  if (streamlines.empty()) return false;
  double total_m = 0, longest_m = 0;
  for (const PaintedStreamline& streamline : streamlines) {
    const double length_m = length_of(streamline.points);
    total_m += length_m;
    longest_m = std::max(longest_m, length_m);
  }
  const double mean_m = total_m / static_cast<double>(streamlines.size());
  return longest_m <= limits.max_extent_ratio * patch_extent_m &&
         mean_m >= limits.min_length_share * rails_mean_length_m;
}

}  // namespace hair
