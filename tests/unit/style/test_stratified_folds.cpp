// Stratified fold assignment: every row once, classes spread evenly, deterministic.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "hair/core/error.h"
#include "hair/style/stratified_folds.h"

namespace hair {
namespace {

TEST(StratifiedFolds, EveryRowInOneFoldAndClassesSpreadEvenly) {
  std::vector<int32_t> labels;
  for (int i = 0; i < 159; ++i) labels.push_back(i % 7 == 0 ? 3 : i % 3);  // four classes
  labels[5] = labels[50] = labels[100] = 9;                                // a class of 3 rows
  std::vector<int32_t> fold = stratified_folds(labels, 10, 1);
  ASSERT_EQ(fold.size(), labels.size());
  std::vector<int> fold_size(10, 0);
  std::map<int32_t, std::vector<int>> class_in_fold;
  for (size_t row = 0; row < labels.size(); ++row) {
    ASSERT_GE(fold[row], 0);
    ASSERT_LT(fold[row], 10);
    ++fold_size[static_cast<size_t>(fold[row])];
    class_in_fold[labels[row]].resize(10, 0);
    ++class_in_fold[labels[row]][static_cast<size_t>(fold[row])];
  }
  EXPECT_LE(*std::max_element(fold_size.begin(), fold_size.end()) -
                *std::min_element(fold_size.begin(), fold_size.end()),
            1);
  for (const auto& [label, counts] : class_in_fold)
    EXPECT_LE(*std::max_element(counts.begin(), counts.end()) -
                  *std::min_element(counts.begin(), counts.end()),
              1)
        << "class " << label;
  std::set<int32_t> small_class_folds = {fold[5], fold[50], fold[100]};
  EXPECT_EQ(small_class_folds.size(), 3u);

  // The union of the test rows of all folds is every row, once.
  std::vector<int> seen(labels.size(), 0);
  for (int32_t f = 0; f < 10; ++f) {
    std::vector<Eigen::Index> test = fold_row_indices(fold, f, true);
    std::vector<Eigen::Index> train = fold_row_indices(fold, f, false);
    EXPECT_EQ(test.size() + train.size(), labels.size());
    for (Eigen::Index row : test) ++seen[static_cast<size_t>(row)];
  }
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int count) { return count == 1; }));
}

TEST(StratifiedFolds, SeededAndDeterministic) {
  std::vector<int32_t> labels(60);
  for (int i = 0; i < 60; ++i) labels[static_cast<size_t>(i)] = i % 4;
  EXPECT_EQ(stratified_folds(labels, 5, 7), stratified_folds(labels, 5, 7));
  EXPECT_NE(stratified_folds(labels, 5, 7), stratified_folds(labels, 5, 8));
  // Not simply the row order: consecutive rows of a class are shuffled across folds.
  std::vector<int32_t> fold = stratified_folds(labels, 5, 7);
  int in_order = 0;
  for (int i = 0; i < 20; ++i) in_order += fold[static_cast<size_t>(4 * i)] == i % 5;
  EXPECT_LT(in_order, 15);
}

TEST(StratifiedFolds, RejectsFoldCountsOutsideTheRows) {
  std::vector<int32_t> labels = {0, 1, 0};
  EXPECT_THROW(stratified_folds(labels, 1, 1), Error);
  EXPECT_THROW(stratified_folds(labels, 4, 1), Error);
  EXPECT_NO_THROW(stratified_folds(labels, 3, 1));
}

TEST(GroupedFolds, KeepEveryGroupInOneFoldAndBalanceTheGroups) {
  // 23 models with 1 to 5 clusters each, rows interleaved.
  std::vector<std::string> group;
  for (int row = 0; row < 70; ++row) group.push_back("model_" + std::to_string((row * 7) % 23));
  std::vector<int32_t> fold = grouped_folds(group, 5, 3);
  ASSERT_EQ(fold.size(), group.size());
  std::map<std::string, std::set<int32_t>> folds_of_group;
  for (size_t row = 0; row < group.size(); ++row) folds_of_group[group[row]].insert(fold[row]);
  std::map<int32_t, int> groups_per_fold;
  for (const auto& [name, folds] : folds_of_group) {
    EXPECT_EQ(folds.size(), 1u) << name;
    ++groups_per_fold[*folds.begin()];
  }
  ASSERT_EQ(groups_per_fold.size(), 5u);
  for (const auto& [f, count] : groups_per_fold) {
    EXPECT_GE(count, 4) << "fold " << f;  // 23 groups in 5 folds: 4 or 5 each
    EXPECT_LE(count, 5) << "fold " << f;
  }
  EXPECT_EQ(grouped_folds(group, 5, 3), fold);
  EXPECT_THROW(grouped_folds({"a", "a", "b"}, 3, 1), Error);  // 2 groups for 3 folds
}

}  // namespace
}  // namespace hair
