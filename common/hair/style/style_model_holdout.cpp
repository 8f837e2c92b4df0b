#include "hair/style/style_model_holdout.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>

#include "hair/core/error.h"
#include "hair/style/feature_standardization.h"
#include "hair/style/hair_style.h"
#include "hair/style/style_held_out_prediction.h"

namespace hair {
namespace {

size_t class_index(std::span<const int32_t> class_labels, int32_t label) {
  auto found = std::find(class_labels.begin(), class_labels.end(), label);
  if (found == class_labels.end())
    throw Error::usage("weighted style scores: label " + std::to_string(label) +
                       " is not one of the classes");
  return static_cast<size_t>(found - class_labels.begin());
}

std::string percent(double part, double whole) {
  if (whole <= 0) return "–";
  return fmt::format("{:.1f}%", 100.0 * part / whole);
}

void append_weighted_confusion(std::string& text, const char* title,
                               const WeightedStyleScores& scores) {
  text +=
      fmt::format("{} (strands; rows: truth, columns: predicted)\n\n| truth \\ predicted |", title);
  for (int32_t label : scores.class_labels)
    text += fmt::format(" {} |", hair_style_label_text(label));
  text += "\n|---|";
  for (size_t c = 0; c < scores.class_labels.size(); ++c) text += "---:|";
  text += "\n";
  for (Eigen::Index truth = 0; truth < scores.confusion.rows(); ++truth) {
    text += fmt::format("| {} |",
                        hair_style_label_text(scores.class_labels[static_cast<size_t>(truth)]));
    for (Eigen::Index predicted = 0; predicted < scores.confusion.cols(); ++predicted)
      text += fmt::format(" {:.0f} |", scores.confusion(truth, predicted));
    text += "\n";
  }
  text += "\n";
}

}  // namespace

double WeightedStyleScores::recall(size_t c) const {
  auto i = static_cast<Eigen::Index>(c);
  double whole = confusion.row(i).sum();
  return whole > 0 ? confusion(i, i) / whole : 0;
}

double WeightedStyleScores::precision(size_t c) const {
  auto i = static_cast<Eigen::Index>(c);
  double whole = confusion.col(i).sum();
  return whole > 0 ? confusion(i, i) / whole : 0;
}

WeightedStyleScores weighted_style_scores(std::span<const int32_t> truth,
                                          std::span<const int32_t> predicted,
                                          std::span<const double> weight,
                                          std::span<const int32_t> class_labels) {
  if (truth.size() != predicted.size() || truth.size() != weight.size())
    throw Error::usage("weighted style scores: " + std::to_string(truth.size()) + " truths, " +
                       std::to_string(predicted.size()) + " predictions and " +
                       std::to_string(weight.size()) + " weights");
  WeightedStyleScores scores;
  scores.class_labels.assign(class_labels.begin(), class_labels.end());
  auto k = static_cast<Eigen::Index>(class_labels.size());
  scores.confusion = Eigen::MatrixXd::Zero(k, k);
  for (size_t i = 0; i < truth.size(); ++i) {
    if (!(weight[i] >= 0))
      throw Error::usage("weighted style scores: weight " + std::to_string(weight[i]) + " of row " +
                         std::to_string(i));
    scores.confusion(static_cast<Eigen::Index>(class_index(class_labels, truth[i])),
                     static_cast<Eigen::Index>(class_index(class_labels, predicted[i]))) +=
        weight[i];
  }
  return scores;
}

ModelHoldout leave_one_model_out(const Eigen::MatrixXd& features, std::span<const int32_t> labels,
                                 const std::vector<std::string>& model_of_row,
                                 const std::vector<bool>& held_out, std::span<const double> weight,
                                 const StyleClassifierParams& params,
                                 std::span<const int32_t> decided,
                                 std::span<const uint8_t> fixed_ruled_out) {
  auto n = labels.size();
  if (static_cast<size_t>(features.rows()) != n || model_of_row.size() != n ||
      held_out.size() != n || weight.size() != n || (!decided.empty() && decided.size() != n) ||
      (!fixed_ruled_out.empty() && fixed_ruled_out.size() != n))
    throw Error::usage(
        "leave-one-model-out: " + std::to_string(features.rows()) + " feature rows, " +
        std::to_string(n) + " labels, " + std::to_string(model_of_row.size()) + " models, " +
        std::to_string(held_out.size()) + " flags, " + std::to_string(weight.size()) +
        " weights, " + std::to_string(decided.size()) + " decided styles and " +
        std::to_string(fixed_ruled_out.size()) + " fixed-ruled-out flags");
  ModelHoldout result;
  for (size_t i = 0; i < n; ++i)
    if (held_out[i]) result.models.push_back(model_of_row[i]);
  std::sort(result.models.begin(), result.models.end());
  result.models.erase(std::unique(result.models.begin(), result.models.end()), result.models.end());
  if (result.models.empty()) throw Error::usage("leave-one-model-out: no model to hold out");

  std::vector<int32_t> class_labels(labels.begin(), labels.end());
  std::sort(class_labels.begin(), class_labels.end());
  class_labels.erase(std::unique(class_labels.begin(), class_labels.end()), class_labels.end());

  for (size_t m = 0; m < result.models.size(); ++m) {
    std::vector<Eigen::Index> train, test;
    for (size_t i = 0; i < n; ++i)
      (model_of_row[i] == result.models[m] ? test : train).push_back(static_cast<Eigen::Index>(i));
    HeldOutPrediction prediction =
        held_out_prediction(features, labels, train, test, params,
                            params.seed + 1 + static_cast<uint64_t>(m), fixed_ruled_out);
    std::vector<double> distance = nearest_row_distances(
        features(train, Eigen::all), features(test, Eigen::all), params.feature_log_offsets);
    for (size_t i = 0; i < test.size(); ++i) {
      auto row = static_cast<size_t>(test[i]);
      bool ruled = !decided.empty() && decided[row] >= 0;
      result.rows.push_back(test[i]);
      result.truth.push_back(labels[row]);
      result.svm.push_back(ruled ? decided[row] : prediction.svm[i]);
      result.forest.push_back(ruled ? decided[row] : prediction.forest[i]);
      result.weight.push_back(weight[row]);
      result.ruled.push_back(ruled ? 1 : 0);
      result.fixed_ruled_out.push_back(
          !ruled && !fixed_ruled_out.empty() && fixed_ruled_out[row] ? 1 : 0);
      result.nearest_training_distance.push_back(distance[i]);
    }
    result.model_rows.push_back(static_cast<int>(test.size()));
    result.svm_choice.push_back(prediction.svm_choice);
  }
  result.svm_scores = weighted_style_scores(result.truth, result.svm, result.weight, class_labels);
  result.forest_scores =
      weighted_style_scores(result.truth, result.forest, result.weight, class_labels);
  return result;
}

std::vector<double> nearest_row_distances(const Eigen::MatrixXd& training,
                                          const Eigen::MatrixXd& queries,
                                          std::span<const double> log_offsets) {
  if (training.rows() == 0 || training.cols() != queries.cols())
    throw Error::usage("nearest row distances: " + std::to_string(training.rows()) + " x " +
                       std::to_string(training.cols()) + " training rows, " +
                       std::to_string(queries.cols()) + " query columns");
  FeatureStandardization standardization = feature_standardization(training, log_offsets);
  FloatRows train = standardized_rows(standardization, training);
  FloatRows query = standardized_rows(standardization, queries);
  std::vector<double> distance(static_cast<size_t>(queries.rows()));
  for (Eigen::Index q = 0; q < query.rows(); ++q)
    distance[static_cast<size_t>(q)] = std::sqrt(
        static_cast<double>((train.rowwise() - query.row(q)).rowwise().squaredNorm().minCoeff()));
  return distance;
}

std::string model_holdout_markdown(const ModelHoldout& holdout,
                                   std::span<const int32_t> cluster_of_row) {
  std::vector<double> ones(holdout.truth.size(), 1.0);
  const std::vector<int32_t>& classes = holdout.forest_scores.class_labels;
  WeightedStyleScores svm_clusters =
      weighted_style_scores(holdout.truth, holdout.svm, ones, classes);
  WeightedStyleScores forest_clusters =
      weighted_style_scores(holdout.truth, holdout.forest, ones, classes);
  std::string text = fmt::format(
      "Leave one model out: {} models held out in turn, {} clusters, {:.0f} strands\n\n"
      "| classifier | strands right | clusters right |\n|---|---:|---:|\n",
      holdout.models.size(), holdout.truth.size(), holdout.forest_scores.total());
  text += fmt::format("| SVM (PUK kernel) | {} | {} ({:.0f} / {}) |\n",
                      percent(holdout.svm_scores.correct(), holdout.svm_scores.total()),
                      percent(svm_clusters.correct(), svm_clusters.total()), svm_clusters.correct(),
                      holdout.truth.size());
  text += fmt::format("| random forest | {} | {} ({:.0f} / {}) |\n\n",
                      percent(holdout.forest_scores.correct(), holdout.forest_scores.total()),
                      percent(forest_clusters.correct(), forest_clusters.total()),
                      forest_clusters.correct(), holdout.truth.size());
  text +=
      "| class | strands | SVM precision | SVM recall | forest precision | forest recall |\n"
      "|---|---:|---:|---:|---:|---:|\n";
  for (size_t c = 0; c < classes.size(); ++c) {
    auto i = static_cast<Eigen::Index>(c);
    const WeightedStyleScores& svm = holdout.svm_scores;
    const WeightedStyleScores& forest = holdout.forest_scores;
    text += fmt::format("| {} | {:.0f} | {} | {} | {} | {} |\n", hair_style_label_text(classes[c]),
                        forest.confusion.row(i).sum(),
                        percent(svm.confusion(i, i), svm.confusion.col(i).sum()),
                        percent(svm.confusion(i, i), svm.confusion.row(i).sum()),
                        percent(forest.confusion(i, i), forest.confusion.col(i).sum()),
                        percent(forest.confusion(i, i), forest.confusion.row(i).sum()));
  }
  text += "\n";
  append_weighted_confusion(text, "SVM confusion", holdout.svm_scores);
  append_weighted_confusion(text, "Random forest confusion", holdout.forest_scores);

  // Accuracy by how far the held-out clusters lie from the training rows.
  if (holdout.nearest_training_distance.size() == holdout.truth.size()) {
    text +=
        "By distance to the nearest training cluster (standardised features; the classifiers "
        "learnt nothing near a far cluster)\n\n| distance | clusters | strands | SVM strands "
        "right | forest strands right |\n|---|---:|---:|---:|---:|\n";
    const std::array<double, 5> bounds = {0.0, 1.0, 2.0, 3.0, 1e300};
    for (size_t b = 0; b + 1 < bounds.size(); ++b) {
      double strands = 0, svm_right = 0, forest_right = 0;
      int clusters = 0;
      for (size_t r = 0; r < holdout.truth.size(); ++r) {
        double d = holdout.nearest_training_distance[r];
        if (d < bounds[b] || d >= bounds[b + 1]) continue;
        double w = holdout.weight[r];
        ++clusters;
        strands += w;
        svm_right += holdout.svm[r] == holdout.truth[r] ? w : 0;
        forest_right += holdout.forest[r] == holdout.truth[r] ? w : 0;
      }
      std::string range = b + 2 < bounds.size()
                              ? fmt::format("{:.0f}-{:.0f}", bounds[b], bounds[b + 1])
                              : fmt::format("{:.0f} or more", bounds[b]);
      text += fmt::format("| {} | {} | {:.0f} | {} | {} |\n", range, clusters, strands,
                          percent(svm_right, strands), percent(forest_right, strands));
    }
    text += "\n";
  }

  text +=
      "Per held-out model: each cluster as `id truth → forest / SVM (strands, distance to the "
      "nearest training cluster)`; `by rule` where the paper's criteria decided its style, `not "
      "fixed by rule` where they ruled fixed out and the classifiers chose among the other "
      "styles\n\n"
      "| model | strands right (forest) | strands right (SVM) | clusters |\n|---|---:|---:|---|\n";
  size_t row = 0;
  for (size_t m = 0; m < holdout.models.size(); ++m) {
    double total = 0, forest_right = 0, svm_right = 0;
    std::string clusters;
    for (int r = 0; r < holdout.model_rows[m]; ++r, ++row) {
      double w = holdout.weight[row];
      total += w;
      forest_right += holdout.forest[row] == holdout.truth[row] ? w : 0;
      svm_right += holdout.svm[row] == holdout.truth[row] ? w : 0;
      if (!clusters.empty()) clusters += ", ";
      int32_t cluster = cluster_of_row[static_cast<size_t>(holdout.rows[row])];
      std::string distance = row < holdout.nearest_training_distance.size()
                                 ? fmt::format(", d {:.1f}", holdout.nearest_training_distance[row])
                                 : "";
      clusters +=
          holdout.ruled[row]
              ? fmt::format("{} {} → {} by rule ({:.0f}{})", cluster,
                            hair_style_label_text(holdout.truth[row]),
                            hair_style_label_text(holdout.svm[row]), w, distance)
              : fmt::format("{} {} → {} / {}{} ({:.0f}{})", cluster,
                            hair_style_label_text(holdout.truth[row]),
                            hair_style_label_text(holdout.forest[row]),
                            hair_style_label_text(holdout.svm[row]),
                            row < holdout.fixed_ruled_out.size() && holdout.fixed_ruled_out[row]
                                ? ", not fixed by rule"
                                : "",
                            w, distance);
    }
    // A model is named by its folder; its last part says which.
    std::string name = std::filesystem::path(holdout.models[m]).filename().string();
    text += fmt::format("| {} | {} | {} | {} |\n", name, percent(forest_right, total),
                        percent(svm_right, total), clusters);
  }
  return text;
}

}  // namespace hair
