#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "hair/style/style_model_holdout.h"

namespace hair {

/// Leave-one-model-out evaluations of one table, each with its own seed: the SVM's inner
/// grid-search folds are drawn afresh; the held-out models, the training rows and the
/// forests' own seed (RandomForestParams::seed) are the same. How much the real meshes' figure owes
/// to that draw (a cluster far from every training row can go either way).
struct RepeatedModelHoldout {
  std::vector<uint64_t> seeds;        ///< per repeat
  std::vector<ModelHoldout> repeats;  ///< per repeat, as leave_one_model_out()
};

/// `repeats` leave_one_model_out() evaluations, the r-th with params.seed + r; the first
/// is exactly leave_one_model_out() with params. Arguments as there. Throws hair::Error
/// (usage) for repeats < 1, and as leave_one_model_out() does.
RepeatedModelHoldout repeated_leave_one_model_out(
    const Eigen::MatrixXd& features, std::span<const int32_t> labels,
    const std::vector<std::string>& model_of_row, const std::vector<bool>& held_out,
    std::span<const double> weight, const StyleClassifierParams& params, int repeats,
    std::span<const int32_t> decided = {}, std::span<const uint8_t> fixed_ruled_out = {});

/// The repeats as Markdown: per classifier, the share of held-out strands right (mean,
/// standard deviation, least, largest, every repeat's in seed order), then per held-out
/// model the share of its strands each classifier got right, mean and range over the
/// repeats. Empty for no repeats.
std::string repeated_model_holdout_markdown(const RepeatedModelHoldout& result);

}  // namespace hair
