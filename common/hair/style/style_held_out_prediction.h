#pragma once
// One round of a held-out evaluation of the two style classifiers: train on some rows,
// predict others (the body of every cross-validation fold and of every held-out mesh).

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

#include "hair/style/puk_svm_grid_search.h"
#include "hair/style/style_classifier_params.h"

namespace hair {

/// The predictions of both classifiers for the test rows, in the order given.
struct HeldOutPrediction {
  std::vector<int32_t> svm;     ///< per test row
  std::vector<int32_t> forest;  ///< per test row
  PukSvmSelection svm_choice;   ///< the SVM settings the grid search chose on the training rows
};

/// Trains both classifiers on the `train` rows and predicts the `test` rows.
///
/// The standardisation is computed on the training rows alone and applied to both; the
/// SVM's sigma, omega and C are chosen by a grid search on the training rows
/// (params.inner_folds folds, seeded by `grid_seed`), so no test row takes part in a
/// choice; the random forest is trained with params.forest. Deterministic.
///   @param[in] features  n x d, finite
///   @param[in] labels  n class labels
///   @param[in] train, test  row indices into features (disjoint; train not empty)
///   @param[in] fixed_ruled_out  empty, or per row of `features` 1 where the paper's
///       criteria rule fixed out (fixed_ruled_out_of_rows): a test row the classifiers call
///       fixed there takes the class they give among the others (svm_label_without,
///       forest_label_without)
HeldOutPrediction held_out_prediction(const Eigen::MatrixXd& features,
                                      std::span<const int32_t> labels,
                                      const std::vector<Eigen::Index>& train,
                                      const std::vector<Eigen::Index>& test,
                                      const StyleClassifierParams& params, uint64_t grid_seed,
                                      std::span<const uint8_t> fixed_ruled_out = {});

}  // namespace hair
