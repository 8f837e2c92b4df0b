// Algorithm 1 on hand-made strands whose types are known.
#include <gtest/gtest.h>

#include <numbers>

#include "hair/cluster/typeify.h"
#include "hair/core/error.h"

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

// A layered cut: card 0 hangs from the crown; card 1 starts on the scalp under card 0's
// lower half and hangs on; card 2 continues card 0 from its end. With the distance of each
// start to the scalp, card 1 is a root (card 0 passes over it, it does not end there) and
// card 2 stays card 0's continuation although it starts on the scalp too. Without the
// distances, or with the rule off (the default: the paper's rule as written), card 1 is
// typed as following card 0.
TEST(GroupTypes, ACardRootedUnderAnotherCardsLowerHalfIsARootWithTheScalp) {
  Eigen::Vector3f down(0, -1, 0);
  Model model =
      model_of({straight({0, 1.70f, 0}, down, 0.12f), straight({0, 1.62f, -0.01f}, down, 0.15f),
                straight({0, 1.575f, 0}, down, 0.10f)});
  const int points = TypeifyParams{}.centre_points;
  StrandSet centres = centre_strands(model.strands, model.first_strand, points);

  GroupTypes plain = group_types(model.strands, model.first_strand, kHeadHeight, {});
  EXPECT_EQ(plain.before[1], std::vector<int32_t>{0});
  EXPECT_NE(plain.type[1], GroupType::root_connected);
  EXPECT_NE(plain.type[1], GroupType::root_free);

  // Every card starts 5 mm from the scalp (under 0.05 H = 12.5 mm).
  const TypeifyParams rule_on{.root_scalp_distance_h = 0.05};
  GroupTypes rooted =
      group_types_from_centres(centres, {0.005, 0.005, 0.005}, kHeadHeight, rule_on);
  EXPECT_TRUE(rooted.before[1].empty());
  EXPECT_TRUE(rooted.type[1] == GroupType::root_free ||
              rooted.type[1] == GroupType::root_connected);
  EXPECT_EQ(rooted.before[2], std::vector<int32_t>{0});
  EXPECT_EQ(rooted.type[2], GroupType::tip);
  EXPECT_EQ(rooted.type[0], GroupType::root_connected);
  EXPECT_EQ(rooted.start_scalp_distance_m.size(), 3u);

  // Card 1 starting 5 cm off the scalp: a piece lying on card 0, its follower as before.
  GroupTypes off = group_types_from_centres(centres, {0.005, 0.05, 0.005}, kHeadHeight, rule_on);
  EXPECT_EQ(off.before[1], std::vector<int32_t>{0});
  // And the rule off, as by default.
  GroupTypes rule_off = group_types_from_centres(centres, {0.005, 0.005, 0.005}, kHeadHeight, {});
  EXPECT_EQ(rule_off.before[1], std::vector<int32_t>{0});

  EXPECT_THROW(group_types_from_centres(centres, {0.005}, kHeadHeight, rule_on), Error);
  TypeifyParams other_count = rule_on;
  other_count.centre_points = points + 1;  // centres of another resolution
  EXPECT_THROW(group_types_from_centres(centres, {0.005, 0.005, 0.005}, kHeadHeight, other_count),
               Error);
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
