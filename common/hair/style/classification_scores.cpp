#include "hair/style/classification_scores.h"

#include <algorithm>
#include <string>

#include "hair/core/error.h"

namespace hair {

ClassificationScores classification_scores(std::span<const int32_t> truth,
                                           std::span<const int32_t> predicted,
                                           std::span<const int32_t> class_labels,
                                           const std::vector<bool>& subset) {
  if (truth.size() != predicted.size() || (!subset.empty() && subset.size() != truth.size()))
    throw Error::usage("classification scores: " + std::to_string(truth.size()) + " labels, " +
                       std::to_string(predicted.size()) + " predictions and " +
                       std::to_string(subset.size()) + " subset flags");
  auto k = static_cast<Eigen::Index>(class_labels.size());
  auto index_of = [&](int32_t label) -> Eigen::Index {
    auto found = std::find(class_labels.begin(), class_labels.end(), label);
    return found == class_labels.end() ? -1 : found - class_labels.begin();
  };
  ClassificationScores scores;
  scores.rows = static_cast<int>(truth.size());
  scores.confusion = Eigen::MatrixXi::Zero(k, k);
  for (int32_t label : class_labels) scores.classes.push_back({label, 0, 0, 0});
  for (size_t row = 0; row < truth.size(); ++row) {
    bool right = truth[row] == predicted[row];
    scores.correct += right;
    if (!subset.empty() && subset[row]) {
      ++scores.subset_rows;
      scores.subset_correct += right;
    }
    Eigen::Index true_class = index_of(truth[row]), predicted_class = index_of(predicted[row]);
    if (true_class >= 0) {
      ++scores.classes[static_cast<size_t>(true_class)].rows;
      scores.classes[static_cast<size_t>(true_class)].correct += right;
    }
    if (predicted_class >= 0) ++scores.classes[static_cast<size_t>(predicted_class)].predicted;
    if (true_class >= 0 && predicted_class >= 0) ++scores.confusion(true_class, predicted_class);
  }
  return scores;
}

}  // namespace hair
