// The classifiers' preprocessing: lengths and counts on a log scale, then standardised.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "hair/core/error.h"
#include "hair/style/feature_standardization.h"
#include "hair/style/style_features.h"
#include "hair/style/style_model_holdout.h"

namespace hair {
namespace {

TEST(FeatureLogOffsets, LengthsInHAndTheNodeCountOnALogScaleTheRestAsTheyAre) {
  const std::vector<std::string> names = {"mean_length_h",     "gathering_ratio", "root_share",
                                          "middle_node_count", "twist_h",         "downward_33"};
  EXPECT_EQ(feature_log_offsets(names),
            (std::vector<double>{kLengthLogOffsetH, 0, 0, kCountLogOffset, kLengthLogOffsetH, 0}));
  // The paper's seven: its five lengths and its count; the ratio and the share as they are.
  std::vector<double> paper = feature_log_offsets(paper_feature_names());
  EXPECT_EQ(std::count(paper.begin(), paper.end(), 0.0), 2);
  // The raw features (positions, their spreads, distances per particle) stay as the paper
  // compares them.
  for (double offset : feature_log_offsets(raw_feature_names(17))) EXPECT_EQ(offset, 0.0);
}

TEST(FeatureStandardization, LogScaledColumnsAreStandardisedLogarithms) {
  Eigen::MatrixXd rows(4, 2);
  rows << 0.2, 1, 0.4, 2, 1.0, 3, 2.0, 4;
  const std::vector<double> offsets = {0.03, 0};
  FeatureStandardization standardization = feature_standardization(rows, offsets);
  // Column 0 by hand: log(x + 0.03), its mean and its standard deviation (divided by n).
  std::vector<double> logs;
  for (double x : {0.2, 0.4, 1.0, 2.0}) logs.push_back(std::log(x + 0.03));
  double mean = (logs[0] + logs[1] + logs[2] + logs[3]) / 4, variance = 0;
  for (double value : logs) variance += (value - mean) * (value - mean) / 4;
  EXPECT_NEAR(standardization.mean[0], mean, 1e-12);
  EXPECT_NEAR(standardization.scale[0], std::sqrt(variance), 1e-12);
  EXPECT_NEAR(standardization.mean[1], 2.5, 1e-12);  // column 1 as it is
  FloatRows z = standardized_rows(standardization, rows);
  for (int row = 0; row < 4; ++row)
    EXPECT_NEAR(z(row, 0), (logs[static_cast<size_t>(row)] - mean) / std::sqrt(variance), 1e-6);
  EXPECT_NEAR(z(0, 1), (1 - 2.5) / std::sqrt(1.25), 1e-6);
  // Doubling a length moves it by nearly the same amount wherever it starts: 0.2 -> 0.4 H
  // and 1 -> 2 H are 0.63 and 0.68 apart in log units (as they are, 0.2 against 1: a fifth).
  EXPECT_GT((z(1, 0) - z(0, 0)) / (z(3, 0) - z(2, 0)), 0.9);
  // A negative length, which no feature gives, counts as none.
  Eigen::MatrixXd negative(1, 2);
  negative << -0.5, 1;
  Eigen::MatrixXd zero(1, 2);
  zero << 0, 1;
  EXPECT_EQ(standardized_rows(standardization, negative), standardized_rows(standardization, zero));
}

TEST(FeatureStandardization, WithoutLogOffsetsEveryColumnAsItIs) {
  Eigen::MatrixXd rows(3, 1);
  rows << 1, 2, 6;
  FeatureStandardization plain = feature_standardization(rows);
  EXPECT_EQ(plain.log_offset.size(), 0);
  EXPECT_NEAR(plain.mean[0], 3, 1e-12);
  FeatureStandardization zeros = feature_standardization(rows, std::vector<double>{0});
  EXPECT_EQ(standardized_rows(plain, rows), standardized_rows(zeros, rows));
}

TEST(FeatureStandardization, RejectsBadLogOffsets) {
  Eigen::MatrixXd rows(2, 2);
  rows << 1, 2, 3, 4;
  EXPECT_THROW(feature_standardization(rows, std::vector<double>{0.03}), Error);
  EXPECT_THROW(feature_standardization(rows, std::vector<double>{0.03, -1}), Error);
  EXPECT_THROW(feature_standardization(rows, std::vector<double>{0.03, NAN}), Error);
}

// Mesh density: a braid cut into 29 middle nodes (braid01) against braids cut into 3 and 10
// and hair with none. As counts it lies 4.5 standard deviations past the most cut braid;
// on the log scale about one.
TEST(FeatureStandardization, AMuchCutBraidLiesNearTheBraidsOnTheLogScale) {
  Eigen::MatrixXd training(3, 1), query(1, 1);
  training << 0, 3, 10;
  query << 29;
  const double as_counts = nearest_row_distances(training, query).front();
  const double on_log_scale =
      nearest_row_distances(training, query, std::vector<double>{kCountLogOffset}).front();
  // By hand: the counts' mean 13/3 and deviation sqrt(158/9); their logs log(1 + n).
  EXPECT_NEAR(as_counts, 19 / std::sqrt(158.0 / 9), 1e-5);
  const double l3 = std::log(4.0), l10 = std::log(11.0), mean = (l3 + l10) / 3;
  const double deviation =
      std::sqrt((mean * mean + (l3 - mean) * (l3 - mean) + (l10 - mean) * (l10 - mean)) / 3);
  EXPECT_NEAR(on_log_scale, (std::log(30.0) - l10) / deviation, 1e-5);
  EXPECT_GT(as_counts, 4.5);
  EXPECT_LT(on_log_scale, 1.05);
}

}  // namespace
}  // namespace hair
