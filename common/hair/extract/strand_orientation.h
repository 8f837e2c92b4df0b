#pragma once

#include <cstdint>
#include <optional>

namespace hair {

/// Which rule decided the root-to-tip direction of a strand group.
enum class OrientationRule : int8_t {
  vertex_order = 0,    ///< vertex ids grow from root to tip (the paper's assumption, sec. 3)
  scalp_distance = 1,  ///< the end nearer the head surface is the root
  continuation = 2,    ///< other patches' strands start where these end (or end where these start)
  uv = 3,              ///< the texture's v runs root to tip as on the mesh's other patches
  height = 4,          ///< the higher end is the root (hair falls)
  parting = 5,         ///< rails draped over the head or looped: the top is the root
  alpha_fade = 6,      ///< the painted alpha fades out towards the tip
};

/// The rule's name as extract.h5 stores it ("vertex_order", ...).
const char* orientation_rule_name(OrientationRule rule);

/// What a region of rails (consistently oriented chains of one patch) says about its
/// direction, for the chains as they are. Positive values favour keeping them.
struct OrientationEvidence {
  /// Length-weighted vote of the ordered rails (rails whose vertex ids grow, or fall,
  /// in most steps): (grow - fall) / (grow + fall), in [-1, 1]; 0 without ordered rails.
  double vertex_order_vote = 0;
  bool has_ordered_rails = false;
  /// sum over rails of (head distance at the last point - at the first) / sum of lengths.
  double scalp_distance_slope = 0;
  /// Mean signed growth of texture v along the rails, per unit of texture motion, in
  /// [-1, 1]; nullopt without texture coordinates.
  std::optional<double> uv_growth = std::nullopt;
  /// sum over rails of (height of the first point - height of the last) / sum of lengths.
  double height_slope = 0;
  /// How the painted alpha fades along the rails, in [-1, 1] (positive: it falls from
  /// their first points to their last, so the tips lie last); nullopt without clear paint.
  std::optional<double> alpha_fade_vote = std::nullopt;
  /// Mean magnitude of the alpha's fall per face along the rails (0 to 1).
  double alpha_fade_mean_fall = 0;
  /// Mean magnitude of the alpha's fall along a whole rail (0 to 1): how much it fades
  /// from one end of the hair to the other, whatever the faces' number.
  double alpha_fade_rail_fall = 0;
  /// Smallest distance of a rail end from the head, in metres: hair lying on the head
  /// (a cap, short hair brushed up) may rise from its root; hair off the head falls.
  double head_distance_min_m = 0;
};

/// Thresholds of the decision; see decide_orientation().
struct OrientationThresholds {
  double vertex_order_min_vote = 0.8;     ///< |vote| for the ordered rails to agree (90%)
  double scalp_distance_min_slope = 0.2;  ///< |slope| for the head distance to decide
  /// |slope| for the head distance to lean: with a decisive height slope the same way,
  /// it overrules vertex ids (see decide_orientation(), step 1)
  double scalp_distance_lean_slope = 0.05;
  double uv_min_growth = 0.3;             ///< |uv growth| for the texture to decide
  double height_min_slope = 0.3;          ///< |height slope| to settle ids against head distance...
  double height_min_head_distance_m = 0;  ///< ...for hair at least this far off the head
  double alpha_fade_min_fall = 0.05;      ///< mean alpha fall per face for the fade to decide...
  double alpha_fade_min_rail_fall = 0.3;  ///< ...or along a whole rail...
  double alpha_fade_min_vote = 0.6;       ///< ...when this much of it falls one way
};

/// What the rest of the mesh says, learnt from its confidently decided regions.
struct MeshConventions {
  bool trust_vertex_order = true;     ///< false when geometry contradicts the ids mostly
  std::optional<int> uv_growth_sign;  ///< sign of v growth from root to tip, if consistent
};

struct OrientationDecision {
  bool reverse = false;  ///< reverse the chains so that they run root to tip
  OrientationRule rule = OrientationRule::height;
  float confidence = 0;  ///< in [0, 1]
};

/// Whether the painted alpha's fade decides root from tip: 60% of its fall one way
/// (`alpha_fade_min_vote`), and a mean fall of `alpha_fade_min_fall` per face crossed or,
/// if `whole_rails_count`, of `alpha_fade_min_rail_fall` along a whole rail (a tube or a
/// finely cut card fades by little per face however clearly its paint fades to the tips).
/// The fade alone (rule 3b below) asks the fall per face; where the texture's v convention
/// backs it (paint over vertex ids, region_orientation.cpp), the fall along the rail is enough.
bool alpha_fade_decides(const OrientationEvidence& evidence,
                        const OrientationThresholds& thresholds, bool whole_rails_count);

/// Decides a region's direction (DESIGN: "check vertex order per patch, fall back on
/// geometry where it is inconsistent"):
///  1. ordered rails that agree decide (vertex_order), unless the head distance decides
///     the other way, or the mesh's ids are not to be trusted; when the two disagree off
///     the head, a decisive height slope settles it (hair falls; a braid's pieces weave toward and
///     away from the head as they cross, so there the head distance misleads); where the
///     head distance does not decide but leans (`scalp_distance_lean_slope`) the way a
///     decisive height slope goes, against the ids, the height decides (hair lying down
///     the side of the head, numbered tip to root);
///  2. else a decisive head-distance slope decides (scalp_distance);
///  3. (continuation is decided between passes, from the neighbours: see continuation.cpp)
///  3b. else a decisive fade of the painted alpha: the tips are where it fades (alpha_fade);
///     after continuation, because a patch's paint may fade towards where it meets the
///     next patch (a cap's cards into a ponytail's band) rather than towards the tips;
///  4. else the texture's v growth, if the mesh has a consistent convention (uv);
///  5. else the higher end is the root (height).
/// Without `conventions` (the first pass, which learns them) steps 3b, 4 and 5 return
/// nullopt.
std::optional<OrientationDecision> decide_orientation(
    const OrientationEvidence& evidence, const OrientationThresholds& thresholds,
    const std::optional<MeshConventions>& conventions);

}  // namespace hair
