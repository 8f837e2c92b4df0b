#pragma once
// Leave-one-model-out evaluation of the style classifiers on real meshes (issue 26): every
// held-out mesh's clusters are classified by classifiers trained on everything else, and
// the figure is the share of its strands that get the style a person gave them.

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "hair/style/puk_svm_grid_search.h"
#include "hair/style/style_classifier_params.h"

namespace hair {

/// Predictions scored with a weight per row (a cluster's strands): a k x k confusion of
/// weights, rows the truth, columns the prediction, over `class_labels`.
struct WeightedStyleScores {
  std::vector<int32_t> class_labels;
  Eigen::MatrixXd confusion;
  double total() const { return confusion.sum(); }
  double correct() const { return confusion.trace(); }
  double accuracy() const { return total() > 0 ? correct() / total() : 0; }
  /// Weight of class c (index into class_labels) predicted as c, over the weight of class c.
  double recall(size_t c) const;
  /// Weight of class c predicted as c, over the weight predicted as c.
  double precision(size_t c) const;
};

/// Scores `predicted` against `truth`, each row weighing `weight` (non-negative). A label
/// outside class_labels throws hair::Error (usage), as do lengths that differ.
WeightedStyleScores weighted_style_scores(std::span<const int32_t> truth,
                                          std::span<const int32_t> predicted,
                                          std::span<const double> weight,
                                          std::span<const int32_t> class_labels);

/// What a leave-one-model-out evaluation found.
struct ModelHoldout {
  std::vector<std::string> models;          ///< the held-out models, ascending
  std::vector<int> model_rows;              ///< per held-out model, its rows
  std::vector<Eigen::Index> rows;           ///< the held-out rows, model by model
  std::vector<int32_t> truth;               ///< per held-out row
  std::vector<int32_t> svm;                 ///< per held-out row, the SVM's prediction
  std::vector<int32_t> forest;              ///< per held-out row, the random forest's
  std::vector<double> weight;               ///< per held-out row
  std::vector<uint8_t> ruled;               ///< per held-out row, 1 where `decided` gave its style
  /// Per held-out row, 1 where `fixed_ruled_out` held (fixed was not a choice there).
  std::vector<uint8_t> fixed_ruled_out;
  /// Per held-out row: the Euclidean distance to the nearest training row of its fold, in
  /// features standardised on those training rows (standard deviations): how far the
  /// cluster lies from anything the classifiers learnt from.
  std::vector<double> nearest_training_distance;
  std::vector<PukSvmSelection> svm_choice;  ///< per held-out model
  WeightedStyleScores svm_scores, forest_scores;  ///< over the held-out rows
};

/// Holds out each model with a flagged row in turn: both classifiers (held_out_prediction)
/// are trained on the rows of every other model, synthetic and flagged alike, and
/// predict the held-out model's rows.
///
///   @param[in] features  n x d, finite
///   @param[in] labels  n class labels
///   @param[in] model_of_row  n model names
///   @param[in] held_out  n flags: the models of flagged rows are held out (the real meshes)
///   @param[in] weight  n non-negative weights (strands)
///   @param[in] decided  n styles decided without training (the paper's criteria,
///       decisive_style_rules.h), -1 where none; where one is given it is both
///       classifiers' answer, as in classify. Empty: none.
///   @param[in] fixed_ruled_out  n flags (fixed_ruled_out_of_rows), or empty: where set, a
///       classifier that says fixed gives its best other class instead, as in classify.
///
/// Deterministic. Throws hair::Error (usage) for lengths that differ or no flagged row.
ModelHoldout leave_one_model_out(const Eigen::MatrixXd& features, std::span<const int32_t> labels,
                                 const std::vector<std::string>& model_of_row,
                                 const std::vector<bool>& held_out, std::span<const double> weight,
                                 const StyleClassifierParams& params,
                                 std::span<const int32_t> decided = {},
                                 std::span<const uint8_t> fixed_ruled_out = {});

/// Per row of `queries` (m x d), the Euclidean distance to the nearest row of `training`
/// (n x d, n >= 1), both standardised on `training` (feature_standardization(), with
/// `log_offsets`).
std::vector<double> nearest_row_distances(const Eigen::MatrixXd& training,
                                          const Eigen::MatrixXd& queries,
                                          std::span<const double> log_offsets = {});

/// The evaluation as Markdown: accuracy weighted by strands and by clusters, per-class
/// recall and precision (strands), the confusion in strands, the accuracy by distance to
/// the nearest training row, and per model what each cluster was given (marked "rule"
/// where the criteria decided) and how far it lies from the training rows. `cluster_of_row` (n)
/// names the clusters in the per-model table.
std::string model_holdout_markdown(const ModelHoldout& holdout,
                                   std::span<const int32_t> cluster_of_row);

}  // namespace hair
