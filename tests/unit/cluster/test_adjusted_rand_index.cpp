// The adjusted Rand index against hand-computed values (which sklearn's
// adjusted_rand_score gives too) and its limiting cases.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "hair/cluster/adjusted_rand_index.h"
#include "hair/core/error.h"

namespace hair {
namespace {

TEST(AdjustedRandIndex, IdenticalPartitionsScoreOne) {
  std::vector<int32_t> a{0, 0, 1, 1, 2, 2, 2};
  EXPECT_DOUBLE_EQ(adjusted_rand_index(a, a), 1.0);
  // The same partition under other names, negative and sparse ones included.
  std::vector<int32_t> renamed{-7, -7, 40, 40, 3, 3, 3};
  EXPECT_DOUBLE_EQ(adjusted_rand_index(a, renamed), 1.0);
  EXPECT_DOUBLE_EQ(adjusted_rand_index(renamed, a), 1.0);
}

TEST(AdjustedRandIndex, MatchesHandComputedValues) {
  // Pairs together in both / in a / in b, out of n choose 2, give
  // (index - expected) / (max - expected) with expected = S_a S_b / (n choose 2).
  // [0,0,1,1] vs [0,0,1,2]: index 1, S_a 2, S_b 1 of 6 pairs: (2/3) / (7/6) = 4/7.
  EXPECT_NEAR(adjusted_rand_index({0, 0, 1, 1}, {0, 0, 1, 2}), 0.5714285714285715, 1e-15);
  // [0,0,0,1,1,1] vs [0,0,1,1,2,2]: index 2, S_a 6, S_b 3 of 15: 0.8 / 3.3.
  EXPECT_NEAR(adjusted_rand_index({0, 0, 0, 1, 1, 1}, {0, 0, 1, 1, 2, 2}), 0.24242424242424243,
              1e-15);
  // Worse than chance: no pair together in both.
  EXPECT_NEAR(adjusted_rand_index({0, 0, 1, 1}, {0, 1, 0, 1}), -0.5, 1e-15);
}

TEST(AdjustedRandIndex, IsSymmetric) {
  std::vector<int32_t> a{0, 0, 0, 1, 1, 1, 2, 2}, b{0, 1, 1, 1, 2, 2, 2, 0};
  EXPECT_DOUBLE_EQ(adjusted_rand_index(a, b), adjusted_rand_index(b, a));
  EXPECT_LT(adjusted_rand_index(a, b), 1.0);
}

TEST(AdjustedRandIndex, IndependentRandomLabelingsScoreNearZero) {
  std::mt19937_64 random(12);
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<int32_t> a, b;
    for (int i = 0; i < 5000; ++i) {
      a.push_back(static_cast<int32_t>(random() % 5));
      b.push_back(static_cast<int32_t>(random() % 7));
    }
    EXPECT_LT(std::abs(adjusted_rand_index(a, b)), 0.01) << "trial " << trial;
  }
}

TEST(AdjustedRandIndex, TrivialPartitions) {
  EXPECT_DOUBLE_EQ(adjusted_rand_index({}, {}), 1.0);
  EXPECT_DOUBLE_EQ(adjusted_rand_index({3}, {9}), 1.0);
  EXPECT_DOUBLE_EQ(adjusted_rand_index({5, 5, 5}, {1, 1, 1}), 1.0);        // one cluster each
  EXPECT_DOUBLE_EQ(adjusted_rand_index({0, 1, 2}, {2, 0, 1}), 1.0);        // all singletons each
  EXPECT_DOUBLE_EQ(adjusted_rand_index({0, 0, 0, 0}, {0, 1, 2, 3}), 0.0);  // one vs singletons
}

TEST(AdjustedRandIndex, DifferentLengthsAreAUsageError) {
  try {
    adjusted_rand_index({0, 1, 1}, {0, 1});
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::usage);
  }
}

}  // namespace
}  // namespace hair
