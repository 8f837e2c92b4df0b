#include "hair/extract/strand_orientation.h"

#include <algorithm>
#include <cmath>

namespace hair {

const char* orientation_rule_name(OrientationRule rule) {
  switch (rule) {
    case OrientationRule::vertex_order:
      return "vertex_order";
    case OrientationRule::scalp_distance:
      return "scalp_distance";
    case OrientationRule::continuation:
      return "continuation";
    case OrientationRule::uv:
      return "uv";
    case OrientationRule::height:
      return "height";
    case OrientationRule::parting:
      return "parting";
    case OrientationRule::alpha_fade:
      return "alpha_fade";
  }
  return "unknown";
}

bool alpha_fade_decides(const OrientationEvidence& evidence,
                        const OrientationThresholds& thresholds, bool whole_rails_count) {
  const bool falls_enough =
      evidence.alpha_fade_mean_fall >= thresholds.alpha_fade_min_fall ||
      (whole_rails_count && evidence.alpha_fade_rail_fall >= thresholds.alpha_fade_min_rail_fall);
  return evidence.alpha_fade_vote && falls_enough &&
         std::abs(*evidence.alpha_fade_vote) >= thresholds.alpha_fade_min_vote;
}

std::optional<OrientationDecision> decide_orientation(
    const OrientationEvidence& evidence, const OrientationThresholds& thresholds,
    const std::optional<MeshConventions>& conventions) {
  bool trust_ids = !conventions || conventions->trust_vertex_order;
  bool ids_agree = evidence.has_ordered_rails &&
                   std::abs(evidence.vertex_order_vote) >= thresholds.vertex_order_min_vote;
  bool distance_decides =
      std::abs(evidence.scalp_distance_slope) >= thresholds.scalp_distance_min_slope;
  bool distance_reverse = evidence.scalp_distance_slope < 0;
  auto clamp01 = [](double x) { return static_cast<float>(std::clamp(x, 0.0, 1.0)); };

  if (ids_agree && trust_ids) {
    bool ids_reverse = evidence.vertex_order_vote < 0;
    // Ids against the head distance's leaning and the height both: hair lying along
    // the head from its root (medium hair down the side), numbered tip to root, nears
    // the head by too little to decide alone, but its root is also the higher end.
    bool height_decides = std::abs(evidence.height_slope) >= thresholds.height_min_slope;
    bool height_reverse = evidence.height_slope < 0;
    if (!distance_decides && height_decides && height_reverse != ids_reverse &&
        std::abs(evidence.scalp_distance_slope) >= thresholds.scalp_distance_lean_slope &&
        distance_reverse == height_reverse)
      return OrientationDecision{height_reverse, OrientationRule::height,
                                 clamp01(std::abs(evidence.height_slope))};
    if (!distance_decides || distance_reverse == ids_reverse) {
      float agreement = clamp01((1 + std::abs(evidence.vertex_order_vote)) / 2);
      return OrientationDecision{ids_reverse, OrientationRule::vertex_order,
                                 distance_decides ? agreement : 0.75f * agreement};
    }
    if (height_decides && evidence.head_distance_min_m >= thresholds.height_min_head_distance_m) {
      return OrientationDecision{height_reverse,
                                 height_reverse == ids_reverse ? OrientationRule::vertex_order
                                                               : OrientationRule::scalp_distance,
                                 clamp01(std::abs(evidence.height_slope))};
    }
  }
  if (distance_decides)
    return OrientationDecision{distance_reverse, OrientationRule::scalp_distance,
                               clamp01(std::abs(evidence.scalp_distance_slope) /
                                       (2 * thresholds.scalp_distance_min_slope))};
  if (!conventions) return std::nullopt;
  if (alpha_fade_decides(evidence, thresholds, false))
    return OrientationDecision{*evidence.alpha_fade_vote < 0, OrientationRule::alpha_fade,
                               clamp01(std::abs(*evidence.alpha_fade_vote))};
  if (conventions->uv_growth_sign && evidence.uv_growth &&
      std::abs(*evidence.uv_growth) >= thresholds.uv_min_growth) {
    bool reverse = (*evidence.uv_growth > 0 ? 1 : -1) != *conventions->uv_growth_sign;
    return OrientationDecision{reverse, OrientationRule::uv,
                               clamp01(std::abs(*evidence.uv_growth))};
  }
  return OrientationDecision{evidence.height_slope < 0, OrientationRule::height,
                             clamp01(std::abs(evidence.height_slope))};
}

}  // namespace hair
