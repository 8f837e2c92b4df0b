#include "hair/style/style_held_out_prediction.h"

#include <algorithm>

#include "hair/core/error.h"
#include "hair/style/feature_standardization.h"
#include "hair/style/hair_style.h"
#include "hair/style/puk_svm.h"
#include "hair/style/random_forest.h"

namespace hair {

HeldOutPrediction held_out_prediction(const Eigen::MatrixXd& features,
                                      std::span<const int32_t> labels,
                                      const std::vector<Eigen::Index>& train,
                                      const std::vector<Eigen::Index>& test,
                                      const StyleClassifierParams& params, uint64_t grid_seed,
                                      std::span<const uint8_t> fixed_ruled_out) {
  if (train.empty()) throw Error::usage("held-out prediction: no training rows");
  if (!fixed_ruled_out.empty() && fixed_ruled_out.size() != static_cast<size_t>(features.rows()))
    throw Error::usage("held-out prediction: " + std::to_string(fixed_ruled_out.size()) +
                       " fixed-ruled-out flags for " + std::to_string(features.rows()) + " rows");
  Eigen::MatrixXd train_features = features(train, Eigen::all);
  std::vector<int32_t> train_labels;
  for (Eigen::Index row : train) train_labels.push_back(labels[static_cast<size_t>(row)]);

  FeatureStandardization standardization =
      feature_standardization(train_features, params.feature_log_offsets);
  FloatRows train_rows = standardized_rows(standardization, train_features);
  FloatRows test_rows = standardized_rows(standardization, features(test, Eigen::all));

  HeldOutPrediction result;
  result.svm_choice = selected_puk_svm_params(train_rows, train_labels, params.svm_grid,
                                              params.inner_folds, grid_seed);
  PukSvm svm = trained_puk_svm(train_rows, train_labels, result.svm_choice.params);
  cv::Ptr<cv::ml::RTrees> forest = trained_random_forest(train_rows, train_labels, params.forest);
  std::vector<int32_t> forest_classes = train_labels;
  std::sort(forest_classes.begin(), forest_classes.end());
  forest_classes.erase(std::unique(forest_classes.begin(), forest_classes.end()),
                       forest_classes.end());
  for (size_t i = 0; i < test.size(); ++i) {
    const float* row = test_rows.row(static_cast<Eigen::Index>(i)).data();
    const SvmPrediction svm_says = svm_prediction(svm, row);
    const ForestPrediction forest_says =
        forest_prediction(*forest, forest_classes, row, static_cast<int>(features.cols()));
    const auto fixed = static_cast<int32_t>(HairStyle::fixed);
    const bool not_fixed =
        !fixed_ruled_out.empty() && fixed_ruled_out[static_cast<size_t>(test[i])] != 0;
    result.svm.push_back(not_fixed && svm_says.label == fixed
                             ? svm_label_without(svm, svm_says.decision_values, fixed)
                             : svm_says.label);
    result.forest.push_back(
        not_fixed && forest_says.label == fixed
            ? forest_label_without(forest_classes, forest_says.vote_fraction, fixed)
            : forest_says.label);
  }
  return result;
}

}  // namespace hair
