// The PUK SVM: our copy of OpenCV's model predicts exactly as OpenCV does; the grid search.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "unit/feature_blobs.h"
#include "hair/core/error.h"
#include "hair/style/feature_standardization.h"
#include "hair/style/puk_svm.h"
#include "hair/style/puk_svm_grid_search.h"

namespace hair {
namespace {

using test::four_blobs;
using test::LabelledRows;

/// Standardised rows: the first `train` rows standardise all.
FloatRows standardized(const LabelledRows& data, Eigen::Index train) {
  return standardized_rows(feature_standardization(data.features.topRows(train)), data.features);
}

std::vector<int32_t> distinct(std::vector<int32_t> labels) {
  std::sort(labels.begin(), labels.end());
  labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
  return labels;
}

/// Trains on the first `train` rows and checks our prediction against OpenCV's on every
/// row, training and test; returns how many rows OpenCV and we got right.
int expect_same_as_opencv(const LabelledRows& data, Eigen::Index train,
                          const PukSvmParams& params) {
  FloatRows rows = standardized(data, train);
  FloatRows train_rows = rows.topRows(train);
  std::vector<int32_t> train_labels(data.labels.begin(), data.labels.begin() + train);
  cv::Ptr<cv::ml::SVM> opencv = trained_opencv_puk_svm(train_rows, train_labels, params);
  PukSvm ours = puk_svm_from_opencv(*opencv, distinct(train_labels), params);
  auto k = ours.class_labels.size();
  EXPECT_EQ(ours.decision_functions.size(), k * (k - 1) / 2);
  int correct = 0;
  for (Eigen::Index row = 0; row < rows.rows(); ++row) {
    cv::Mat sample(1, static_cast<int>(rows.cols()), CV_32F, rows.row(row).data());
    float expected = opencv->predict(sample);
    SvmPrediction prediction = svm_prediction(ours, rows.row(row).data());
    EXPECT_EQ(static_cast<float>(prediction.label), expected) << "row " << row;
    EXPECT_EQ(prediction.decision_values.size(), k * (k - 1) / 2);
    int votes = 0;
    for (int32_t count : prediction.votes) votes += count;
    EXPECT_EQ(votes, static_cast<int>(k * (k - 1) / 2));
    if (k == 2) {  // OpenCV gives the one decision value itself
      cv::Mat raw;
      opencv->predict(sample, raw, cv::ml::StatModel::RAW_OUTPUT);
      EXPECT_EQ(static_cast<float>(prediction.decision_values[0]), raw.at<float>(0));
    }
    correct += prediction.label == data.labels[static_cast<size_t>(row)];
  }
  return correct;
}

TEST(PukSvm, PredictsAsOpenCvOnSeparableBlobs) {
  LabelledRows data = four_blobs(40, 0.5, 11);
  for (PukSvmParams params : {PukSvmParams{1, 1, 1}, PukSvmParams{4, 5, 100}})
    EXPECT_GE(expect_same_as_opencv(data, 120, params), 155);
}

TEST(PukSvm, PredictsAsOpenCvOnOverlappingBlobs) {
  LabelledRows data = four_blobs(40, 2.0, 12);
  for (PukSvmParams params :
       {PukSvmParams{0.5, 0.5, 10}, PukSvmParams{2, 1, 1}, PukSvmParams{8, 2, 0.1}})
    expect_same_as_opencv(data, 120, params);
}

TEST(PukSvm, PredictsAsOpenCvWithTwoClassesAndGappedLabels) {
  LabelledRows data = four_blobs(30, 1.5, 13);
  LabelledRows two = data, gapped = data;
  for (int32_t& label : two.labels) label = label < 2 ? 0 : 1;          // two classes
  for (int32_t& label : gapped.labels) label = label == 1 ? 7 : label;  // 0, 2, 3, 7
  expect_same_as_opencv(two, 90, {1, 1, 10});
  expect_same_as_opencv(gapped, 90, {2, 1, 10});
}

TEST(PukSvm, OneClassPredictsIt) {
  LabelledRows data = four_blobs(5, 1.0, 14);
  std::vector<int32_t> labels(data.labels.size(), 2);
  PukSvm svm = trained_puk_svm(standardized(data, 20), labels, {});
  EXPECT_TRUE(svm.decision_functions.empty());
  SvmPrediction prediction = svm_prediction(svm, standardized(data, 20).row(3).data());
  EXPECT_EQ(prediction.label, 2);
  EXPECT_TRUE(prediction.decision_values.empty());
  EXPECT_THROW(trained_opencv_puk_svm(standardized(data, 20), labels, {}), Error);
}

TEST(PukSvm, RejectsBadParameters) {
  LabelledRows data = four_blobs(5, 1.0, 15);
  EXPECT_THROW(trained_puk_svm(standardized(data, 20), data.labels, {1, 1, 0}), Error);
  EXPECT_THROW(trained_puk_svm(standardized(data, 20), data.labels, {-1, 1, 1}), Error);
}

TEST(PukSvmGridSearch, CandidatesInOrderOfPreference) {
  PukSvmGrid grid{{1, 4}, {2, 1}, {10, 0.1}};
  std::vector<PukSvmParams> candidates = puk_svm_candidates(grid);
  ASSERT_EQ(candidates.size(), 8u);
  EXPECT_EQ(candidates.front(), (PukSvmParams{4, 1, 0.1}));  // smallest C, widest, omega 1
  EXPECT_EQ(candidates[1], (PukSvmParams{4, 2, 0.1}));
  EXPECT_EQ(candidates.back(), (PukSvmParams{1, 2, 10}));
  EXPECT_THROW(check_puk_svm_grid({{}, {1}, {1}}), Error);
  EXPECT_THROW(check_puk_svm_grid({{1}, {0}, {1}}), Error);
}

TEST(PukSvmGridSearch, PicksTheBestAndIsDeterministic) {
  LabelledRows data = four_blobs(25, 1.2, 16);
  FloatRows rows = standardized(data, 100);
  PukSvmGrid grid{{0.05, 2}, {1}, {1, 10}};
  PukSvmSelection first = selected_puk_svm_params(rows, data.labels, grid, 5, 3);
  PukSvmSelection second = selected_puk_svm_params(rows, data.labels, grid, 5, 3);
  EXPECT_EQ(first.params, second.params);
  EXPECT_EQ(first.correct, second.correct);
  EXPECT_EQ(first.rows, 100);
  // A kernel far narrower than the gaps between rows remembers the training rows and
  // guesses elsewhere: the search must not pick it.
  EXPECT_EQ(first.params.sigma, 2);
  EXPECT_GT(first.accuracy(), 0.8);
  // Equal scores go to the earlier candidate: with one candidate per C that are all
  // perfect on far-apart blobs, the smallest C wins.
  LabelledRows far = four_blobs(10, 0.1, 17, 20.0);
  PukSvmSelection tie =
      selected_puk_svm_params(standardized(far, 40), far.labels, {{2}, {1}, {100, 1, 10}}, 5, 3);
  EXPECT_EQ(tie.correct, 40);
  EXPECT_EQ(tie.params.c, 1);
}

}  // namespace
}  // namespace hair
