#include "hair/style/style_held_out_prediction.h"

#include <algorithm>

#include "hair/core/error.h"
#include "hair/style/feature_standardization.h"
#include "hair/style/puk_svm.h"
#include "hair/style/random_forest.h"

namespace hair {

HeldOutPrediction held_out_prediction(const Eigen::MatrixXd& features,
                                      std::span<const int32_t> labels,
                                      const std::vector<Eigen::Index>& train,
                                      const std::vector<Eigen::Index>& test,
                                      const StyleClassifierParams& params, uint64_t grid_seed) {
  if (train.empty()) throw Error::usage("held-out prediction: no training rows");
  Eigen::MatrixXd train_features = features(train, Eigen::all);
  std::vector<int32_t> train_labels;
  for (Eigen::Index row : train) train_labels.push_back(labels[static_cast<size_t>(row)]);

  FeatureStandardization standardization = feature_standardization(train_features);
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
    result.svm.push_back(svm_prediction(svm, row).label);
    result.forest.push_back(
        forest_prediction(*forest, forest_classes, row, static_cast<int>(features.cols())).label);
  }
  return result;
}

}  // namespace hair
