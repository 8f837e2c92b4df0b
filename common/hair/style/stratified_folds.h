#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace hair {

/// The fold of every row for a stratified k-fold cross-validation.
///
/// The rows of each class (classes in ascending label order) are shuffled, then all of
/// them, class after class, are dealt to the folds in turn (0, 1, ..., folds - 1, 0, ...),
/// the dealing running on from one class to the next. So every fold holds the same
/// number of rows of a class, give or take one, and of rows in all, give or take one; a
/// class of fewer rows than folds has its rows in different folds. The shuffle is a
/// Fisher-Yates shuffle drawn from std::mt19937_64(seed) with uniform draws written here
/// (not the implementation-defined std distributions): the same folds on every platform.
///
///   @param[in] labels  n class labels
///   @param[in] folds  2 <= folds <= n
///   @return n fold numbers in [0, folds)
///
/// Throws hair::Error (usage) for folds outside [2, n].
std::vector<int32_t> stratified_folds(std::span<const int32_t> labels, int folds, uint64_t seed);

/// The fold of every row for a k-fold cross-validation that keeps the rows of a group
/// together (e.g. the clusters of one hair model): the distinct groups are dealt to the
/// folds as stratified_folds() deals the rows of one class, so every fold holds as many
/// groups as the others, give or take one.
///
///   @param[in] group_of_row  n group names
///   @param[in] folds  2 <= folds <= the number of distinct groups
///   @return n fold numbers in [0, folds)
///
/// Throws hair::Error (usage) for folds outside [2, #groups].
std::vector<int32_t> grouped_folds(const std::vector<std::string>& group_of_row, int folds,
                                   uint64_t seed);

/// The rows (indices into `fold_of_row`, ascending) whose fold is `fold` when `in_fold`,
/// the others otherwise: a fold's test rows, or its training rows.
std::vector<Eigen::Index> fold_row_indices(std::span<const int32_t> fold_of_row, int32_t fold,
                                           bool in_fold);

}  // namespace hair
