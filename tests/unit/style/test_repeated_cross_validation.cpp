// Repeated cross-validation: every repeat a fresh draw of folds, the first one the single
// cross-validation, and the spread of the accuracies reported.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "hair/core/error.h"
#include "hair/style/repeated_cross_validation.h"
#include "hair/style/stratified_folds.h"
#include "hair/style/style_cross_validation.h"
#include "unit/feature_blobs.h"

namespace hair {
namespace {

using test::four_blobs;
using test::LabelledRows;

StyleClassifierParams quick_params() {
  StyleClassifierParams params;
  params.svm_grid = {{1, 4}, {1}, {1, 10}};
  params.forest.trees = 30;
  params.seed = 7;
  return params;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(AccuracySpread, MeanSampleDeviationAndRange) {
  // 0.88, 0.90, 0.92: mean 0.90, sample variance (0.02^2 + 0 + 0.02^2) / 2 = 0.0004.
  std::vector<double> accuracies = {0.90, 0.88, 0.92};
  AccuracySpread spread = accuracy_spread(accuracies);
  EXPECT_NEAR(spread.mean, 0.90, 1e-12);
  EXPECT_NEAR(spread.standard_deviation, 0.02, 1e-12);
  EXPECT_DOUBLE_EQ(spread.min, 0.88);
  EXPECT_DOUBLE_EQ(spread.max, 0.92);
  std::vector<double> one = {0.7};
  EXPECT_DOUBLE_EQ(accuracy_spread(one).standard_deviation, 0.0);
  EXPECT_DOUBLE_EQ(accuracy_spread(one).mean, 0.7);
  EXPECT_DOUBLE_EQ(accuracy_spread(std::vector<double>{}).mean, 0.0);
}

TEST(RepeatedCrossValidation, EachRepeatDrawsItsOwnFoldsAndTheFirstIsTheSingleRun) {
  // Overlapping blobs, so that the draw of folds moves the accuracy.
  LabelledRows data = four_blobs(25, 1.4, 41);
  std::vector<bool> subset(data.labels.size(), false);
  for (size_t row = 0; row < subset.size(); row += 4) subset[row] = true;
  const StyleClassifierParams params = quick_params();
  RepeatedCrossValidation repeated =
      repeated_style_cross_validation(data.features, data.labels, subset, params, 3);
  ASSERT_EQ(repeated.repeats.size(), 3u);
  EXPECT_EQ(repeated.seeds, (std::vector<uint64_t>{7, 8, 9}));

  StyleCrossValidation single = style_cross_validation(data.features, data.labels, subset, params);
  EXPECT_EQ(repeated.repeats[0].fold, single.fold);
  EXPECT_EQ(repeated.repeats[0].svm_predicted, single.svm_predicted);
  EXPECT_EQ(repeated.repeats[0].forest_predicted, single.forest_predicted);

  EXPECT_NE(repeated.repeats[0].fold, repeated.repeats[1].fold);
  EXPECT_NE(repeated.repeats[1].fold, repeated.repeats[2].fold);
  EXPECT_EQ(repeated.repeats[2].fold, stratified_folds(data.labels, params.folds, 9));

  std::vector<double> svm;
  for (const StyleCrossValidation& cv : repeated.repeats) svm.push_back(cv.svm.accuracy());
  AccuracySpread spread = accuracy_spread(svm);
  EXPECT_GT(spread.mean, 0.5);  // four classes: well above chance
  EXPECT_LE(spread.min, spread.mean);
  EXPECT_GE(spread.max, spread.mean);

  std::string markdown = repeated_cross_validation_markdown(repeated, "real meshes");
  EXPECT_TRUE(contains(markdown, "3 cross-validations, folds drawn with seeds 7 to 9"));
  EXPECT_TRUE(contains(markdown, "| classifier | mean | sd | least | largest | each |"));
  char mean_cell[32];
  std::snprintf(mean_cell, sizeof mean_cell, "| SVM (PUK kernel) | %.1f%% |", 100 * spread.mean);
  EXPECT_TRUE(contains(markdown, mean_cell)) << markdown;
  EXPECT_TRUE(contains(markdown, "| SVM, real meshes |"));
}

TEST(RepeatedCrossValidation, GivenFoldsAreDrawnPerSeed) {
  LabelledRows data = four_blobs(12, 1.0, 42);
  std::vector<std::string> model(data.labels.size());
  for (size_t row = 0; row < model.size(); ++row) model[row] = std::to_string(row % 16);
  StyleClassifierParams params = quick_params();
  params.folds = 4;
  std::vector<uint64_t> asked;
  FoldsForSeed by_model = [&](uint64_t seed) {
    asked.push_back(seed);
    return grouped_folds(model, params.folds, seed);
  };
  RepeatedCrossValidation repeated =
      repeated_style_cross_validation(data.features, data.labels, {}, params, 2, by_model);
  EXPECT_EQ(asked, (std::vector<uint64_t>{7, 8}));
  for (size_t r = 0; r < 2; ++r) {
    EXPECT_TRUE(repeated.repeats[r].given_folds);
    EXPECT_EQ(repeated.repeats[r].fold, grouped_folds(model, params.folds, 7 + r));
  }
  // No subset: no subset rows in the table.
  EXPECT_FALSE(contains(repeated_cross_validation_markdown(repeated, "real meshes"), "real"));
}

TEST(RepeatedCrossValidation, RefusesNoRepeats) {
  LabelledRows data = four_blobs(10, 1.0, 43);
  try {
    repeated_style_cross_validation(data.features, data.labels, {}, quick_params(), 0);
    FAIL();
  } catch (const Error& error) {
    EXPECT_EQ(error.exit_code(), 2);
    EXPECT_TRUE(contains(error.what(), "0 repeats")) << error.what();
  }
}

}  // namespace
}  // namespace hair
