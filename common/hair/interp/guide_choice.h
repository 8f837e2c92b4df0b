#pragma once
// The guides an interpolated strand follows: the guides it may follow, its moving part,
// the barycentric or clump choice among the nearest guides, and its binding to those chosen.

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "hair/core/strand_set.h"
#include "hair/geom/point_index.h"
#include "hair/interp/strand_interpolation.h"

namespace hair {

/// The guides that strands can follow (strand guides, not wisp centres), their anchors
/// in a k-d tree, their directions at rest, and every guide's rest length.
struct FollowableGuides {
  std::vector<int32_t> usable;             ///< guide indices
  Points3f anchors;                        ///< per usable guide: its first particle
  std::vector<Eigen::Vector3d> direction;  ///< per usable guide: anchor to tip at rest, unit
  std::optional<PointIndex> index;         ///< of the anchors
  std::vector<double> guide_length_m;      ///< per guide: rest length from its anchor to its tip
};

/// The followable guides of `guides`. Throws Error::runtime for a guide of fewer than 2
/// particles.
FollowableGuides followable_guides(const InterpolationGuides& guides);

/// The moving part of one strand to interpolate (points held to bound_from): its anchor
/// (the last held point, or the root), its cluster (that of its first moving point) and
/// its arc length from the anchor.
struct MovingStrand {
  const StrandSet& strands;
  int64_t begin = 0, held = 0, bound_from = 0, anchor = 0;
  Eigen::Vector3d anchor_m = Eigen::Vector3d::Zero();
  int32_t cluster = 0;
  std::vector<double> arc;  ///< from the anchor, per point from it to the tip
  double length = 0;

  MovingStrand(const StrandSet& strands_in, int64_t s, int64_t held_in, int64_t bound_from_in,
               int32_t cluster_in);

  /// The arc parameter of point i along guides of rest length `guide_m`: a strand as long
  /// as they are or longer spans them (its tip follows theirs), a shorter one follows
  /// their first `length` metres (its tip follows the guide's point as far from the
  /// anchor). Spread over the whole guide, a strand a fifth its length would have each
  /// point follow a guide point five times as far out, and stretch as the guide bends.
  double parameter_along(int64_t i, double guide_m) const {
    const double span = std::max(length, guide_m);
    return span > 0 ? arc[static_cast<size_t>(i - anchor)] / span : 0.0;
  }

  /// Mean distance at rest from the moving points to guide g at the same arc parameter:
  /// the size of the offsets g would have to carry.
  double mean_offset_m(const InterpolationGuides& guides, const FollowableGuides& followable,
                       int32_t g) const;
};

/// The guides a strand follows and their weights.
struct GuideChoice {
  std::array<int32_t, 3> chosen = {-1, -1, -1};
  std::array<double, 3> weights = {1, 0, 0};
  bool barycentric = false;
};

/// Barycentric: the three nearest candidates (`nearest`, indices into followable.usable),
/// if they are of the strand's cluster, long enough, point alike and make no sliver;
/// else no choice (nullopt).
std::optional<GuideChoice> barycentric_choice(const MovingStrand& strand,
                                              const InterpolationGuides& guides,
                                              const FollowableGuides& followable,
                                              const std::vector<int32_t>& nearest,
                                              const InterpolationParams& params);

/// Clump: of the candidates `nearest`, the guide whose rest shape lies closest to the
/// strand's (the least mean offset: the nearest root alone can be a short guide that a
/// long strand would swing around): one of the strand's cluster long enough to follow;
/// else one long enough of another cluster simulated alike (`simulated_as`); else the best
/// of the cluster whatever its length; else the nearest guide of the cluster; else the
/// nearest guide.
GuideChoice clump_choice(const MovingStrand& strand, const InterpolationGuides& guides,
                         const FollowableGuides& followable, const std::vector<int32_t>& nearest,
                         int8_t simulated_as, const InterpolationParams& params);

/// Strand s follows `choice`: its method, guides and weights (normalised again in float,
/// so that they sum to 1 as the frames use them), and each moving point's arc parameter
/// and rest offset from the weighted guides there, along the guides' weighted length (one
/// parameter for the three guides of a barycentric strand).
void follow(const MovingStrand& strand, int64_t s, const GuideChoice& choice,
            const InterpolationGuides& guides, const FollowableGuides& followable,
            StrandBinding& binding);

}  // namespace hair
