// Leave-one-model-out evaluation on real meshes (issue 26): strand-weighted scores and
// held-out models that never take part in their own training.
#include <gtest/gtest.h>

#include "../feature_blobs.h"
#include "hair/core/error.h"
#include "hair/style/style_model_holdout.h"

namespace hair {
namespace {

StyleClassifierParams quick_params() {
  StyleClassifierParams params;
  params.svm_grid = {{1, 4}, {1}, {1, 10}};
  params.forest.trees = 50;
  return params;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(WeightedStyleScores, WeighEachRowByItsStrands) {
  // Three clusters: a big normal one right, a small fixed one called normal, a short one right.
  std::vector<int32_t> truth = {0, 1, 2}, predicted = {0, 0, 2}, classes = {0, 1, 2, 3};
  std::vector<double> strands = {7000, 1000, 2000};
  WeightedStyleScores scores = weighted_style_scores(truth, predicted, strands, classes);
  EXPECT_DOUBLE_EQ(scores.total(), 10000);
  EXPECT_DOUBLE_EQ(scores.accuracy(), 0.9);
  EXPECT_DOUBLE_EQ(scores.confusion(1, 0), 1000);
  EXPECT_DOUBLE_EQ(scores.recall(1), 0);
  EXPECT_DOUBLE_EQ(scores.precision(0), 0.875);
  EXPECT_DOUBLE_EQ(scores.recall(0), 1);
  EXPECT_DOUBLE_EQ(scores.recall(3), 0);  // no braided strands: no recall, no division by 0
  std::vector<int32_t> unknown = {0, 7, 2};
  EXPECT_THROW(weighted_style_scores(truth, unknown, strands, classes), Error);
  std::vector<double> negative = {1, -1, 1};
  EXPECT_THROW(weighted_style_scores(truth, predicted, negative, classes), Error);
  EXPECT_THROW(weighted_style_scores(truth, predicted, std::vector<double>{1}, classes), Error);
}

/// Four well separated classes drawn for several synthetic models, and one "real" model
/// whose rows lie in class 0's blob but are labelled 1. Classifiers that had seen those
/// rows (the same points, repeated) would learn them; held out, they must be called 0.
using Corpus = test::ModelCorpus;

Corpus corpus_with_a_contrary_real_model() {
  Corpus corpus = test::synthetic_model_corpus(24, 0.5, 41, 6);
  // Two real models drawn from the blobs of classes 1-3, labelled truly (class 0's blob
  // is where the contrary model lies: that model, in their training, may sway it).
  test::LabelledRows drawn = test::four_blobs(4, 0.5, 42);
  auto n = corpus.data.features.rows();
  int truthful = 0;
  for (Eigen::Index r = 0; r < drawn.features.rows(); ++r) {
    if (drawn.labels[static_cast<size_t>(r)] == 0) continue;
    corpus.data.features.conservativeResize(n + truthful + 1, Eigen::NoChange);
    corpus.data.features.row(n + truthful) = drawn.features.row(r);
    corpus.data.labels.push_back(drawn.labels[static_cast<size_t>(r)]);
    corpus.model.push_back(truthful % 2 == 0 ? "real_a" : "real_b");
    corpus.real.push_back(true);
    corpus.strands.push_back(truthful % 2 == 0 ? 500 : 50);
    ++truthful;
  }
  // One real model in class 0's blob labelled 1, its rows repeated.
  n = corpus.data.features.rows();
  corpus.data.features.conservativeResize(n + 12, Eigen::NoChange);
  std::vector<Eigen::Index> class_0;  // two synthetic rows of class 0
  for (Eigen::Index r = 0; r < n && class_0.size() < 2; ++r)
    if (corpus.data.labels[static_cast<size_t>(r)] == 0) class_0.push_back(r);
  for (Eigen::Index r = 0; r < 12; ++r) {
    Eigen::Index row = n + r;
    corpus.data.features.row(row) = corpus.data.features.row(class_0[static_cast<size_t>(r % 2)]);
    corpus.data.labels.push_back(1);
    corpus.model.push_back("real_contrary");
    corpus.real.push_back(true);
    corpus.strands.push_back(1000);
  }
  return corpus;
}

TEST(LeaveOneModelOut, AHeldOutModelNeverTrainsItsOwnClassifiers) {
  Corpus corpus = corpus_with_a_contrary_real_model();
  ModelHoldout holdout = leave_one_model_out(corpus.data.features, corpus.data.labels, corpus.model,
                                             corpus.real, corpus.strands, quick_params());
  ASSERT_EQ(holdout.models, (std::vector<std::string>{"real_a", "real_b", "real_contrary"}));
  ASSERT_EQ(holdout.model_rows, (std::vector<int>{6, 6, 12}));  // 12 rows of classes 1-3
  ASSERT_EQ(holdout.rows.size(), 24u);
  size_t row = 0;
  double right_strands = 0;
  for (size_t m = 0; m < holdout.models.size(); ++m)
    for (int r = 0; r < holdout.model_rows[m]; ++r, ++row) {
      EXPECT_EQ(corpus.model[static_cast<size_t>(holdout.rows[row])], holdout.models[m]);
      EXPECT_EQ(holdout.weight[row], corpus.strands[static_cast<size_t>(holdout.rows[row])]);
      if (holdout.models[m] == "real_contrary") {
        // Trained without them, both classifiers call them what their blob is.
        EXPECT_EQ(holdout.forest[row], 0);
        EXPECT_EQ(holdout.svm[row], 0);
      } else {
        EXPECT_EQ(holdout.forest[row], holdout.truth[row]);
        right_strands += holdout.forest[row] == holdout.truth[row] ? holdout.weight[row] : 0;
      }
    }
  // 6 x 500 + 6 x 50 strands right out of those and 12 x 1000 wrong.
  EXPECT_DOUBLE_EQ(right_strands, 3300);
  EXPECT_DOUBLE_EQ(holdout.forest_scores.accuracy(), 3300.0 / 15300.0);
  EXPECT_DOUBLE_EQ(holdout.forest_scores.confusion(1, 0), 12000);

  std::vector<int32_t> cluster(corpus.model.size());
  for (size_t i = 0; i < cluster.size(); ++i) cluster[i] = static_cast<int32_t>(i % 7);
  std::string markdown = model_holdout_markdown(holdout, cluster);
  EXPECT_TRUE(contains(markdown, "3 models held out in turn, 24 clusters, 15300 strands"));
  EXPECT_TRUE(contains(markdown, "| random forest | 21.6% | 50.0% (12 / 24) |")) << markdown;
  EXPECT_TRUE(contains(markdown, "| real_contrary | 0.0% | 0.0% |"));
  // The contrary rows repeat synthetic rows: they lie on the training data (distance 0).
  EXPECT_TRUE(contains(markdown, "fixed → normal / normal (1000, d 0.0)")) << markdown;
  ASSERT_EQ(holdout.nearest_training_distance.size(), 24u);
  for (size_t r = 0; r < 24; ++r) {
    if (corpus.model[static_cast<size_t>(holdout.rows[r])] == "real_contrary") {
      EXPECT_DOUBLE_EQ(holdout.nearest_training_distance[r], 0.0);
    }
  }
  EXPECT_TRUE(contains(markdown, "By distance to the nearest training cluster"));
}

TEST(NearestRowDistances, InStandardDeviationsOfTheTrainingRows) {
  // Training: x in {0, 2} (mean 1, deviation 1), y constant (scale 1). A query at x = 5
  // lies 3 standard deviations from the row at 2; one at the row at 0, 0.
  Eigen::MatrixXd training(2, 2), queries(3, 2);
  training << 0, 7, 2, 7;
  queries << 5, 7, 0, 7, 2, 9;
  std::vector<double> distance = nearest_row_distances(training, queries);
  ASSERT_EQ(distance.size(), 3u);
  EXPECT_NEAR(distance[0], 3.0, 1e-6);
  EXPECT_NEAR(distance[1], 0.0, 1e-6);
  EXPECT_NEAR(distance[2], 2.0, 1e-6);  // a constant column keeps scale 1
  EXPECT_THROW(nearest_row_distances(Eigen::MatrixXd(0, 2), queries), Error);
  EXPECT_THROW(nearest_row_distances(training, Eigen::MatrixXd(1, 3)), Error);
}

TEST(LeaveOneModelOut, DecidedStylesTakeThePlaceOfBothClassifiers) {
  Corpus corpus = corpus_with_a_contrary_real_model();
  std::vector<int32_t> decided(corpus.model.size(), -1);
  for (size_t row = 0; row < decided.size(); ++row)
    if (corpus.model[row] == "real_contrary") decided[row] = 1;  // what the rule says
  ModelHoldout holdout = leave_one_model_out(corpus.data.features, corpus.data.labels, corpus.model,
                                             corpus.real, corpus.strands, quick_params(), decided);
  for (size_t row = 0; row < holdout.rows.size(); ++row) {
    bool contrary = corpus.model[static_cast<size_t>(holdout.rows[row])] == "real_contrary";
    EXPECT_EQ(holdout.ruled[row], contrary ? 1 : 0);
    if (contrary) {
      EXPECT_EQ(holdout.forest[row], 1);
      EXPECT_EQ(holdout.svm[row], 1);
    }
  }
  EXPECT_GE(holdout.forest_scores.confusion(1, 1), 12000);  // and the true fixed ones
  std::vector<int32_t> cluster(corpus.model.size(), 3);
  EXPECT_TRUE(
      contains(model_holdout_markdown(holdout, cluster), "3 fixed → fixed by rule (1000, d 0.0)"));
  std::vector<int32_t> too_few(3, -1);
  EXPECT_THROW(leave_one_model_out(corpus.data.features, corpus.data.labels, corpus.model,
                                   corpus.real, corpus.strands, quick_params(), too_few),
               Error);
}

TEST(LeaveOneModelOut, WhereFixedIsRuledOutTheClassifiersGiveTheirBestOtherClass) {
  Corpus corpus = corpus_with_a_contrary_real_model();
  // Rule fixed (1) out for the real rows of fixed's blob: both classifiers call them fixed
  // without the flags, something else with them; every other row as before.
  std::vector<uint8_t> not_fixed(corpus.model.size(), 0);
  for (size_t row = 0; row < not_fixed.size(); ++row)
    if (corpus.real[row] && corpus.model[row] != "real_contrary" && corpus.data.labels[row] == 1)
      not_fixed[row] = 1;
  ModelHoldout plain = leave_one_model_out(corpus.data.features, corpus.data.labels, corpus.model,
                                           corpus.real, corpus.strands, quick_params());
  ModelHoldout ruled =
      leave_one_model_out(corpus.data.features, corpus.data.labels, corpus.model, corpus.real,
                          corpus.strands, quick_params(), {}, not_fixed);
  ASSERT_EQ(plain.rows, ruled.rows);
  int flagged = 0;
  for (size_t row = 0; row < ruled.rows.size(); ++row) {
    const bool flag = not_fixed[static_cast<size_t>(ruled.rows[row])] != 0;
    EXPECT_EQ(ruled.fixed_ruled_out[row], flag ? 1 : 0);
    if (flag) {
      ++flagged;
      EXPECT_EQ(plain.svm[row], 1);
      EXPECT_EQ(plain.forest[row], 1);
      EXPECT_NE(ruled.svm[row], 1);
      EXPECT_NE(ruled.forest[row], 1);
    } else {
      EXPECT_EQ(ruled.svm[row], plain.svm[row]);
      EXPECT_EQ(ruled.forest[row], plain.forest[row]);
    }
  }
  EXPECT_GE(flagged, 1);
  std::vector<int32_t> cluster(corpus.model.size(), 3);
  EXPECT_TRUE(contains(model_holdout_markdown(ruled, cluster), ", not fixed by rule ("));
  std::vector<uint8_t> too_few(3, 0);
  EXPECT_THROW(leave_one_model_out(corpus.data.features, corpus.data.labels, corpus.model,
                                   corpus.real, corpus.strands, quick_params(), {}, too_few),
               Error);
}

TEST(LeaveOneModelOut, RefusesMismatchedInputsAndNothingToHoldOut) {
  Corpus corpus = corpus_with_a_contrary_real_model();
  std::vector<bool> none(corpus.real.size(), false);
  EXPECT_THROW(leave_one_model_out(corpus.data.features, corpus.data.labels, corpus.model, none,
                                   corpus.strands, quick_params()),
               Error);
  std::vector<double> short_weights(3, 1.0);
  EXPECT_THROW(leave_one_model_out(corpus.data.features, corpus.data.labels, corpus.model,
                                   corpus.real, short_weights, quick_params()),
               Error);
}

}  // namespace
}  // namespace hair
