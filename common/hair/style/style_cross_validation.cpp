#include "hair/style/style_cross_validation.h"

#include <algorithm>
#include <string>

#include "hair/core/error.h"
#include "hair/style/feature_standardization.h"
#include "hair/style/puk_svm.h"
#include "hair/style/random_forest.h"
#include "hair/style/stratified_folds.h"

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
    Eigen::MatrixXd train_features = features(train, Eigen::all);
    std::vector<int32_t> train_labels;
    for (Eigen::Index row : train) train_labels.push_back(labels[static_cast<size_t>(row)]);

    FeatureStandardization standardization = feature_standardization(train_features);
    FloatRows train_rows = standardized_rows(standardization, train_features);
    FloatRows test_rows = standardized_rows(standardization, features(test, Eigen::all));

    PukSvmSelection choice = selected_puk_svm_params(train_rows, train_labels, params.svm_grid,
                                                     params.inner_folds, params.seed + 1 + fold);
    PukSvm svm = trained_puk_svm(train_rows, train_labels, choice.params);
    cv::Ptr<cv::ml::RTrees> forest = trained_random_forest(train_rows, train_labels, params.forest);
    std::vector<int32_t> forest_classes = train_labels;
    std::sort(forest_classes.begin(), forest_classes.end());
    forest_classes.erase(std::unique(forest_classes.begin(), forest_classes.end()),
                         forest_classes.end());
    for (size_t i = 0; i < test.size(); ++i) {
      const float* row = test_rows.row(static_cast<Eigen::Index>(i)).data();
      auto target = static_cast<size_t>(test[i]);
      result.svm_predicted[target] = svm_prediction(svm, row).label;
      result.forest_predicted[target] =
          forest_prediction(*forest, forest_classes, row, static_cast<int>(features.cols())).label;
    }
    result.svm_choice.push_back(choice);
    result.fold_rows.push_back(static_cast<int>(test.size()));
  }
  result.svm = classification_scores(labels, result.svm_predicted, result.class_labels, subset);
  result.forest =
      classification_scores(labels, result.forest_predicted, result.class_labels, subset);
  return result;
}

}  // namespace hair
