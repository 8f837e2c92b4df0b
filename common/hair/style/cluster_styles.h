#pragma once
// The hairstyle of every cluster of grown strands by a trained style model (paper
// section 5.1): the classify stage's algorithm.

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

#include "hair/style/decisive_style_rules.h"
#include "hair/style/style_classifier.h"
#include "hair/style/style_features.h"

namespace hair {

/// What both classifiers say about every cluster.
struct ClusterStyles {
  StyleClassifierKind classifier = StyleClassifierKind::random_forest;  ///< behind `style`
  std::vector<int32_t> classes;          ///< k, the model's classes (HairStyle values), ascending
  std::vector<int8_t> style;             ///< per cluster: the chosen classifier's class; -1 none
  std::vector<int8_t> svm_style;         ///< per cluster; -1 for a cluster without strands
  std::vector<int8_t> forest_style;      ///< per cluster; -1 for a cluster without strands
  Eigen::MatrixXd svm_decision_values;   ///< #clusters x k (k - 1) / 2, 0 where not classified
  Eigen::MatrixXi svm_votes;             ///< #clusters x k
  Eigen::MatrixXd forest_vote_fraction;  ///< #clusters x k
  /// Per cluster, how sure the chosen classifier is of `style`, in [0, 1]: the SVM's
  /// margin (svm_margin_confidence), or the random forest's vote share of that class; 0
  /// for a cluster without a style. A pinned cluster (style_overrides.h) keeps what the
  /// classifier's confidence was in its own answer.
  std::vector<double> confidence;
  /// Per cluster, 1 where a user pinned its style (classify --overrides).
  std::vector<uint8_t> pinned;
  /// Per cluster, 1 where the paper's criteria decided its style (decisive_style_rules.h);
  /// its confidence is then 1, and svm_style and forest_style still say what the
  /// classifiers would have given.
  std::vector<uint8_t> ruled;
  /// Per cluster, 1 where the paper's criteria rule fixed out (fixed_ruled_out()): `style`
  /// is then the chosen classifier's best other class (svm_label_without,
  /// forest_label_without) where it said fixed, its confidence that of the contests
  /// between the other classes; svm_style and forest_style still say what the classifiers
  /// gave.
  std::vector<uint8_t> fixed_ruled_out;
};

/// Below this confidence a cluster's style is called unsure (styles.h5 /clusters/unsure,
/// the picture, the stage's log) by default: the random forest gave the style fewer than
/// three votes in five.
inline constexpr double kDefaultUnsureBelow = 0.6;

/// How sure the SVM is of class index `chosen` (into svm.class_labels) for a row whose
/// one-vs-one decision values (in svm.decision_functions' order) are given: the smallest
/// of its pairwise decision values, signed for it, clipped to [0, 1]. A C-SVC's decision
/// function is 1 on its margin, so 1 means the row lies beyond the margin of every
/// contest the class won, and values towards 0 that it is near a boundary (0 as well
/// where it lost a contest and still won the vote). Unlike the share of won contests,
/// which is 1 for nearly every row, this grades the answer.
double svm_margin_confidence(const PukSvm& svm, std::span<const double> decision_values,
                             size_t chosen);
/// The same over the contests against classes other than index `excluded` (into
/// svm.class_labels), which was ruled out.
double svm_margin_confidence_without(const PukSvm& svm, std::span<const double> decision_values,
                                     size_t chosen, size_t excluded);

/// Classifies every cluster that grown strands run through by its features of the
/// model's feature set (feature_set_rows(); their names must be the model's); a cluster
/// without strands gets no style (-1). `classifier` picks which classifier's class is
/// `style`; where `rules` decide (decisive_style()), they give the style instead, and
/// where they rule fixed out (fixed_ruled_out()), a classifier's fixed gives way to its
/// best other class.
ClusterStyles cluster_styles(const StyleFeatures& features, const StyleModel& model,
                             StyleClassifierKind classifier, const DecisiveStyleRules& rules);

}  // namespace hair
