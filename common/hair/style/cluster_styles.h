#pragma once
// The hairstyle of every cluster of grown strands by a trained style model (paper
// section 5.1): the classify stage's algorithm.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

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
};

/// Classifies every cluster that grown strands run through by its features of the
/// model's feature set (feature_set_rows(); their names must be the model's); a cluster
/// without strands gets no style (-1). `classifier` picks which classifier's class is
/// `style`.
ClusterStyles cluster_styles(const StyleFeatures& features, const StyleModel& model,
                             StyleClassifierKind classifier);

}  // namespace hair
