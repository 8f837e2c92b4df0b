#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "hair/style/classification_scores.h"
#include "hair/style/puk_svm_grid_search.h"
#include "hair/style/style_classifier_params.h"

namespace hair {

/// What a cross-validation of the two style classifiers measured.
struct StyleCrossValidation {
  int folds = 0;
  bool given_folds = false;            ///< the caller's folds (e.g. by model), not stratified ones
  std::vector<int32_t> class_labels;   ///< k, the distinct labels of the rows, ascending
  std::vector<int32_t> fold;           ///< n, the fold of every row (its test fold)
  std::vector<int32_t> svm_predicted;  ///< n, each row predicted by the SVM of its fold
  std::vector<int32_t> forest_predicted;  ///< n, likewise by the random forest
  ClassificationScores svm;               ///< scores of svm_predicted, over class_labels
  ClassificationScores forest;            ///< scores of forest_predicted, over class_labels
  /// Per fold: the SVM settings chosen by the grid search on its training rows, with their
  /// inner cross-validated accuracy.
  std::vector<PukSvmSelection> svm_choice;
  std::vector<int> fold_rows;  ///< per fold, its test rows
};

/// Stratified `params.folds`-fold cross-validation of both classifiers (paper, section 5.1:
/// ten folds, 84.8% for the SVM and 86.7% for the random forest).
///
/// For each fold: the other folds are the training rows; the standardisation is computed
/// on them (feature_standardization) and applied to training and test rows; the SVM's
/// sigma, omega and C are chosen by a grid search on the training rows alone
/// (selected_puk_svm_params, params.inner_folds folds), so the test rows never take part
/// in a choice; the SVM with those settings and the random forest are trained on the
/// training rows and predict the test rows. Every row is predicted once.
///
///   @param[in] features  n x d, finite, rows = samples (clusters)
///   @param[in] labels  n class labels (HairStyle values); a class may have fewer rows
///       than folds (its rows go to different folds) and may then be missing from some
///       training sets (their classifiers cannot predict it)
///   @param[in] subset  n flags (or empty), e.g. the rows from real meshes: the scores'
///       subset accuracy is that of the cross-validated predictions on these rows alone
///
/// Deterministic: the same inputs and settings give the same result, whatever the thread
/// count. Throws hair::Error: bad input for a non-finite feature (naming row and
/// column); usage for bad settings, fewer rows than folds, or lengths that differ.
///   @param[in] fold_of_row  n folds in [0, params.folds), or empty: the stratified folds
///       of stratified_folds(labels, params.folds, params.seed). Given folds keep rows
///       together, e.g. the clusters of one model (grouped_folds).
StyleCrossValidation style_cross_validation(const Eigen::MatrixXd& features,
                                            std::span<const int32_t> labels,
                                            const std::vector<bool>& subset,
                                            const StyleClassifierParams& params,
                                            std::span<const int32_t> fold_of_row = {});

}  // namespace hair
