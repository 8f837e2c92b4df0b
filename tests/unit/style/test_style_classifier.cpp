// The style classifiers end to end: cross-validation, the trained model, its file.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "unit/feature_blobs.h"
#include "unit/file_test.h"
#include "hair/core/error.h"
#include "hair/style/hair_style.h"
#include "hair/style/style_classifier.h"
#include "hair/style/style_cross_validation.h"
#include "hair/style/style_cross_validation_markdown.h"
#include "hair/style/style_model_io.h"

namespace hair {
namespace {

using test::four_blobs;
using test::LabelledRows;

/// A small grid keeps the tests fast.
StyleClassifierParams quick_params() {
  StyleClassifierParams params;
  params.svm_grid = {{1, 4}, {1}, {1, 10}};
  params.forest.trees = 50;
  return params;
}

const std::vector<std::string> kNames = {"length_m", "count", "ratio"};

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(HairStyle, NamesRoundTrip) {
  for (HairStyle style :
       {HairStyle::normal, HairStyle::fixed, HairStyle::short_hair, HairStyle::braided})
    EXPECT_EQ(hair_style_from_name(hair_style_name(style)), style);
  EXPECT_STREQ(hair_style_name(HairStyle::short_hair), "short");
  EXPECT_FALSE(hair_style_from_name("short_hair"));
  EXPECT_STREQ(hair_style_name(static_cast<HairStyle>(9)), "unknown");
}

TEST(StyleCrossValidation, SeparatedBlobsAreClassifiedWell) {
  LabelledRows data = four_blobs(30, 0.6, 31);
  std::vector<bool> subset(data.labels.size(), false);
  for (size_t row = 0; row < subset.size(); row += 3) subset[row] = true;
  StyleCrossValidation result =
      style_cross_validation(data.features, data.labels, subset, quick_params());
  EXPECT_GT(result.svm.accuracy(), 0.95);
  EXPECT_GT(result.forest.accuracy(), 0.95);
  ASSERT_EQ(result.class_labels, (std::vector<int32_t>{0, 1, 2, 3}));
  ASSERT_EQ(result.svm_choice.size(), 10u);
  ASSERT_EQ(result.fold_rows.size(), 10u);
  int rows = 0;
  for (int count : result.fold_rows) rows += count;
  EXPECT_EQ(rows, 120);

  // The subset accuracy is that of the cross-validated predictions on the flagged rows.
  int subset_rows = 0, subset_correct = 0;
  for (size_t row = 0; row < subset.size(); ++row)
    if (subset[row]) {
      ++subset_rows;
      subset_correct += result.svm_predicted[row] == data.labels[row];
    }
  EXPECT_EQ(result.svm.subset_rows, subset_rows);
  EXPECT_EQ(result.svm.subset_correct, subset_correct);

  // Confusion rows sum to the class counts, its diagonal to the correct predictions.
  EXPECT_EQ(result.svm.confusion.sum(), 120);
  EXPECT_EQ(result.svm.confusion.trace(), result.svm.correct);
  for (int c = 0; c < 4; ++c) {
    EXPECT_EQ(result.forest.confusion.row(c).sum(), 30);
    EXPECT_EQ(result.forest.classes[static_cast<size_t>(c)].rows, 30);
    EXPECT_EQ(result.forest.confusion.col(c).sum(),
              result.forest.classes[static_cast<size_t>(c)].predicted);
  }

  std::string markdown = style_cross_validation_markdown(result, "real meshes");
  EXPECT_TRUE(contains(markdown, "| classifier | accuracy | real meshes |"));
  EXPECT_TRUE(contains(markdown, "| braided |"));
  EXPECT_TRUE(contains(markdown, "| short |"));
  EXPECT_TRUE(contains(markdown, "| fold | test rows | sigma | omega | C | inner accuracy |"));
}

TEST(StyleCrossValidation, RandomLabelsStayNearChance) {
  // Labels unrelated to the features: any accuracy well above 1/4 would mean the test
  // rows leaked into training or into the choice of the SVM's settings.
  LabelledRows data = four_blobs(50, 1.0, 32);
  std::mt19937_64 random(5);
  for (int32_t& label : data.labels) label = static_cast<int32_t>(random() % 4);
  StyleCrossValidation result =
      style_cross_validation(data.features, data.labels, {}, quick_params());
  EXPECT_LT(result.svm.accuracy(), 0.4);
  EXPECT_LT(result.forest.accuracy(), 0.4);
  EXPECT_EQ(result.svm.subset_rows, 0);
  EXPECT_FALSE(contains(style_cross_validation_markdown(result, "real meshes"), "real meshes"));
}

TEST(StyleCrossValidation, DeterministicWithATinyClassWhateverTheThreads) {
  LabelledRows data = four_blobs(20, 1.5, 33);
  data.labels[4] = data.labels[44] = data.labels[70] = 9;  // three rows for ten folds
  StyleCrossValidation first =
      style_cross_validation(data.features, data.labels, {}, quick_params());
  int threads = omp_get_max_threads();
  omp_set_num_threads(1);  // the grid search runs its candidates in parallel
  StyleCrossValidation second =
      style_cross_validation(data.features, data.labels, {}, quick_params());
  omp_set_num_threads(threads);
  EXPECT_EQ(first.fold, second.fold);
  EXPECT_EQ(first.svm_predicted, second.svm_predicted);
  EXPECT_EQ(first.forest_predicted, second.forest_predicted);
  for (size_t fold = 0; fold < first.svm_choice.size(); ++fold) {
    EXPECT_EQ(first.svm_choice[fold].params, second.svm_choice[fold].params);
    EXPECT_EQ(first.svm_choice[fold].correct, second.svm_choice[fold].correct);
  }
  EXPECT_EQ(first.class_labels.back(), 9);
  EXPECT_EQ(first.svm.classes.back().rows, 3);
}

TEST(StyleCrossValidation, RejectsNonFiniteFeatures) {
  LabelledRows data = four_blobs(10, 1.0, 34);
  data.features(5, 1) = std::numeric_limits<double>::quiet_NaN();
  try {
    style_cross_validation(data.features, data.labels, {}, quick_params());
    FAIL();
  } catch (const Error& error) {
    EXPECT_EQ(error.exit_code(), 2);
    EXPECT_TRUE(contains(error.what(), "feature row 5, column 1: NaN")) << error.what();
  }
  data.features(5, 1) = 0;
  data.features(7, 2) = -std::numeric_limits<double>::infinity();
  try {
    trained_style_model(data.features, data.labels, "test", kNames, quick_params());
    FAIL();
  } catch (const Error& error) {
    EXPECT_TRUE(contains(error.what(), "feature row 7, column 2 (ratio): -inf")) << error.what();
  }
}

class StyleModelTest : public test::FileTest {
 protected:
  StyleModelTest() : data_(four_blobs(25, 1.2, 35)) {
    model_ = trained_style_model(data_.features, data_.labels, "test", kNames, quick_params());
  }

