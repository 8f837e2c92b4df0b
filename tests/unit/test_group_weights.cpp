// Connectivity and similarity weights between centre strands (paper equations 1-5)
// on hand-made strands whose values are worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hair/group_weights.h"

namespace hair {
namespace {

constexpr double kHeadHeight = 0.25;

/// A straight strand of `points` points from `start` to `end`.
Points3f straight(Eigen::Vector3f start, Eigen::Vector3f end, int points = 8) {
  Points3f strand(points, 3);
  for (int i = 0; i < points; ++i)
    strand.row(i) = (start + (end - start) * (static_cast<float>(i) / (points - 1))).transpose();
  return strand;
}

TEST(GroupWeights, ConsecutivePiecesOfAStraightStreamAreWorkedOutByHand) {
  Points3f upper = straight({0, 0, 0}, {0, -0.1f, 0});
  Points3f lower = straight({0, -0.105f, 0}, {0, -0.2f, 0});
  for (bool swapped : {false, true}) {
    ConnectionFeatures f = swapped ? connection_features(lower, upper, kHeadHeight)
                                   : connection_features(upper, lower, kHeadHeight);
    EXPECT_EQ(f.first_is_root_side, !swapped);
    EXPECT_NEAR(f.f1, 0.005 / kHeadHeight, 1e-5);              // the 5 mm gap, in H
    EXPECT_NEAR(f.f2, 0.005 * 0.095 / (0.095 * 0.095), 1e-4);  // gap over the tip piece
    EXPECT_NEAR(f.f3, 0, 1e-4);                                // one flow
    ConnectivityParams params;
    std::optional<double> w = connectivity_weight(f, params);
    ASSERT_TRUE(w);
    EXPECT_NEAR(*w, params.k1 * f.f1 + params.k2 * f.f2 + params.k3 * f.f3, 1e-12);
  }
}

TEST(GroupWeights, NoEdgeBeyondEachBound) {
  Points3f upper = straight({0, 0, 0}, {0, -0.1f, 0});
  ConnectivityParams params;
  // Turning at a right angle: f3 = 0.5, beyond the paper's bound 0.3, within ours.
  ConnectionFeatures turn =
      connection_features(upper, straight({0, -0.105f, 0}, {0.1f, -0.105f, 0}), kHeadHeight);
  EXPECT_NEAR(turn.f3, 0.5, 1e-3);
  EXPECT_TRUE(connectivity_weight(turn, params));
  ConnectivityParams paper = params;
  paper.f3_max = 0.3;
  EXPECT_FALSE(connectivity_weight(turn, paper));
  // Turning back up at 135 degrees: f3 = 0.75.
  ConnectionFeatures back =
      connection_features(upper, straight({0, -0.105f, 0}, {0.1f, -0.005f, 0}), kHeadHeight);
  EXPECT_NEAR(back.f3, 0.75, 1e-3);
  EXPECT_FALSE(connectivity_weight(back, params));
  // Starting 6 cm up the upper piece: f2 = 0.06 / 0.1 = 0.6 >= 0.5.
  ConnectionFeatures overlap =
      connection_features(upper, straight({0, -0.04f, 0}, {0, -0.14f, 0}), kHeadHeight);
  EXPECT_NEAR(overlap.f2, 0.6, 1e-4);
  EXPECT_FALSE(connectivity_weight(overlap, params));
  // A gap of H / 2: f1 = 0.5 >= 0.25.
  ConnectionFeatures far =
      connection_features(upper, straight({0, -0.225f, 0}, {0, -0.325f, 0}), kHeadHeight);
  EXPECT_NEAR(far.f1, 0.5, 1e-4);
  EXPECT_FALSE(connectivity_weight(far, params));
  // Side by side (the same heights, 1 cm apart): the end of one lies at the end of the
  // other, f2 = 1.
  ConnectionFeatures beside =
      connection_features(upper, straight({0.01f, 0, 0}, {0.01f, -0.1f, 0}), kHeadHeight);
  EXPECT_NEAR(beside.f2, 1.0, 1e-3);
  EXPECT_FALSE(connectivity_weight(beside, params));
}

TEST(GroupWeights, FlowAngleUsesTheFarthestPointFromTheChord) {
  // An arc bulging in +X: the farthest point from its chord is its middle, and the
  // flow into its end comes from there.
  Points3f arc(9, 3);
  for (int i = 0; i < 9; ++i) {
    double t = std::numbers::pi * i / 8;
    arc.row(i) << static_cast<float>(0.05 * std::sin(t)), static_cast<float>(0.05 * std::cos(t)),
        0.0f;
  }
  EXPECT_EQ(farthest_from_chord(arc), 4);
  EXPECT_EQ(farthest_from_chord(straight({0, 0, 0}, {0, -1, 0}, 9)), 4);
  // Continuing straight down from the arc's end (0, -0.05): the arc's flow from its
  // middle (0.05, 0) to its end is 45 degrees off -Y, the continuation runs along -Y.
  ConnectionFeatures f =
      connection_features(arc, straight({0, -0.055f, 0}, {0, -0.155f, 0}), kHeadHeight);
  EXPECT_TRUE(f.first_is_root_side);
  EXPECT_NEAR(f.f3, 0.25, 1e-3);
}

TEST(GroupWeights, EndGapIgnoresAPieceCrossingTheDistalHalf) {
  // A piece crossing the upper one's distal half, as the pieces of a braid's other
  // streams do: the paper's f1 (closest approach of the halves) is small, the gap
  // between the upper piece's end and the piece's start is not.
  Points3f upper = straight({0, 0, 0}, {0, -0.1f, 0});
  Points3f crossing = straight({0.01f, -0.07f, 0}, {-0.01f, -0.17f, 0});
  ConnectionFeatures halves = connection_features(upper, crossing, kHeadHeight,
                                                  FlowDirection::end_quarter, Closeness::halves);
  ConnectionFeatures ends = connection_features(upper, crossing, kHeadHeight,
                                                FlowDirection::end_quarter, Closeness::ends);
  EXPECT_TRUE(ends.first_is_root_side);
  EXPECT_LT(halves.f1, 0.03);
  EXPECT_NEAR(ends.f1, std::hypot(0.01, 0.03) / kHeadHeight, 1e-5);
  // Both agree on a true continuation with a gap (its closest points are the ends).
  Points3f lower = straight({0, -0.105f, 0}, {0, -0.2f, 0});
  EXPECT_NEAR(
      connection_features(upper, lower, kHeadHeight, FlowDirection::end_quarter, Closeness::halves)
          .f1,
      connection_features(upper, lower, kHeadHeight, FlowDirection::end_quarter, Closeness::ends)
          .f1,
      1e-9);
  for (Closeness closeness : {Closeness::halves, Closeness::ends})
    EXPECT_EQ(closeness_from_name(closeness_name(closeness)), closeness);
  EXPECT_FALSE(closeness_from_name("nearest"));
}

TEST(GroupWeights, SimilarityOfFreeRootGroups) {
  Points3f a = straight({0, 0, 0}, {0, -0.2f, 0});
  Points3f b = straight({0.01f, 0, 0}, {0.02f, -0.2f, 0});
  std::optional<double> w = similarity_weight(a, b, kHeadHeight, SimilarityParams{});
  ASSERT_TRUE(w);
  EXPECT_NEAR(*w, (0.01 + 0.02) / (2 * kHeadHeight), 1e-6);
  Points3f far_tips = straight({0.01f, 0, 0}, {0.1f, -0.2f, 0});
  EXPECT_FALSE(similarity_weight(a, far_tips, kHeadHeight, SimilarityParams{}));
}

}  // namespace
}  // namespace hair
