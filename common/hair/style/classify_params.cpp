#include "hair/style/classify_params.h"

namespace hair {

void declare_decisive_rules_params(ParamSet& p, DecisiveStyleRules& rules) {
  p.add("decisive_rules", rules.enabled,
        "let the paper's criteria decide where they are decisive: hair lying on the "
        "scalp to its ends is short, a cap gathered into a band is fixed "
        "(docs/classify.md)");
  const auto share = ParamRange::closed(0.0, 1.0);
  const auto distance = ParamRange::closed(0.0, 10.0);
  p.add("short_far_scalp_distance_h", rules.short_far_scalp_distance_h,
        "short rule: the far particles (95th percentile) at most this far from the "
        "scalp, in H",
        distance);
  p.add("short_tip_share", rules.short_tip_share,
        "short rule: at least this share of the strands end in the cluster", share);
  p.add("short_gathering_ratio", rules.short_gathering_ratio,
        "short rule: the ends at least this spread (equation 6's ratio)", share);
  p.add("fixed_root_share", rules.fixed_root_share,
        "fixed rule: at least this share of the strands start at roots", share);
  p.add("fixed_gathering_ratio", rules.fixed_gathering_ratio,
        "fixed rule: the ends at most this spread (equation 6's ratio)", share);
  p.add("fixed_far_scalp_distance_h", rules.fixed_far_scalp_distance_h,
        "fixed rule: the far particles at most this far from the scalp, in H", distance);
  p.add("fixed_tip_share", rules.fixed_tip_share,
        "fixed rule: at most this share of the strands end in the cluster (the "
        "others go on past the band)",
        share);
  p.add("ungathered_root_share", rules.ungathered_root_share,
        "not fixed: at least this share of the strands start at roots, ...", share);
  p.add("ungathered_tip_share", rules.ungathered_tip_share,
        "not fixed: ... at least this share of them end in the cluster, ...", share);
  p.add("ungathered_gathering_ratio", rules.ungathered_gathering_ratio,
        "not fixed: ... and their ends at least this spread (equation 6's ratio): "
        "gathered into nothing, they are not fixed, and the classifier's best other "
        "style is taken",
        share);
}

void declare_classify_params(ParamSet& p, ClassifyStageParams& params) {
  p.add("classifier", params.classifier,
        "whose class is the style: svm (the better on real meshes held out, "
        "docs/classify.md) or random_forest (the paper's better one)",
        {"random_forest", "svm"});
  declare_decisive_rules_params(p, params.rules);
  p.add("unsure_below", params.unsure_below,
        "a cluster whose classifier is less sure of its style is unsure (styles.h5, the "
        "picture, the log): the SVM's margin, or the forest's share of votes",
        ParamRange::closed(0.0, 1.0));
}

void check_decisive_rules_params(const DecisiveStyleRules& rules) {
  check_params(rules, declare_decisive_rules_params);
}

}  // namespace hair
