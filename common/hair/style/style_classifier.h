#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <opencv2/ml.hpp>
#include <span>
#include <string>
#include <vector>

#include "hair/style/feature_standardization.h"
#include "hair/style/puk_svm.h"
#include "hair/style/puk_svm_grid_search.h"
#include "hair/style/style_classifier_params.h"

namespace hair {

/// Both style classifiers trained on all rows of a feature set, with what they need to
/// classify a new row: the feature names in their order and the standardisation.
struct StyleModel {
  std::string feature_set;                 ///< name of the feature set (e.g. "paper", "raw")
  std::vector<std::string> feature_names;  ///< d, the order of a row's values
  FeatureStandardization standardization;  ///< of the training rows, applied before both
  PukSvm svm;                              ///< settings from the grid search on all rows
  PukSvmSelection svm_selection;           ///< the grid search's choice and inner accuracy
  cv::Ptr<cv::ml::RTrees> forest;
  RandomForestParams forest_params;
  StyleClassifierKind default_classifier = StyleClassifierKind::random_forest;
  std::vector<int32_t> class_labels;  ///< k, the distinct training labels, ascending
  std::vector<int> class_counts;      ///< k, training rows per class
  int training_rows = 0;
};

/// Trains both classifiers on all rows: the standardisation of all rows; the SVM with the
/// settings of a grid search by params.inner_folds-fold cross-validation on all rows
/// (seed params.seed + 1 + params.folds); the random forest with params.forest.
///
///   @param[in] features  n x d, finite (n >= 1)
///   @param[in] labels  n class labels (HairStyle values)
///   @param[in] feature_names  d names
///
/// Throws hair::Error: bad input for a non-finite feature (naming row and feature); usage
/// for bad settings, mismatched lengths, or no rows.
StyleModel trained_style_model(const Eigen::MatrixXd& features, std::span<const int32_t> labels,
                               std::string feature_set, std::vector<std::string> feature_names,
                               const StyleClassifierParams& params);

/// What the two classifiers of a model say about one row.
struct StylePrediction {
  int32_t svm_label = 0;
  /// The SVM's one-vs-one decision values (k (k - 1) / 2, pairs in PukSvm's order: > 0
  /// votes for the pair's first class) and votes (k, per StyleModel::class_labels).
  std::vector<double> svm_decision_values;
  std::vector<int32_t> svm_votes;
  int32_t forest_label = 0;
  std::vector<double> forest_vote_fraction;  ///< k, per StyleModel::class_labels, sum 1
  int32_t label = 0;                         ///< the default classifier's class
};

/// The classes of one row (d values, raw, in the model's feature order).
/// Throws hair::Error (bad input) for a row of another length or a non-finite value.
StylePrediction style_prediction(const StyleModel& model, std::span<const double> row);

}  // namespace hair
