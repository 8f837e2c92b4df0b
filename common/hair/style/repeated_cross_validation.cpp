#include "hair/style/repeated_cross_validation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>

#include "hair/core/error.h"

namespace hair {

AccuracySpread accuracy_spread(std::span<const double> accuracies) {
  AccuracySpread spread;
  if (accuracies.empty()) return spread;
  const auto n = static_cast<double>(accuracies.size());
  spread.mean = std::accumulate(accuracies.begin(), accuracies.end(), 0.0) / n;
  double squares = 0;
  for (double accuracy : accuracies) squares += (accuracy - spread.mean) * (accuracy - spread.mean);
  spread.standard_deviation = accuracies.size() > 1 ? std::sqrt(squares / (n - 1)) : 0;
  auto [least, largest] = std::minmax_element(accuracies.begin(), accuracies.end());
  spread.min = *least;
  spread.max = *largest;
  return spread;
}

std::vector<StyleClassifierParams> seeded_repeats(const StyleClassifierParams& params, int repeats,
                                                  std::string_view what) {
  if (repeats < 1)
    throw Error::usage(std::string(what) + ": " + std::to_string(repeats) +
                       " repeats (need at least 1)");
  std::vector<StyleClassifierParams> settings(static_cast<size_t>(repeats), params);
  for (int r = 0; r < repeats; ++r)
    settings[static_cast<size_t>(r)].seed = params.seed + static_cast<uint64_t>(r);
  return settings;
}

RepeatedCrossValidation repeated_style_cross_validation(const Eigen::MatrixXd& features,
                                                        std::span<const int32_t> labels,
                                                        const std::vector<bool>& subset,
                                                        const StyleClassifierParams& params,
                                                        int repeats,
                                                        const FoldsForSeed& folds_for_seed) {
  RepeatedCrossValidation result;
  for (const StyleClassifierParams& repeat_params :
       seeded_repeats(params, repeats, "repeated cross-validation")) {
    std::vector<int32_t> folds;
    if (folds_for_seed) folds = folds_for_seed(repeat_params.seed);
    result.seeds.push_back(repeat_params.seed);
    result.repeats.push_back(
        style_cross_validation(features, labels, subset, repeat_params, folds));
  }
  return result;
}

namespace {

void append_row(std::string& text, const std::string& name, const std::vector<double>& accuracies) {
  AccuracySpread spread = accuracy_spread(accuracies);
  text += fmt::format("| {} | {:.1f}% | {:.1f} | {:.1f}% | {:.1f}% |", name, 100 * spread.mean,
                      100 * spread.standard_deviation, 100 * spread.min, 100 * spread.max);
  for (size_t r = 0; r < accuracies.size(); ++r)
    text += fmt::format("{}{:.1f}", r == 0 ? " " : ", ", 100 * accuracies[r]);
  text += " |\n";
}

}  // namespace

std::string repeated_cross_validation_markdown(const RepeatedCrossValidation& result,
                                               std::string_view subset_name) {
  if (result.repeats.empty()) return "";
  auto accuracies = [&](const std::function<double(const StyleCrossValidation&)>& of) {
    std::vector<double> values;
    for (const StyleCrossValidation& repeat : result.repeats) values.push_back(of(repeat));
    return values;
  };
  std::string text = fmt::format(
      "{} cross-validations, folds drawn with seeds {} to {} (accuracy in %; standard "
      "deviation in points):\n\n| classifier | mean | sd | least | largest | each |\n"
      "|---|---:|---:|---:|---:|---|\n",
      result.repeats.size(), result.seeds.front(), result.seeds.back());
  append_row(text, "SVM (PUK kernel)",
             accuracies([](const StyleCrossValidation& cv) { return cv.svm.accuracy(); }));
  append_row(text, "random forest",
             accuracies([](const StyleCrossValidation& cv) { return cv.forest.accuracy(); }));
  if (result.repeats.front().svm.subset_rows > 0) {
    append_row(text, fmt::format("SVM, {}", subset_name),
               accuracies([](const StyleCrossValidation& cv) { return cv.svm.subset_accuracy(); }));
    append_row(
        text, fmt::format("random forest, {}", subset_name),
        accuracies([](const StyleCrossValidation& cv) { return cv.forest.subset_accuracy(); }));
  }
  return text;
}

}  // namespace hair
