#include "hair/style/puk_svm_grid_search.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <functional>
#include <string>

#include "hair/core/error.h"
#include "hair/style/stratified_folds.h"

namespace hair {
namespace {

/// Rows of a cross-validation of `params` classified right.
int cross_validated_correct(const FloatRows& rows, std::span<const int32_t> labels,
                            const std::vector<int32_t>& fold_of_row, int folds,
                            const PukSvmParams& params) {
  int correct = 0;
  for (int32_t fold = 0; fold < folds; ++fold) {
    std::vector<Eigen::Index> train = fold_row_indices(fold_of_row, fold, false);
    FloatRows train_rows = rows(train, Eigen::all);
    std::vector<int32_t> train_labels;
    for (Eigen::Index row : train) train_labels.push_back(labels[static_cast<size_t>(row)]);
    PukSvm svm = trained_puk_svm(train_rows, train_labels, params);
    for (Eigen::Index row : fold_row_indices(fold_of_row, fold, true))
      if (svm_prediction(svm, rows.row(row).data()).label == labels[static_cast<size_t>(row)])
        ++correct;
  }
  return correct;
}

void check_values(const std::vector<double>& values, const char* name) {
  if (values.empty())
    throw Error::usage(std::string("SVM grid: the list of ") + name + " is empty");
  for (double value : values)
    if (!(std::isfinite(value) && value > 0))
      throw Error::usage(std::string("SVM grid: ") + name + " = " + std::to_string(value) +
                         " is not finite and positive");
}

}  // namespace

void check_puk_svm_grid(const PukSvmGrid& grid) {
  check_values(grid.sigma, "sigma");
  check_values(grid.omega, "omega");
  check_values(grid.c, "C");
}

std::vector<PukSvmParams> puk_svm_candidates(const PukSvmGrid& grid) {
  std::vector<double> sigma = grid.sigma, omega = grid.omega, c = grid.c;
  std::sort(c.begin(), c.end());
  std::sort(sigma.begin(), sigma.end(), std::greater<>());
  std::sort(omega.begin(), omega.end());
  std::vector<PukSvmParams> candidates;
  for (double c_value : c)
    for (double sigma_value : sigma)
      for (double omega_value : omega) candidates.push_back({sigma_value, omega_value, c_value});
  return candidates;
}

PukSvmSelection selected_puk_svm_params(const FloatRows& rows, std::span<const int32_t> labels,
                                        const PukSvmGrid& grid, int folds, uint64_t seed) {
  check_puk_svm_grid(grid);
  if (rows.rows() < 1 || static_cast<size_t>(rows.rows()) != labels.size())
    throw Error::usage("SVM grid search: " + std::to_string(rows.rows()) + " rows and " +
                       std::to_string(labels.size()) + " labels (need as many, at least 1)");
  if (folds < 2)
    throw Error::usage("SVM grid search: " + std::to_string(folds) + " folds (need at least 2)");
  std::vector<PukSvmParams> candidates = puk_svm_candidates(grid);
  if (rows.rows() == 1) return {candidates.front(), 0, 0};  // nothing to cross-validate

  int inner_folds = std::min(folds, static_cast<int>(rows.rows()));
  std::vector<int32_t> fold_of_row = stratified_folds(labels, inner_folds, seed);

  std::vector<int> correct(candidates.size(), 0);
  std::exception_ptr failure;
#pragma omp parallel for schedule(dynamic)
  for (size_t i = 0; i < candidates.size(); ++i) {
    try {
      correct[i] = cross_validated_correct(rows, labels, fold_of_row, inner_folds, candidates[i]);
    } catch (...) {
#pragma omp critical(hair_svm_grid_failure)
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);

  size_t best = 0;
  for (size_t i = 1; i < candidates.size(); ++i)
    if (correct[i] > correct[best]) best = i;
  return {candidates[best], correct[best], static_cast<int>(rows.rows())};
}

}  // namespace hair
