// The strands of a group run the same way (group_sense.h): hand-made groups of strands.
#include <gtest/gtest.h>

#include <vector>

#include "hair/extract/group_sense.h"

namespace hair {
namespace {

/// A strand of 11 points from `start` along `step`, with a point attribute "source_vertex"
/// counting up from `first_id`.
void append(StrandSet& strands, const Eigen::Vector3f& start, const Eigen::Vector3f& step,
            int32_t first_id) {
  Points3f points(11, 3);
  for (int i = 0; i < 11; ++i) points.row(i) = (start + static_cast<float>(i) * step).transpose();
  strands.append_strand(points);
  auto& ids = std::get<std::vector<int32_t>>(strands.point_attributes["source_vertex"]);
  for (int i = 0; i < 11; ++i) ids.push_back(first_id + i);
}

/// Five strands 5 mm apart hanging 10 cm down; strand 2 (with `reverse_middle`) drawn
/// from its tip up.
StrandSet hanging_group(bool reverse_middle) {
  StrandSet strands;
  strands.point_attributes["source_vertex"] = std::vector<int32_t>{};
  for (int s = 0; s < 5; ++s) {
    const Eigen::Vector3f root(0.005f * static_cast<float>(s), 0, 0);
    if (s == 2 && reverse_middle)
      append(strands, root - Eigen::Vector3f(0, 0.1f, 0), Eigen::Vector3f(0, 0.01f, 0), 100 * s);
    else
      append(strands, root, Eigen::Vector3f(0, -0.01f, 0), 100 * s);
  }
  return strands;
}

GroupSenseParams params() {
  GroupSenseParams p;
  p.radius_m = 0.02;
  return p;
}

TEST(GroupSense, AStrandRunningAgainstItsGroupIsTurned) {
  StrandSet strands = hanging_group(true);
  const std::vector<int64_t> group{0, 1, 2, 3, 4};
  int judged = 0;
  EXPECT_LT(mean_cosine_with_group(strands, group, 2, params(), judged), -0.9);
  EXPECT_EQ(judged, 10);
  EXPECT_GT(mean_cosine_with_group(strands, group, 1, params(), judged), 0.3);  // 2 of 3 agree
  const std::vector<int32_t> first{0, 5};
  EXPECT_EQ(turn_strands_against_their_group(strands, first, params()), 1);
  // Strand 2 now hangs from its root like the others, its vertex ids turned with it.
  EXPECT_NEAR(strands.strand(2)(0, 1), 0.0f, 1e-6);
  EXPECT_NEAR(strands.strand(2)(10, 1), -0.1f, 1e-6);
  const auto& ids = std::get<std::vector<int32_t>>(strands.point_attributes.at("source_vertex"));
  EXPECT_EQ(ids[22], 210);
  EXPECT_EQ(ids[32], 200);
  // The others as they were; a second pass turns nothing.
  EXPECT_TRUE(strands.points.isApprox(hanging_group(false).points, 1e-6f));
  EXPECT_EQ(turn_strands_against_their_group(strands, first, params()), 0);
}

TEST(GroupSense, EachGroupIsJudgedByItsOwnStrands) {
  // The reversed strand alone in a group of its own (groups {0, 1}, {2}, {3, 4}), or the
  // five hanging alike: nothing to turn.
  StrandSet strands = hanging_group(true);
  const Points3f before = strands.points;
  const std::vector<int32_t> small_groups{0, 2, 3, 5};
  EXPECT_EQ(turn_strands_against_their_group(strands, small_groups, params()), 0);
  EXPECT_EQ(strands.points, before);
  StrandSet alike = hanging_group(false);
  const std::vector<int32_t> one{0, 5};
  EXPECT_EQ(turn_strands_against_their_group(alike, one, params()), 0);
}

TEST(GroupSense, StrandsCrossingOneSayNothingOfItsWay) {
  // A strand down the middle of three rings running across it (a cap's rails beside a
  // strand traced down it): no neighbour along its axis, not judged, not turned.
  StrandSet strands;
  strands.point_attributes["source_vertex"] = std::vector<int32_t>{};
  append(strands, Eigen::Vector3f(0, 0, 0), Eigen::Vector3f(0, -0.01f, 0), 0);
  for (int r = 0; r < 3; ++r)
    append(strands, Eigen::Vector3f(-0.05f, -0.03f * static_cast<float>(r), 0.003f),
           Eigen::Vector3f(0.01f, 0, 0), 100 * (r + 1));
  const std::vector<int64_t> group{0, 1, 2, 3};
  int judged = 0;
  mean_cosine_with_group(strands, group, 0, params(), judged);
  EXPECT_EQ(judged, 0);
  const std::vector<int32_t> first{0, 4};
  EXPECT_EQ(turn_strands_against_their_group(strands, first, params()), 0);
}

}  // namespace
}  // namespace hair
