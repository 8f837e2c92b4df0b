#include "hair/style/repeated_model_holdout.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "hair/core/error.h"
#include "hair/style/repeated_cross_validation.h"

namespace hair {

RepeatedModelHoldout repeated_leave_one_model_out(
    const Eigen::MatrixXd& features, std::span<const int32_t> labels,
    const std::vector<std::string>& model_of_row, const std::vector<bool>& held_out,
    std::span<const double> weight, const StyleClassifierParams& params, int repeats,
    std::span<const int32_t> decided, std::span<const uint8_t> fixed_ruled_out) {
  RepeatedModelHoldout result;
  for (const StyleClassifierParams& repeat_params :
       seeded_repeats(params, repeats, "repeated leave-one-model-out")) {
    result.seeds.push_back(repeat_params.seed);
    result.repeats.push_back(leave_one_model_out(features, labels, model_of_row, held_out, weight,
                                                 repeat_params, decided, fixed_ruled_out));
  }
  return result;
}

namespace {

/// Share of the weight of rows [first, first + count) that `predicted` gets right.
double share_right(const ModelHoldout& holdout, const std::vector<int32_t>& predicted, size_t first,
                   size_t count) {
  double right = 0, total = 0;
  for (size_t row = first; row < first + count; ++row) {
    total += holdout.weight[row];
    if (predicted[row] == holdout.truth[row]) right += holdout.weight[row];
  }
  return total > 0 ? right / total : 0.0;
}

std::string spread_cells(const std::vector<double>& shares) {
  const AccuracySpread spread = accuracy_spread(shares);
  return fmt::format("{:.1f}% | {:.1f}% | {:.1f}%", 100 * spread.mean, 100 * spread.min,
                     100 * spread.max);
}

}  // namespace

std::string repeated_model_holdout_markdown(const RepeatedModelHoldout& result) {
  if (result.repeats.empty()) return "";
  std::vector<double> svm, forest;
  for (const ModelHoldout& repeat : result.repeats) {
    svm.push_back(repeat.svm_scores.accuracy());
    forest.push_back(repeat.forest_scores.accuracy());
  }
  std::string text = fmt::format(
      "{} leave-one-model-out evaluations, the SVM's grid-search folds drawn with seeds {} to "
      "{} (strands right in %; standard deviation in points):\n\n"
      "| classifier | mean | sd | least | largest | each |\n|---|---:|---:|---:|---:|---|\n",
      result.repeats.size(), result.seeds.front(), result.seeds.back());
  for (const auto& [name, shares] :
       {std::pair{"SVM (PUK kernel)", svm}, {"random forest", forest}}) {
    const AccuracySpread spread = accuracy_spread(shares);
    text += fmt::format("| {} | {:.1f}% | {:.1f} | {:.1f}% | {:.1f}% |", name, 100 * spread.mean,
                        100 * spread.standard_deviation, 100 * spread.min, 100 * spread.max);
    for (size_t r = 0; r < shares.size(); ++r)
      text += fmt::format("{}{:.1f}", r == 0 ? " " : ", ", 100 * shares[r]);
    text += " |\n";
  }
  text +=
      "\nPer held-out model, strands right over the repeats:\n\n| model | SVM mean | SVM least "
      "| SVM largest | forest mean | forest least | forest largest |\n"
      "|---|---:|---:|---:|---:|---:|---:|\n";
  const ModelHoldout& first = result.repeats.front();
  size_t row = 0;
  for (size_t m = 0; m < first.models.size(); ++m) {
    const auto count = static_cast<size_t>(first.model_rows[m]);
    std::vector<double> svm_shares, forest_shares;
    for (const ModelHoldout& repeat : result.repeats) {
      svm_shares.push_back(share_right(repeat, repeat.svm, row, count));
      forest_shares.push_back(share_right(repeat, repeat.forest, row, count));
    }
    text += "| " + std::filesystem::path(first.models[m]).filename().string() + " | " +
            spread_cells(svm_shares) + " | " + spread_cells(forest_shares) + " |\n";
    row += count;
  }
  return text;
}

}  // namespace hair
