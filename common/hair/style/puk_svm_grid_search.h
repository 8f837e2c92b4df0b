#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "hair/style/feature_standardization.h"
#include "hair/style/puk_svm.h"

namespace hair {

/// The candidate SVM settings, every combination of the three lists (96 by default). On
/// standardised features the distance of two rows is about sqrt(2 d): 3 for the paper's 5
/// features, 20 for the 190 raw ones; sigma (the kernel's full width at half height)
/// spans both. omega from Cauchy-like tails (0.5, 1) to nearly Gaussian (5); C over four
/// decades.
struct PukSvmGrid {
  std::vector<double> sigma = {0.5, 1, 2, 4, 8, 16};
  std::vector<double> omega = {0.5, 1, 2, 5};
  std::vector<double> c = {0.1, 1, 10, 100};
};

/// Throws hair::Error (usage) for an empty list or a value that is not finite and positive.
void check_puk_svm_grid(const PukSvmGrid& grid);

/// The grid's candidates in the order of preference among equals: C ascending, then sigma
/// descending, then omega ascending (the most regularised, smoothest candidate first).
std::vector<PukSvmParams> puk_svm_candidates(const PukSvmGrid& grid);

/// The candidate chosen by a grid search.
struct PukSvmSelection {
  PukSvmParams params;
  int correct = 0;  ///< rows its inner cross-validation classified right
  int rows = 0;     ///< rows of the inner cross-validation
  double accuracy() const { return rows > 0 ? static_cast<double>(correct) / rows : 0.0; }
};

/// The grid search for the PUK SVM: each candidate is scored by a stratified
/// min(folds, n)-fold cross-validation on `rows` (n x d, standardised) with
/// `labels` (n), folds drawn from `seed` (stratified_folds), the same folds for every
/// candidate; the candidate of most correct predictions wins, the first in
/// puk_svm_candidates() order among equals. Candidates run in parallel (OpenMP); the
/// result does not depend on the thread count. A single row: the first candidate, unscored.
///
/// Throws hair::Error: usage for a bad grid, no rows, or folds < 2.
PukSvmSelection selected_puk_svm_params(const FloatRows& rows, std::span<const int32_t> labels,
                                        const PukSvmGrid& grid, int folds, uint64_t seed);

}  // namespace hair
