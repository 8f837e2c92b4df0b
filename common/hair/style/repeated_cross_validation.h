#pragma once
// Repeated cross-validation of the style classifiers: the same k folds drawn again with
// other seeds, so that an accuracy is read with the spread that the draw of folds alone
// gives it (one 10-fold run of our 1,049 clusters moves by about half a point from one
// draw to the next, docs/classify.md). Weka's Experimenter repeats 10-fold
// cross-validation ten times for that reason, after Bouckaert & Frank 2004, "Evaluating
// the replicability of significance tests for comparing learning algorithms".

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hair/style/style_classifier_params.h"
#include "hair/style/style_cross_validation.h"

namespace hair {

/// Cross-validations of one table, each with its own draw of folds.
struct RepeatedCrossValidation {
  std::vector<uint64_t> seeds;                ///< per repeat, the seed its folds were drawn with
  std::vector<StyleCrossValidation> repeats;  ///< per repeat, as style_cross_validation()
};

/// Mean, sample standard deviation (n - 1; 0 for one value), least and largest of a list of
/// accuracies; all 0 for an empty list.
struct AccuracySpread {
  double mean = 0;
  double standard_deviation = 0;
  double min = 0;
  double max = 0;
};
AccuracySpread accuracy_spread(std::span<const double> accuracies);

/// The settings of `repeats` repeats: copies of `params` whose seed is params.seed + r for
/// r = 0, 1, ... (the first is `params` itself). Throws hair::Error (usage), naming `what`,
/// for repeats < 1.
std::vector<StyleClassifierParams> seeded_repeats(const StyleClassifierParams& params, int repeats,
                                                  std::string_view what);

/// Folds for a repeat drawn with `seed` (e.g. grouped_folds(models, folds, seed)); empty
/// function: stratified folds of the labels, as style_cross_validation() draws them.
using FoldsForSeed = std::function<std::vector<int32_t>(uint64_t seed)>;

/// `repeats` cross-validations (style_cross_validation) of the same rows, the r-th with
/// params.seed + r: its folds (stratified, or `folds_for_seed`), its inner grid-search
/// folds and its forests are drawn afresh. The first repeat is exactly the single
/// cross-validation with params. Throws hair::Error usage for repeats < 1, and as
/// style_cross_validation() does.
RepeatedCrossValidation repeated_style_cross_validation(const Eigen::MatrixXd& features,
                                                        std::span<const int32_t> labels,
                                                        const std::vector<bool>& subset,
                                                        const StyleClassifierParams& params,
                                                        int repeats,
                                                        const FoldsForSeed& folds_for_seed = {});

/// The repeats as a Markdown table: per classifier (and per classifier on the subset,
/// titled `subset_name`, when it has rows) the mean accuracy, its standard deviation,
/// least and largest, and every repeat's accuracy in seed order.
std::string repeated_cross_validation_markdown(const RepeatedCrossValidation& result,
                                               std::string_view subset_name);

}  // namespace hair
