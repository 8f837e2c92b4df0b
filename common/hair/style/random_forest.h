#pragma once

#include <cstdint>
#include <opencv2/ml.hpp>
#include <span>
#include <vector>

#include "hair/style/feature_standardization.h"

namespace hair {

/// Settings of the random forest (OpenCV's cv::ml::RTrees, Breiman's random forest). The
/// paper uses 100 trees (section 5.1); the rest follows Breiman: unpruned trees grown on
/// bootstrap samples, each split chosen among a random subset of the features.
struct RandomForestParams {
  int trees = 100;  ///< trees in the forest (>= 1); training stops at this count only
                    ///< (no out-of-bag early stop)
  /// Deepest a tree grows (1..20). 16 lets trees grow until their leaves are pure on a few
  /// hundred rows; OpenCV reserves 2^max_depth nodes per tree, so not much more.
  int max_depth = 16;
  /// A node of this many rows or fewer is a leaf (>= 1); 1 splits until leaves are pure.
  int min_sample_count = 1;
  /// Features drawn at each split; 0: round(sqrt(d)) (OpenCV's default, Breiman's choice).
  int active_var_count = 0;
  /// OpenCV draws the bootstrap samples and feature subsets from cv::theRNG(), which is
  /// set to cv::RNG(seed) before training (and restored after), so that a forest is the
  /// same at every training.
  uint64_t seed = 1;
  bool operator==(const RandomForestParams&) const = default;
};

/// Throws hair::Error (usage) naming the first setting outside its range.
void check_random_forest_params(const RandomForestParams& params);

/// A classification forest trained on `rows` (n x d) with `labels` (n). No variable
/// importance, no surrogate splits, no priors (every row weighs the same).
/// Throws hair::Error: usage for a bad setting, runtime when OpenCV fails.
cv::Ptr<cv::ml::RTrees> trained_random_forest(const FloatRows& rows,
                                              std::span<const int32_t> labels,
                                              const RandomForestParams& params);

/// What a forest says about one row.
struct ForestPrediction {
  int32_t label = 0;                  ///< the class of most votes (the lowest label of equals)
  std::vector<int32_t> votes;         ///< per class of `class_labels`: trees voting for it
  std::vector<double> vote_fraction;  ///< votes / trees
};

/// The votes of the trees of `forest` for `row` (d values) through RTrees::getVotes, over
/// `class_labels` (ascending; those the forest was trained on: a class the forest does not
/// know gets no votes). The label is the one RTrees::predict gives (most votes, ties to the
/// lower class index).
ForestPrediction forest_prediction(const cv::ml::RTrees& forest,
                                   std::span<const int32_t> class_labels, const float* row,
                                   int feature_count);

/// The class of most votes other than `excluded_label` (the lowest label of equals), as
/// forest_prediction() orders them; the label of most votes where no other class is there.
///   @param[in] class_labels  as given to forest_prediction()
///   @param[in] votes  per class, its votes or their share (ForestPrediction::vote_fraction)
int32_t forest_label_without(std::span<const int32_t> class_labels, std::span<const double> votes,
                             int32_t excluded_label);

}  // namespace hair
