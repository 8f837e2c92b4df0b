#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

namespace hair {

/// How well one class was recognised.
struct ClassScore {
  int32_t label = 0;
  int rows = 0;       ///< rows of this class (truth)
  int predicted = 0;  ///< rows predicted as this class
  int correct = 0;    ///< rows of this class predicted as it
  double precision() const { return predicted > 0 ? static_cast<double>(correct) / predicted : 0; }
  double recall() const { return rows > 0 ? static_cast<double>(correct) / rows : 0; }
};

/// Predictions of one classifier scored against the truth.
struct ClassificationScores {
  int rows = 0;
  int correct = 0;
  std::vector<ClassScore> classes;  ///< one per class label, in the order given
  /// k x k, rows the true class, columns the predicted class (in the order of `classes`);
  /// a label outside the class list is not counted here (it still counts as wrong).
  Eigen::MatrixXi confusion;
  int subset_rows = 0;     ///< rows flagged in the subset mask
  int subset_correct = 0;  ///< of them, predicted right
  double accuracy() const { return rows > 0 ? static_cast<double>(correct) / rows : 0; }
  double subset_accuracy() const {
    return subset_rows > 0 ? static_cast<double>(subset_correct) / subset_rows : 0;
  }
};

/// Accuracy, per-class precision and recall, the confusion matrix, and the accuracy on the
/// rows flagged in `subset` (empty: no subset; else n flags).
///
///   @param[in] truth, predicted  n labels each
///   @param[in] class_labels  k distinct labels, the order of the classes and the matrix
///
/// Throws hair::Error (usage) when the lengths differ.
ClassificationScores classification_scores(std::span<const int32_t> truth,
                                           std::span<const int32_t> predicted,
                                           std::span<const int32_t> class_labels,
                                           const std::vector<bool>& subset);

}  // namespace hair
