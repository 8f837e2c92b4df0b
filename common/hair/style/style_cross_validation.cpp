#include "hair/style/style_cross_validation.h"

#include <algorithm>
#include <string>

#include "hair/core/error.h"
#include "hair/style/stratified_folds.h"
#include "hair/style/style_held_out_prediction.h"

namespace hair {

StyleCrossValidation style_cross_validation(const Eigen::MatrixXd& features,
                                            std::span<const int32_t> labels,
                                            const std::vector<bool>& subset,
                                            const StyleClassifierParams& params,
                                            std::span<const int32_t> fold_of_row) {
  params.check();
  if (static_cast<size_t>(features.rows()) != labels.size() ||
      (!subset.empty() && subset.size() != labels.size()))
    throw Error::usage("style cross-validation: " + std::to_string(features.rows()) +
                       " feature rows, " + std::to_string(labels.size()) + " labels and " +
                       std::to_string(subset.size()) + " subset flags");
  check_finite_features(features);

  StyleCrossValidation result;
  result.folds = params.folds;
  result.class_labels.assign(labels.begin(), labels.end());
  std::sort(result.class_labels.begin(), result.class_labels.end());
  result.class_labels.erase(std::unique(result.class_labels.begin(), result.class_labels.end()),
                            result.class_labels.end());
  if (fold_of_row.empty()) {
    result.fold = stratified_folds(labels, params.folds, params.seed);
  } else {
    if (fold_of_row.size() != labels.size())
      throw Error::usage("style cross-validation: " + std::to_string(fold_of_row.size()) +
                         " folds for " + std::to_string(labels.size()) + " rows");
    for (int32_t fold : fold_of_row)
      if (fold < 0 || fold >= params.folds)
        throw Error::usage("style cross-validation: fold " + std::to_string(fold) + " outside 0.." +
                           std::to_string(params.folds - 1));
    result.fold.assign(fold_of_row.begin(), fold_of_row.end());
    result.given_folds = true;
  }
  result.svm_predicted.assign(labels.size(), 0);
  result.forest_predicted.assign(labels.size(), 0);

  for (int32_t fold = 0; fold < params.folds; ++fold) {
    std::vector<Eigen::Index> train = fold_row_indices(result.fold, fold, false);
    std::vector<Eigen::Index> test = fold_row_indices(result.fold, fold, true);
    HeldOutPrediction prediction =
        held_out_prediction(features, labels, train, test, params, params.seed + 1 + fold);
    for (size_t i = 0; i < test.size(); ++i) {
      auto target = static_cast<size_t>(test[i]);
      result.svm_predicted[target] = prediction.svm[i];
      result.forest_predicted[target] = prediction.forest[i];
    }
    result.svm_choice.push_back(prediction.svm_choice);
    result.fold_rows.push_back(static_cast<int>(test.size()));
  }
  result.svm = classification_scores(labels, result.svm_predicted, result.class_labels, subset);
  result.forest =
      classification_scores(labels, result.forest_predicted, result.class_labels, subset);
  return result;
}

}  // namespace hair
