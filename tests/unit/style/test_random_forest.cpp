// The random forest: OpenCV's RTrees with our settings, votes and determinism.
#include <gtest/gtest.h>

#include <vector>

#include "unit/feature_blobs.h"
#include "hair/core/error.h"
#include "hair/style/feature_standardization.h"
#include "hair/style/random_forest.h"

namespace hair {
namespace {

using test::four_blobs;
using test::LabelledRows;

TEST(RandomForest, VotesAgreeWithOpenCvPredict) {
  LabelledRows data = four_blobs(30, 1.5, 21);
  FloatRows rows = standardized_rows(feature_standardization(data.features), data.features);
  RandomForestParams params;
  cv::Ptr<cv::ml::RTrees> forest = trained_random_forest(rows, data.labels, params);
  EXPECT_EQ(static_cast<int>(forest->getRoots().size()), params.trees);
  std::vector<int32_t> classes = {0, 1, 2, 3};
  int correct = 0;
  for (Eigen::Index row = 0; row < rows.rows(); ++row) {
    ForestPrediction prediction = forest_prediction(*forest, classes, rows.row(row).data(), 3);
    cv::Mat sample(1, 3, CV_32F, rows.row(row).data());
    EXPECT_EQ(static_cast<float>(prediction.label), forest->predict(sample)) << "row " << row;
    double sum = 0;
    int votes = 0;
    for (size_t c = 0; c < classes.size(); ++c) {
      sum += prediction.vote_fraction[c];
      votes += prediction.votes[c];
      EXPECT_EQ(prediction.vote_fraction[c], prediction.votes[c] / 100.0);
    }
    EXPECT_NEAR(sum, 1.0, 1e-12);
    EXPECT_EQ(votes, 100);
    correct += prediction.label == data.labels[static_cast<size_t>(row)];
  }
  EXPECT_GT(correct, 110);  // fully grown trees nearly remember their training rows
}

TEST(RandomForest, TwoTrainingsGiveTheSameForest) {
  LabelledRows data = four_blobs(20, 2.0, 22);
  FloatRows rows = standardized_rows(feature_standardization(data.features), data.features);
  LabelledRows probe = four_blobs(20, 2.5, 23);
  FloatRows probe_rows = standardized_rows(feature_standardization(data.features), probe.features);
  cv::theRNG() = cv::RNG(99);  // whatever the caller's generator holds
  cv::Ptr<cv::ml::RTrees> first = trained_random_forest(rows, data.labels, {});
  uint64_t state_after = cv::theRNG().state;
  cv::Ptr<cv::ml::RTrees> second = trained_random_forest(rows, data.labels, {});
  EXPECT_EQ(state_after, cv::RNG(99).state);  // the caller's generator is restored
  RandomForestParams other_seed;
  other_seed.seed = 2;
  cv::Ptr<cv::ml::RTrees> third = trained_random_forest(rows, data.labels, other_seed);
  std::vector<int32_t> classes = {0, 1, 2, 3};
  bool any_difference = false;
  for (Eigen::Index row = 0; row < probe_rows.rows(); ++row) {
    const float* values = probe_rows.row(row).data();
    EXPECT_EQ(forest_prediction(*first, classes, values, 3).votes,
              forest_prediction(*second, classes, values, 3).votes);
    any_difference |= forest_prediction(*first, classes, values, 3).votes !=
                      forest_prediction(*third, classes, values, 3).votes;
  }
  EXPECT_TRUE(any_difference);  // the seed does matter
}

TEST(RandomForest, ClassesItDoesNotKnowGetNoVotes) {
  LabelledRows data = four_blobs(10, 1.0, 24);
  for (int32_t& label : data.labels) label = label == 0 ? 5 : 2;
  FloatRows rows = standardized_rows(feature_standardization(data.features), data.features);
  cv::Ptr<cv::ml::RTrees> forest = trained_random_forest(rows, data.labels, {});
  ForestPrediction prediction =
      forest_prediction(*forest, std::vector<int32_t>{1, 2, 5}, rows.row(0).data(), 3);
  EXPECT_EQ(prediction.votes[0], 0);
  EXPECT_EQ(prediction.votes[1] + prediction.votes[2], 100);
}

TEST(RandomForest, RejectsBadSettings) {
  LabelledRows data = four_blobs(5, 1.0, 25);
  FloatRows rows = standardized_rows(feature_standardization(data.features), data.features);
  RandomForestParams params;
  params.trees = 0;
  EXPECT_THROW(trained_random_forest(rows, data.labels, params), Error);
  params = {};
  params.max_depth = 40;
  EXPECT_THROW(trained_random_forest(rows, data.labels, params), Error);
}

}  // namespace
}  // namespace hair
