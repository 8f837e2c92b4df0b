// Algorithm 1 on hand-made strands whose types are known.
#include <gtest/gtest.h>

#include <numbers>

#include "hair/cluster/typeify.h"

namespace hair {
namespace {

/// A straight strand of `points` points from `start` along `direction` for `length`.
Points3f straight(const Eigen::Vector3f& start, const Eigen::Vector3f& direction, float length,
                  int points = 8) {
  Points3f strand(points, 3);
  for (int i = 0; i < points; ++i)
    strand.row(i) = (start + direction.normalized() * length * static_cast<float>(i) / (points - 1))
                        .transpose();
  return strand;
}

/// Groups of two side-by-side strands (1 cm apart in x) along each centre line.
struct Model {
  StrandSet strands;
  std::vector<int32_t> first_strand{0};
};

Model model_of(const std::vector<Points3f>& centres) {
  std::vector<Points3f> polylines;
  Model model;
  for (const Points3f& centre : centres) {
    for (float dx : {-0.005f, 0.005f}) {
      Points3f shifted = centre;
      shifted.col(0).array() += dx;
      polylines.push_back(shifted);
    }
    model.first_strand.push_back(static_cast<int32_t>(polylines.size()));
  }
  model.strands = strand_set_from_polylines(polylines);
  return model;
}

constexpr double kHeadHeight = 0.25;  // neighbour distance 0.08 H = 2 cm

TEST(GroupTypes, ChainOfPiecesIsRootMiddleTip) {
  Eigen::Vector3f down(0, -1, 0);
  Model model = model_of({straight({0, 1.6f, 0}, down, 0.1f), straight({0, 1.49f, 0}, down, 0.1f),
                          straight({0, 1.38f, 0}, down, 0.1f)});
  GroupTypes types = group_types(model.strands, model.first_strand, kHeadHeight, {});
  ASSERT_EQ(types.type.size(), 3u);
  EXPECT_EQ(types.type[0], GroupType::root_connected);
  EXPECT_EQ(types.type[1], GroupType::middle);
  EXPECT_EQ(types.type[2], GroupType::tip);
  EXPECT_EQ(types.before[1], std::vector<int32_t>{0});
  EXPECT_EQ(types.after[0], std::vector<int32_t>{1});
  EXPECT_NEAR(types.after_angle_rad[0][0], 0.0, 1e-3);
}

TEST(GroupTypes, LoneAndSideBySideStrandsAreRootFree) {
  Eigen::Vector3f down(0, -1, 0);
  Model model =
      model_of({straight({0, 1.6f, 0}, down, 0.2f), straight({0.03f, 1.6f, 0}, down, 0.2f),
                straight({0.5f, 1.6f, 0}, down, 0.2f)});
  GroupTypes types = group_types(model.strands, model.first_strand, kHeadHeight, {});
  for (GroupType type : types.type) EXPECT_EQ(type, GroupType::root_free);
}

TEST(GroupTypes, SharpTurnIsNotConnectedUnderASmallAngle) {
  Model model = model_of(
      {straight({0, 1.6f, 0}, {0, -1, 0}, 0.1f), straight({0, 1.49f, 0.01f}, {0, 0, 1}, 0.1f)});
  TypeifyParams params;
  params.connect_angle_deg = 45;
  GroupTypes types = group_types(model.strands, model.first_strand, kHeadHeight, params);
  EXPECT_EQ(types.type[0], GroupType::root_free);  // 90 degrees: not one flow
  EXPECT_EQ(types.type[1], GroupType::tip);
  EXPECT_FALSE(types.threshold_from_distribution);
  EXPECT_NEAR(types.after_angle_rad[0][0], std::numbers::pi / 2, 1e-3);
}

TEST(GroupTypes, CentreStrandIsTheMeanOfTheGroupsStrands) {
  Model model = model_of({straight({0, 1.6f, 0}, {0, -1, 0}, 0.2f)});
  GroupTypes types =
      group_types(model.strands, model.first_strand, kHeadHeight, {.centre_points = 5});
  auto centre = types.centre_strands.strand(0);
  ASSERT_EQ(centre.rows(), 5);
  for (int i = 0; i < 5; ++i) {
    EXPECT_NEAR(centre(i, 0), 0.0f, 1e-6f);
    EXPECT_NEAR(centre(i, 1), 1.6f - 0.05f * static_cast<float>(i), 1e-5f);
  }
}

TEST(ConnectionAngleThreshold, SplitsTwoClustersOfAngles) {
  std::vector<double> angles;
  for (double degrees : {5.0, 8.0, 10.0, 12.0, 80.0, 85.0, 90.0, 95.0})
    angles.push_back(degrees * std::numbers::pi / 180);
  auto threshold = connection_angle_threshold(angles, 0, std::numbers::pi);
  ASSERT_TRUE(threshold);
  EXPECT_NEAR(*threshold, 46 * std::numbers::pi / 180, 2 * std::numbers::pi / 180);  // mid-gap
  EXPECT_FALSE(connection_angle_threshold({0.1, 0.2}, 0, std::numbers::pi));         // too few
  EXPECT_NEAR(*connection_angle_threshold(angles, 1.0, 1.2), 1.0, 1e-12);            // clamped up
  EXPECT_NEAR(*connection_angle_threshold(angles, 0.1, 0.5), 0.5, 1e-12);            // clamped down
}

}  // namespace
}  // namespace hair