  /// The model file's text with `from` replaced by `to` (which must be there).
  std::string edited_text(const std::string& from, const std::string& to) {
    std::string text = style_model_text(model_);
    size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
  }

  /// The one-line error message of reading `text`.
  std::string read_error(const std::string& text, const std::vector<std::string>& names = kNames) {
    try {
      style_model_from_text(text, "model.yml", names);
    } catch (const Error& error) {
      EXPECT_EQ(error.exit_code(), 2);
      EXPECT_FALSE(contains(error.what(), "\n"));
      return error.what();
    }
    ADD_FAILURE() << "no error";
    return {};
  }

  LabelledRows data_;
  StyleModel model_;
};

TEST_F(StyleModelTest, TrainedOnAllRows) {
  EXPECT_EQ(model_.training_rows, 100);
  EXPECT_EQ(model_.class_labels, (std::vector<int32_t>{0, 1, 2, 3}));
  EXPECT_EQ(model_.class_counts, (std::vector<int>{25, 25, 25, 25}));
  EXPECT_EQ(model_.svm_selection.rows, 100);
  int svm_correct = 0, forest_correct = 0;
  for (Eigen::Index row = 0; row < data_.features.rows(); ++row) {
    Eigen::VectorXd values = data_.features.row(row).transpose();
    StylePrediction prediction = style_prediction(model_, {values.data(), 3});
    svm_correct += prediction.svm_label == data_.labels[static_cast<size_t>(row)];
    forest_correct += prediction.forest_label == data_.labels[static_cast<size_t>(row)];
    EXPECT_EQ(prediction.label, prediction.svm_label);  // the default classifier
    EXPECT_EQ(prediction.svm_decision_values.size(), 6u);
    EXPECT_EQ(prediction.forest_vote_fraction.size(), 4u);
  }
  EXPECT_GT(svm_correct, 90);
  EXPECT_GT(forest_correct, 90);
}

/// Expects `a` and `b` to predict every row of `rows` alike; returns how many rows `a`'s SVM
/// gives `labels`.
int expect_same_predictions(const StyleModel& a, const StyleModel& b, const LabelledRows& rows) {
  int correct = 0;
  for (Eigen::Index row = 0; row < rows.features.rows(); ++row) {
    Eigen::VectorXd values = rows.features.row(row).transpose();
    StylePrediction first = style_prediction(a, {values.data(), 3});
    StylePrediction second = style_prediction(b, {values.data(), 3});
    EXPECT_EQ(first.svm_label, second.svm_label);
    EXPECT_EQ(first.svm_decision_values, second.svm_decision_values);
    EXPECT_EQ(first.forest_label, second.forest_label);
    EXPECT_EQ(first.forest_vote_fraction, second.forest_vote_fraction);
    correct += first.svm_label == rows.labels[static_cast<size_t>(row)];
  }
  return correct;
}

TEST_F(StyleModelTest, FileRoundTripPredictsTheSame) {
  std::filesystem::path path = directory_ / "model.yml";
  write_style_model(path, model_);
  StyleModel read = read_style_model(path, kNames);
  EXPECT_EQ(read.feature_set, "test");
  EXPECT_EQ(read.feature_names, kNames);
  EXPECT_EQ(read.class_counts, model_.class_counts);
  EXPECT_EQ(read.svm.params, model_.svm.params);
  EXPECT_EQ(read.forest_params, model_.forest_params);
  EXPECT_EQ(read.standardization.mean, model_.standardization.mean);
  EXPECT_EQ(read.standardization.scale, model_.standardization.scale);
  EXPECT_EQ(read.svm.support_vectors, model_.svm.support_vectors);
  EXPECT_EQ(style_model_text(read), style_model_text(model_));

  expect_same_predictions(model_, read, four_blobs(25, 2.5, 36));  // rows it has not seen
  std::string text = style_model_text(model_);
  EXPECT_TRUE(contains(text, "format: \"hairstyle.style_model\""));
  EXPECT_TRUE(contains(text, "version: 2"));
  EXPECT_TRUE(contains(text, "log_offset: [ 0., 0., 0. ]")) << text.substr(0, 600);
  EXPECT_TRUE(contains(text, "default_classifier: svm"));
}

// A model trained with a length on a log scale keeps the scale in its file and predicts
// the same read back.
TEST_F(StyleModelTest, FileRoundTripKeepsTheLogScale) {
  LabelledRows data = four_blobs(25, 1.2, 35);
  data.features.col(0) = data.features.col(0).array().exp().matrix();  // lengths: positive
  StyleClassifierParams params = quick_params();
  params.feature_log_offsets = {0.03, 0, 0};
  const StyleModel model = trained_style_model(data.features, data.labels, "test", kNames, params);
  ASSERT_EQ(model.standardization.log_offset.size(), 3);
  EXPECT_EQ(model.standardization.log_offset[0], 0.03);
  const std::filesystem::path path = directory_ / "log_model.yml";
  write_style_model(path, model);
  const StyleModel read = read_style_model(path, kNames);
  EXPECT_EQ(read.standardization.log_offset, model.standardization.log_offset);
  EXPECT_EQ(read.standardization.mean, model.standardization.mean);
  EXPECT_GT(expect_same_predictions(model, read, data),
            90);  // the blobs stay apart on the log scale of their first column
  // A negative log offset in the file is refused.
  std::string text = style_model_text(model);
  const size_t at = text.find("log_offset: [ ");
  ASSERT_NE(at, std::string::npos);
  text.insert(at + 14, "-");
  EXPECT_TRUE(contains(read_error(text), "model.yml:/standardization/log_offset"));
}

TEST_F(StyleModelTest, WrongVersionIsRejected) {
  std::string message = read_error(edited_text("version: 2", "version: 1"));
  EXPECT_EQ(message,
            "model.yml:/version: model version 1, this build reads version 2: retrain the model "
            "with this build");
}

TEST_F(StyleModelTest, WrongFormatIsRejected) {
  EXPECT_TRUE(
      contains(read_error(edited_text("hairstyle.style_model", "hairstyle.other")),
               "model.yml:/format: is 'hairstyle.other', expected 'hairstyle.style_model'"));
  EXPECT_TRUE(contains(read_error("%YAML:1.0\n---\nanswer: 42\n"), "model.yml:/format: missing"));
  EXPECT_TRUE(contains(read_error("not: [a, model"), "model.yml"));
  EXPECT_TRUE(contains(read_error(""), "model.yml"));
}

TEST_F(StyleModelTest, OtherFeatureNamesAreRejected) {
  std::vector<std::string> other = {"length_m", "count", "angle"};
  EXPECT_EQ(read_error(style_model_text(model_), other),
            "model.yml:/feature_names: the model's 3 features differ from the caller's 3 at "
            "feature 2: 'ratio' in the model, 'angle' given: retrain the model for these features");
  std::vector<std::string> longer = {"length_m", "count", "ratio", "extra"};
  EXPECT_TRUE(contains(read_error(style_model_text(model_), longer), "'extra' given"));
  // Empty: no check (a tool that only shows a model).
  EXPECT_NO_THROW(style_model_from_text(style_model_text(model_), "model.yml", {}));
}

TEST_F(StyleModelTest, MissingOrBrokenEntriesAreNamed) {
  EXPECT_TRUE(
      contains(read_error(edited_text("   sigma:", "   sigmo:")), "model.yml:/svm/sigma: missing"));
  EXPECT_TRUE(contains(read_error(edited_text("random_forest:\n", "random_wood:\n")),
                       "model.yml:/random_forest: missing"));
  EXPECT_TRUE(contains(read_error(edited_text("default_classifier: svm",
                                              "default_classifier: perceptron")),
                       "/default_classifier: is 'perceptron'"));
  EXPECT_THROW(read_style_model(directory_ / "absent.yml", kNames), Error);
}

TEST_F(StyleModelTest, PredictionRejectsBadRows) {
  std::vector<double> short_row = {1.0, 2.0};
  EXPECT_THROW(style_prediction(model_, short_row), Error);
  std::vector<double> infinite = {1.0, std::numeric_limits<double>::infinity(), 0.0};
  try {
    style_prediction(model_, infinite);
    FAIL();
  } catch (const Error& error) {
    EXPECT_TRUE(contains(error.what(), "(count): +inf")) << error.what();
  }
}

}  // namespace
}  // namespace hair
