#include "hair/style/decisive_style_rules.h"

#include <algorithm>

#include "hair/core/error.h"

namespace hair {
namespace {

const std::vector<std::string>& rule_feature_names() {
  static const std::vector<std::string> names = {"far_scalp_distance_h", "tip_share",
                                                 "gathering_ratio", "root_share"};
  return names;
}

}  // namespace

std::optional<HairStyle> decisive_style(const PaperFeatures& features,
                                        const DecisiveStyleRules& rules) {
  if (!rules.enabled) return std::nullopt;
  if (features.far_scalp_distance_h <= rules.short_far_scalp_distance_h &&
      features.tip_share >= rules.short_tip_share &&
      features.gathering_ratio >= rules.short_gathering_ratio)
    return HairStyle::short_hair;
  if (features.root_share >= rules.fixed_root_share &&
      features.gathering_ratio <= rules.fixed_gathering_ratio &&
      features.far_scalp_distance_h <= rules.fixed_far_scalp_distance_h &&
      features.tip_share <= rules.fixed_tip_share)
    return HairStyle::fixed;
  return std::nullopt;
}

bool fixed_ruled_out(const PaperFeatures& features, const DecisiveStyleRules& rules) {
  return rules.enabled && features.root_share >= rules.ungathered_root_share &&
         features.tip_share >= rules.ungathered_tip_share &&
         features.gathering_ratio >= rules.ungathered_gathering_ratio;
}

bool has_decisive_rule_features(const std::vector<std::string>& names) {
  return std::all_of(rule_feature_names().begin(), rule_feature_names().end(),
                     [&](const std::string& name) {
                       return std::find(names.begin(), names.end(), name) != names.end();
                     });
}

namespace {

/// The features the rules read, of every row of a table whose columns are `names`.
std::vector<PaperFeatures> rule_features_of_rows(const Eigen::MatrixXd& rows,
                                                 const std::vector<std::string>& names) {
  auto column = [&](const std::string& name) {
    auto found = std::find(names.begin(), names.end(), name);
    if (found == names.end())
      throw Error::usage("decisive style rules: the features have no column " + name);
    return static_cast<Eigen::Index>(found - names.begin());
  };
  Eigen::Index far = column("far_scalp_distance_h"), tip = column("tip_share"),
               gathering = column("gathering_ratio"), root = column("root_share");
  std::vector<PaperFeatures> result(static_cast<size_t>(rows.rows()));
  for (Eigen::Index r = 0; r < rows.rows(); ++r) {
    PaperFeatures& features = result[static_cast<size_t>(r)];
    features.far_scalp_distance_h = rows(r, far);
    features.tip_share = rows(r, tip);
    features.gathering_ratio = rows(r, gathering);
    features.root_share = rows(r, root);
  }
  return result;
}

}  // namespace

std::vector<int32_t> decisive_styles_of_rows(const Eigen::MatrixXd& rows,
                                             const std::vector<std::string>& names,
                                             const DecisiveStyleRules& rules) {
  std::vector<int32_t> decided(static_cast<size_t>(rows.rows()), -1);
  const std::vector<PaperFeatures> features = rule_features_of_rows(rows, names);
  for (size_t r = 0; r < features.size(); ++r)
    if (std::optional<HairStyle> style = decisive_style(features[r], rules))
      decided[r] = static_cast<int32_t>(*style);
  return decided;
}

std::vector<uint8_t> fixed_ruled_out_of_rows(const Eigen::MatrixXd& rows,
                                             const std::vector<std::string>& names,
                                             const DecisiveStyleRules& rules) {
  std::vector<uint8_t> ruled_out(static_cast<size_t>(rows.rows()), 0);
  const std::vector<PaperFeatures> features = rule_features_of_rows(rows, names);
  for (size_t r = 0; r < features.size(); ++r)
    ruled_out[r] = fixed_ruled_out(features[r], rules) ? 1 : 0;
  return ruled_out;
}

}  // namespace hair
