// cluster_passages(): where the grown strands touching each cluster come from and go, on
// hand-made strands (a cap feeding a tail, a strand that stays, one crossing twice).

#include <gtest/gtest.h>

#include "hair/grow/grow_measures.h"

namespace hair {
namespace {

TEST(ClusterPassages, CountsRootedLeavingAndPassingStrands) {
  StrandSet strands;
  // Point clusters per strand: cap into tail; cap only; cap, tail, cap, tail (one pass,
  // counted once); rooted in the tail.
  const std::vector<std::vector<int32_t>> point_clusters = {
      {0, 0, 1, 1}, {0, 0, 0}, {0, 1, 0, 1}, {1, 1}};
  std::vector<int32_t> roots, points;
  for (const auto& strand : point_clusters) {
    roots.push_back(strand.front());
    points.insert(points.end(), strand.begin(), strand.end());
    strands.offsets.push_back(strands.offsets.back() + static_cast<int64_t>(strand.size()));
  }
  strands.points = Points3f::Zero(static_cast<Eigen::Index>(points.size()), 3);
  strands.strand_attributes["cluster"] = roots;
  strands.point_attributes["cluster"] = points;

  const std::vector<ClusterPassage> passages = cluster_passages(strands, 3);
  ASSERT_EQ(passages.size(), 3u);
  EXPECT_EQ(passages[0].rooted, 3);
  EXPECT_EQ(passages[0].rooted_leaving, 2);  // the first and third end in the tail
  EXPECT_EQ(passages[0].passing_in, 0);
  EXPECT_EQ(passages[1].rooted, 1);
  EXPECT_EQ(passages[1].rooted_leaving, 0);
  EXPECT_EQ(passages[1].passing_in, 2);
  EXPECT_EQ(passages[2].rooted, 0);
  EXPECT_EQ(passages[2].passing_in, 0);
}

}  // namespace
}  // namespace hair
