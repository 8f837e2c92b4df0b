// Connectivity and similarity weights between centre strands (paper equations 1-5)
// on hand-made strands whose values are worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hair/cluster/group_weights.h"

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

TEST(GroupWeights, ContinuationOffsetIsZeroOnAStraightStreamWhateverTheGap) {
  Points3f upper = straight({0, 0, 0}, {0, -0.1f, 0});
  for (float gap : {0.002f, 0.005f, 0.02f}) {
    ConnectionFeatures f =
        connection_features(upper, straight({0, -0.1f - gap, 0}, {0, -0.2f, 0}), kHeadHeight,
                            FlowDirection::end_quarter, Closeness::ends);
    EXPECT_NEAR(f.f1, gap / kHeadHeight, 1e-5);
    EXPECT_NEAR(f.f4, 0, 1e-5);
  }
  EXPECT_NEAR(offset_from_line({1, 2, 0}, {0, 0, 0}, {0, 3, 0}), 1, 1e-12);
  EXPECT_NEAR(offset_from_line({1, 2, 0}, {1, 0, 0}, {0, 0, 0}), 2, 1e-12);  // no direction
}

TEST(GroupWeights, ContinuationOffsetPrefersAStraightContinuationToAKinkedOne) {
  // The upper piece ends at (0, -0.1); three candidates start 5 mm from its end.
  Points3f upper = straight({0, 0, 0}, {0, -0.1f, 0});
  Points3f on = straight({0, -0.105f, 0}, {0, -0.2f, 0});  // straight on
  // Beside the end, running parallel: 3 mm across and 4 mm down, so each end lies 3 mm
  // off the other's line.
  Points3f beside = straight({0.003f, -0.104f, 0}, {0.003f, -0.2f, 0});
  // Straight below the end but turned at a right angle: the upper end lies 5 mm off the
  // line of the lower piece's flow, the lower start on the upper line.
  Points3f kinked = straight({0, -0.105f, 0}, {0.095f, -0.105f, 0});
  auto features = [&](const Points3f& lower) {
    return connection_features(upper, lower, kHeadHeight, FlowDirection::end_quarter,
                               Closeness::ends);
  };
  ConnectionFeatures straight_on = features(on), side = features(beside), kink = features(kinked);
  EXPECT_NEAR(straight_on.f4, 0, 1e-5);
  EXPECT_NEAR(side.f4, 0.003 / kHeadHeight, 1e-5);
  EXPECT_NEAR(kink.f4, 0.005 / 2 / kHeadHeight, 1e-5);
  // All three start as close (f1 alike), but the weights rank the straight continuation
  // first.
  EXPECT_NEAR(side.f1, straight_on.f1, 1e-5);
  ConnectivityParams params;
  std::optional<double> w_on = connectivity_weight(straight_on, params);
  std::optional<double> w_side = connectivity_weight(side, params);
  std::optional<double> w_kink = connectivity_weight(kink, params);
  ASSERT_TRUE(w_on && w_side && w_kink);
  EXPECT_LT(*w_on, *w_side);
  EXPECT_LT(*w_on, *w_kink);
  EXPECT_NEAR(*w_side - *w_on,
              params.k1 * (side.f1 - straight_on.f1) + params.k2 * (side.f2 - straight_on.f2) +
                  params.k3 * (side.f3 - straight_on.f3) + params.k4 * side.f4,
              1e-9);
  // A piece that starts 1 cm beside the end is beyond the bound (0.03 H = 7.5 mm here).
  ConnectionFeatures far_beside = features(straight({0.01f, -0.1f, 0}, {0.01f, -0.2f, 0}));
  EXPECT_GT(far_beside.f4, params.f4_max);
  EXPECT_FALSE(connectivity_weight(far_beside, params));
}

TEST(GroupWeights, ContinuationOffsetIsSmallAlongACurvedStream) {
  // Pieces of one circle of radius 3 cm, 5 mm apart, against a piece of a circle of the
  // same radius that starts as close but runs across the first one's end.
  auto arc = [](double centre_x, double from, double to) {
    Points3f points(16, 3);
    for (int i = 0; i < 16; ++i) {
      double t = from + (to - from) * i / 15;
      points.row(i) << static_cast<float>(centre_x + 0.03 * std::cos(t)),
          static_cast<float>(-0.03 * std::sin(t)), 0.0f;
    }
    return points;
  };
  double gap = 0.005 / 0.03;  // radians
  Points3f first = arc(0, 0, 1), next = arc(0, 1 + gap, 2 + gap);
  ConnectionFeatures along =
      connection_features(first, next, kHeadHeight, FlowDirection::end_quarter, Closeness::ends);
  // A straight piece of another stream that starts 5 mm beside the first one's end and
  // runs on parallel to its flow there, as a crossing braid stream's piece does.
  Eigen::Vector3f end = first.row(15).transpose();
  Eigen::Vector3f flow = (end - first.row(12).transpose()).normalized();
  Eigen::Vector3f beside = end + 0.005f * Eigen::Vector3f(flow.y(), -flow.x(), 0);
  Points3f across = straight(beside, beside + 0.05f * flow, 16);
  ConnectionFeatures other =
      connection_features(first, across, kHeadHeight, FlowDirection::end_quarter, Closeness::ends);
  EXPECT_TRUE(along.first_is_root_side);
  EXPECT_TRUE(other.first_is_root_side);
  EXPECT_NEAR(along.f1, other.f1, 0.0002 / kHeadHeight);  // both start 5 mm away
  EXPECT_LT(along.f4, 0.001 / kHeadHeight);               // under 1 mm off on a 3 cm bend
  EXPECT_NEAR(other.f4, 0.005 / kHeadHeight, 1e-5);
  EXPECT_GT(other.f4, 4 * along.f4);
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
