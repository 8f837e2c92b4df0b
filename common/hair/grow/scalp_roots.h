#pragma once
// Where grown strands start: the scalp that carries their roots, the roots sampled on it
// with their reference strands, the seeds of their clusters' fields besides the input
// strands, and the way a strand that cannot leave its root lies.

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <vector>

#include "hair/core/strand_set.h"
#include "hair/grow/growing_context.h"
#include "hair/grow/strand_growing.h"
#include "hair/grow/surface_sampling.h"

namespace hair {

/// The scalp that carries roots, and the context the strands grow with.
struct RootingScalp {
  std::unique_ptr<GrowingContext> context;
  std::vector<uint8_t> covered;  ///< per body triangle: it carries roots
  /// As GrowResult::typed_root_scalp_share.
  double typed_root_scalp_share = 1.0;
};

/// The scalp triangles under the root-carrying strands (scalp_cover_h, standing_cover_h),
/// with their context; where there is no root-type group, or where root-type strands cover
/// less than min_typed_root_scalp_share of the scalp that strands of any type cover, roots
/// take any input strand (a warning says so).
RootingScalp rooting_scalp(const GrowInput& input, const GrowParams& params);

/// The seeds under hair that lies off the head (GrowParams::field_shell_seeds,
/// shell_field_seeds.h), with strand attribute "cluster" (int32), that of the strand each
/// lies under; the scalp under them is flagged in `covered`. Empty when field_shell_seeds
/// is off.
StrandSet seeds_under_shells(const GrowInput& input, const GrowingContext& context,
                             const GrowParams& params, std::vector<uint8_t>& covered);

/// The roots: blue noise over the `covered` scalp triangles (`covered_count` of them);
/// within a covered triangle, a root beside a standing strand lies within
/// standing_cover_h of it along the scalp. Throws hair::Error (bad_input) where no
/// triangle is covered.
SurfaceSamples sample_roots(const GrowInput& input, const GrowingContext& context,
                            const GrowParams& params, const std::vector<uint8_t>& covered,
                            int64_t covered_count);

/// Per root, its reference input-strand point (GrowingContext::reference_row()) and the
/// cluster of that point's strand, the root's cluster.
struct RootReferences {
  std::vector<int64_t> row;
  std::vector<int32_t> cluster;
};
/// RootReferences of the roots at `root_positions` (#roots x 3).
RootReferences root_references(const GrowingContext& context, const Points3f& root_positions);

/// The seeds the painted faces give the fields (GrowParams::field_paint_seeds): of the
/// groups whose strands seed them, sampled at half a voxel's edge, so that a
/// face adds to each voxel it covers about what a strand through it does.
StrandSet field_paint_seeds(const GrowInput& input, const GrowingContext& context,
                            const GrowParams& params);

/// The way a strand that cannot leave its `root` takes its one step: along the hair there
/// (the input strand of the root's reference point `reference_row`, less any part into the
/// scalp of unit outward `normal`), turned onto the painted flow near the root.
Eigen::Vector3d stub_step_direction(const GrowingContext& context, int64_t reference_row,
                                    const Eigen::Vector3d& normal, const Eigen::Vector3d& root);

}  // namespace hair
