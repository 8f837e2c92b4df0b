#pragma once
// How simulated guides keep their groom: each guide's tip drift in the head's frame (a
// still head's hair should not move), and whether a guide flips over its root.

#include <vector>

#include "hair/sim/guides_io.h"

namespace hair {

/// Per guide, over the frames: where its tip went against its rest place, in the head's
/// frame (the head's own motion taken out), as a share of the guide's length.
struct GuideDrift {
  double length_m = 0;
  double final_share = 0;    ///< at the last frame
  double largest_share = 0;  ///< the most over the frames
  /// The guide's first segment turned by more than 90 degrees from its rest direction
  /// (in the head's frame) at some frame: it flipped over its root.
  bool flipped = false;
};

/// The drift of every guide of `guides` (frame 0 is the rest state).
std::vector<GuideDrift> guide_drift(const SimulatedGuides& guides);

/// Mean, 95th percentile and largest of the guides' drift at the last frame (shares of
/// length), the largest over all frames, and the guides that flipped.
struct DriftSummary {
  double mean = 0, p95 = 0, largest = 0, largest_any_frame = 0;
  int64_t guides = 0, flipped = 0;
};
DriftSummary summarise_drift(const std::vector<GuideDrift>& drift);

/// How a bundle of guides (a tail) holds together: per frame, the spread of their points
/// at `fraction` of their length (root mean square distance from their mean, in the
/// head's frame) over that at rest. Only the guides at least half as long as the
/// cluster's median guide count: a stub of the cluster that ends by the scalp is not in
/// the tail, and its point, far from the tail's, would swell the rest spread and so hide
/// the tail's fanning out (a few stubs of a few centimetres by the nape swell a tail's
/// rest spread by half).
struct BundleSpread {
  int32_t cluster = -1;
  int64_t guides = 0;
  double rest_spread_m = 0;
  std::vector<double> ratio;  ///< per frame
  double median = 0, largest = 0;
};

/// The spread of the guides of `cluster` (-1: the simulated cluster with the most guides)
/// at `fraction` of their length.
BundleSpread bundle_spread(const SimulatedGuides& guides, int32_t cluster = -1,
                           double fraction = 0.75);

}  // namespace hair
