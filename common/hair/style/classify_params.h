#pragma once

#include <string>

#include "hair/core/params.h"
#include "hair/style/cluster_styles.h"
#include "hair/style/decisive_style_rules.h"

namespace hair {

/// The classify stage's settings: whose class is the style, the paper's criteria where
/// they decide, and the confidence under which a cluster is unsure.
struct ClassifyStageParams {
  std::string classifier = "svm";  ///< "svm" or "random_forest"
  DecisiveStyleRules rules;
  double unsure_below = kDefaultUnsureBelow;
};

/// Registers the decisive rules' parameters with their descriptions and ranges.
void declare_decisive_rules_params(ParamSet& p, DecisiveStyleRules& rules);

/// Registers every classify parameter with its description and range, bound to `params`.
void declare_classify_params(ParamSet& p, ClassifyStageParams& params);

/// Holds `rules` to the ranges declare_decisive_rules_params() gives them
/// (check_params()); cluster_styles() calls it. Throws hair::Error (usage).
void check_decisive_rules_params(const DecisiveStyleRules& rules);

}  // namespace hair
