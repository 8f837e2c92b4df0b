#include "hair/style/cluster_styles.h"

#include <algorithm>

#include "hair/core/error.h"
#include "hair/style/classify_params.h"
#include "hair/style/hair_style.h"
#include "hair/style/puk_svm.h"
#include "hair/style/random_forest.h"

namespace hair {

double svm_margin_confidence_without(const PukSvm& svm, std::span<const double> decision_values,
                                     size_t chosen, size_t excluded) {
  if (decision_values.size() != svm.decision_functions.size())
    throw Error::usage("svm margin confidence: " + std::to_string(decision_values.size()) +
                       " decision values for " + std::to_string(svm.decision_functions.size()) +
                       " decision functions");
  double smallest = 1.0;  // one class: nothing to lose
  for (size_t p = 0; p < decision_values.size(); ++p) {
    const SvmDecisionFunction& function = svm.decision_functions[p];
    const auto first = static_cast<size_t>(function.first);
    const auto second = static_cast<size_t>(function.second);
    if (first == excluded || second == excluded) continue;
    if (first == chosen)
      smallest = std::min(smallest, decision_values[p]);
    else if (second == chosen)
      smallest = std::min(smallest, -decision_values[p]);
  }
  return std::clamp(smallest, 0.0, 1.0);
}

double svm_margin_confidence(const PukSvm& svm, std::span<const double> decision_values,
                             size_t chosen) {
  // No class index is svm.class_labels.size(): every contest counts.
  return svm_margin_confidence_without(svm, decision_values, chosen, svm.class_labels.size());
}

ClusterStyles cluster_styles(const StyleFeatures& features, const StyleModel& model,
                             StyleClassifierKind classifier, const DecisiveStyleRules& rules) {
  check_decisive_rules_params(rules);
  const Eigen::MatrixXd& rows = feature_set_rows(features, model.feature_set);
  if (model.feature_names != feature_set_names(model.feature_set))
    throw Error::usage("the style model's '" + model.feature_set +
                       "' features are not the ones classify measures under that name");
  const auto cluster_count = static_cast<Eigen::Index>(features.strand_count.size());
  const auto class_count = static_cast<Eigen::Index>(model.class_labels.size());
  ClusterStyles result;
  result.classifier = classifier;
  result.classes = model.class_labels;
  result.style.assign(static_cast<size_t>(cluster_count), -1);
  result.svm_style = result.style;
  result.forest_style = result.style;
  result.svm_decision_values =
      Eigen::MatrixXd::Zero(cluster_count, class_count * (class_count - 1) / 2);
  result.svm_votes = Eigen::MatrixXi::Zero(cluster_count, class_count);
  result.forest_vote_fraction = Eigen::MatrixXd::Zero(cluster_count, class_count);
  result.confidence.assign(static_cast<size_t>(cluster_count), 0.0);
  result.pinned.assign(static_cast<size_t>(cluster_count), 0);
  result.ruled.assign(static_cast<size_t>(cluster_count), 0);
  result.fixed_ruled_out.assign(static_cast<size_t>(cluster_count), 0);
  const auto fixed = static_cast<int32_t>(HairStyle::fixed);
  auto svm_index = [&](int32_t label) {
    return static_cast<size_t>(
        std::find(model.svm.class_labels.begin(), model.svm.class_labels.end(), label) -
        model.svm.class_labels.begin());
  };
  for (Eigen::Index c = 0; c < cluster_count; ++c) {
    if (features.strand_count[static_cast<size_t>(c)] == 0) continue;
    Eigen::RowVectorXd row = rows.row(c);
    StylePrediction prediction =
        style_prediction(model, std::span<const double>(row.data(), row.size()));
    auto i = static_cast<size_t>(c);
    result.svm_style[i] = static_cast<int8_t>(prediction.svm_label);
    result.forest_style[i] = static_cast<int8_t>(prediction.forest_label);
    const bool not_fixed = fixed_ruled_out(features.paper[i], rules);
    result.fixed_ruled_out[i] = not_fixed ? 1 : 0;
    int32_t chosen_label =
        classifier == StyleClassifierKind::svm ? prediction.svm_label : prediction.forest_label;
    if (not_fixed && chosen_label == fixed)
      chosen_label =
          classifier == StyleClassifierKind::svm
              ? svm_label_without(model.svm, prediction.svm_decision_values, fixed)
              : forest_label_without(model.class_labels, prediction.forest_vote_fraction, fixed);
    result.style[i] = static_cast<int8_t>(chosen_label);
    for (Eigen::Index p = 0; p < result.svm_decision_values.cols(); ++p)
      result.svm_decision_values(c, p) = prediction.svm_decision_values[static_cast<size_t>(p)];
    for (Eigen::Index k = 0; k < class_count; ++k) {
      result.svm_votes(c, k) = prediction.svm_votes[static_cast<size_t>(k)];
      result.forest_vote_fraction(c, k) = prediction.forest_vote_fraction[static_cast<size_t>(k)];
    }
    const auto chosen = static_cast<Eigen::Index>(
        std::find(model.class_labels.begin(), model.class_labels.end(), result.style[i]) -
        model.class_labels.begin());
    if (chosen < class_count)
      result.confidence[i] =
          classifier == StyleClassifierKind::svm
              ? svm_margin_confidence_without(
                    model.svm, prediction.svm_decision_values, svm_index(result.style[i]),
                    not_fixed ? svm_index(fixed) : model.svm.class_labels.size())
              : result.forest_vote_fraction(c, chosen);
    if (std::optional<HairStyle> decided = decisive_style(features.paper[i], rules)) {
      result.style[i] = static_cast<int8_t>(*decided);
      result.confidence[i] = 1.0;
      result.ruled[i] = 1;
    }
  }
  return result;
}

}  // namespace hair
