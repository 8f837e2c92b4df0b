#include "hair/style/stratified_folds.h"

#include <algorithm>
#include <map>
#include <random>
#include <string>
#include <utility>

#include "hair/core/error.h"

namespace hair {
namespace {

/// A uniform index in [0, count) from the top 53 bits of one output of the generator.
size_t uniform_index(std::mt19937_64& random, size_t count) {
  double uniform01 = static_cast<double>(random() >> 11) * 0x1.0p-53;
  return std::min(static_cast<size_t>(uniform01 * static_cast<double>(count)), count - 1);
}

}  // namespace

std::vector<int32_t> stratified_folds(std::span<const int32_t> labels, int folds, uint64_t seed) {
  if (folds < 2 || static_cast<size_t>(folds) > labels.size())
    throw Error::usage("cross-validation: " + std::to_string(folds) + " folds need between 2 and " +
                       std::to_string(labels.size()) + " (the number of rows)");
  std::map<int32_t, std::vector<size_t>> rows_of_class;  // ascending labels
  for (size_t row = 0; row < labels.size(); ++row) rows_of_class[labels[row]].push_back(row);

  std::mt19937_64 random(seed);
  std::vector<int32_t> fold(labels.size(), -1);
  int32_t next = 0;
  for (auto& [label, rows] : rows_of_class) {
    for (size_t i = rows.size(); i > 1; --i) std::swap(rows[i - 1], rows[uniform_index(random, i)]);
    for (size_t row : rows) {
      fold[row] = next;
      next = (next + 1) % folds;
    }
  }
  return fold;
}

std::vector<int32_t> grouped_folds(const std::vector<std::string>& group_of_row, int folds,
                                   uint64_t seed) {
  std::vector<std::string> groups = group_of_row;
  std::sort(groups.begin(), groups.end());
  groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
  std::vector<int32_t> one_class(groups.size(), 0);
  std::vector<int32_t> group_fold = stratified_folds(one_class, folds, seed);
  std::vector<int32_t> fold_of_row;
  fold_of_row.reserve(group_of_row.size());
  for (const std::string& group : group_of_row)
    fold_of_row.push_back(group_fold[static_cast<size_t>(
        std::lower_bound(groups.begin(), groups.end(), group) - groups.begin())]);
  return fold_of_row;
}

std::vector<Eigen::Index> fold_row_indices(std::span<const int32_t> fold_of_row, int32_t fold,
                                           bool in_fold) {
  std::vector<Eigen::Index> rows;
  for (size_t row = 0; row < fold_of_row.size(); ++row)
    if ((fold_of_row[row] == fold) == in_fold) rows.push_back(static_cast<Eigen::Index>(row));
  return rows;
}

}  // namespace hair
