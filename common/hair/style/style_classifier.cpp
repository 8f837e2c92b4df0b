#include "hair/style/style_classifier.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "hair/core/error.h"
#include "hair/style/random_forest.h"

namespace hair {

StyleModel trained_style_model(const Eigen::MatrixXd& features, std::span<const int32_t> labels,
                               std::string feature_set, std::vector<std::string> feature_names,
                               const StyleClassifierParams& params) {
  params.check();
  if (features.rows() < 1 || static_cast<size_t>(features.rows()) != labels.size() ||
      static_cast<size_t>(features.cols()) != feature_names.size())
    throw Error::usage("style model: " + std::to_string(features.rows()) + " x " +
                       std::to_string(features.cols()) + " features, " +
                       std::to_string(labels.size()) + " labels and " +
                       std::to_string(feature_names.size()) +
                       " feature names (need one label a row, one name a column, one row or more)");
  check_finite_features(features, feature_names);

  StyleModel model;
  model.feature_set = std::move(feature_set);
  model.feature_names = std::move(feature_names);
  model.standardization = feature_standardization(features, params.feature_log_offsets);
  FloatRows rows = standardized_rows(model.standardization, features);
  model.svm_selection = selected_puk_svm_params(rows, labels, params.svm_grid, params.inner_folds,
                                                params.seed + 1 + params.folds);
  model.svm = trained_puk_svm(rows, labels, model.svm_selection.params);
  model.forest = trained_random_forest(rows, labels, params.forest);
  model.forest_params = params.forest;
  model.default_classifier = params.default_classifier;
  model.class_labels = model.svm.class_labels;
  for (int32_t label : model.class_labels)
    model.class_counts.push_back(static_cast<int>(std::count(labels.begin(), labels.end(), label)));
  model.training_rows = static_cast<int>(labels.size());
  return model;
}

StylePrediction style_prediction(const StyleModel& model, std::span<const double> row) {
  if (row.size() != model.feature_names.size())
    throw Error::bad_input("", "a feature row of " + std::to_string(row.size()) +
                                   " values for a style model of " +
                                   std::to_string(model.feature_names.size()) + " features");
  Eigen::MatrixXd features(1, static_cast<Eigen::Index>(row.size()));
  for (size_t i = 0; i < row.size(); ++i) features(0, static_cast<Eigen::Index>(i)) = row[i];
  check_finite_features(features, model.feature_names);
  FloatRows standardized = standardized_rows(model.standardization, features);

  StylePrediction prediction;
  SvmPrediction svm = svm_prediction(model.svm, standardized.data());
  prediction.svm_label = svm.label;
  prediction.svm_decision_values = std::move(svm.decision_values);
  prediction.svm_votes = std::move(svm.votes);
  ForestPrediction forest =
      forest_prediction(*model.forest, model.class_labels, standardized.data(),
                        static_cast<int>(standardized.cols()));
  prediction.forest_label = forest.label;
  prediction.forest_vote_fraction = std::move(forest.vote_fraction);
  prediction.label = model.default_classifier == StyleClassifierKind::svm ? prediction.svm_label
                                                                          : prediction.forest_label;
  return prediction;
}

}  // namespace hair
