// The sense of strands: hairpins, chords through air and curvature on hand-made strands
// whose answers are known from geometry (a helix's curvature is r / (r^2 + c^2)).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hair/core/error.h"
#include "hair/grow/strand_sense.h"

namespace {

using hair::Points3f;

Points3f polyline(std::initializer_list<std::array<float, 3>> points) {
  Points3f p(static_cast<Eigen::Index>(points.size()), 3);
  Eigen::Index i = 0;
  for (const auto& q : points) p.row(i++) << q[0], q[1], q[2];
  return p;
}

/// A helix of radius r (m) rising c (m) per radian about +Y, `turns` turns, n points a turn.
Points3f helix(double r, double c, double turns, int n) {
  const int count = static_cast<int>(turns * n) + 1;
  Points3f p(count, 3);
  for (int i = 0; i < count; ++i) {
    const double t = 2 * std::numbers::pi * i / n;
    p.row(i) << static_cast<float>(r * std::cos(t)), static_cast<float>(-c * t),
        static_cast<float>(r * std::sin(t));
  }
  return p;
}

/// A flat card: a 0.2 m square in the plane z = 0, centred on the origin.
struct FlatCard {
  Points3f vertices = polyline({{-0.1f, -0.1f, 0}, {0.1f, -0.1f, 0}, {0.1f, 0.1f, 0}, {-0.1f, 0.1f, 0}});
  hair::Triangles3i triangles = (hair::Triangles3i(2, 3) << 0, 1, 2, 0, 2, 3).finished();
};

TEST(StrandSense, AStrandThatTurnsBackIsAHairpinAndABendIsNot) {
  EXPECT_TRUE(hair::has_hairpin(polyline({{0, 0, 0}, {0, -0.01f, 0}, {0.002f, 0, 0}}), 90));
  // A right angle is not sharper than 90 degrees; 100 degrees is.
  EXPECT_FALSE(hair::has_hairpin(polyline({{0, 0, 0}, {0, -0.01f, 0}, {0.01f, -0.01f, 0}}), 90));
  const double a = 100 * std::numbers::pi / 180;
  EXPECT_TRUE(hair::has_hairpin(
      polyline({{0, 0, 0},
                {0, -0.01f, 0},
                {static_cast<float>(0.01 * std::sin(a)), static_cast<float>(-0.01 - 0.01 * std::cos(a)), 0}}),
      90));
  // A repeated point between two segments is no turn, and a tight curl of 5 mm radius
  // sampled every 36 degrees has no hairpin.
  EXPECT_FALSE(hair::has_hairpin(polyline({{0, 0, 0}, {0, -0.01f, 0}, {0, -0.01f, 0}, {0, -0.02f, 0}}), 90));
  EXPECT_FALSE(hair::has_hairpin(helix(0.005, 0.001, 3, 10), 90));
}

TEST(StrandSense, AStretchFarFromTheMeshIsAChordThroughAir) {
  const FlatCard card;
  const hair::TriangleMeshDistance distance(card.vertices, card.triangles);
  const hair::AirAroundHair air(distance, nullptr, 0.01, 0.1);
  // On the card for 5 cm, then 3 cm straight out of it in one segment: the stretch farther
  // than 1 cm is the last 2 cm, found within one segment by the samples along it.
  const Points3f out = polyline({{0, 0.05f, 0}, {0, 0, 0}, {0, 0, 0.03f}});
  EXPECT_NEAR(hair::longest_air_stretch_m(out, air, 0.0025), 0.02, 0.003);
  // Lying 5 mm over the card all along: no air at 1 cm.
  const Points3f over = polyline({{0, 0.05f, 0.005f}, {0, -0.05f, 0.005f}});
  EXPECT_EQ(hair::longest_air_stretch_m(over, air, 0.0025), 0.0);
  // A chord off the card's edge and back: 0.3 m beyond x = 0.1, 2 cm high.
  const Points3f chord = polyline({{0.05f, 0, 0}, {0.15f, 0, 0.02f}, {0.45f, 0, 0.02f}});
  EXPECT_GT(hair::longest_air_stretch_m(chord, air, 0.0025), 0.29);

  hair::StrandSet strands = hair::strand_set_from_polylines(
      {out, over, chord, polyline({{0, 0, 0}, {0, -0.01f, 0}, {0.002f, 0, 0}})});
  const hair::KinkMeasures m = hair::measure_kinks(strands, distance, nullptr, 0.25);
  EXPECT_EQ(m.strands, 4);
  EXPECT_EQ(m.hairpin_strands, 1);
  EXPECT_EQ(m.air_chord_strands, 1);  // `chord`; `out` is in air for under 2 cm
  EXPECT_EQ(m.kinked_strands, 2);
  EXPECT_EQ(m.kinked, (std::vector<int64_t>{2, 3}));
  EXPECT_DOUBLE_EQ(m.kinked_share(), 0.5);
}

TEST(StrandSense, AChordIsCountedByTheRuleThatGrewMostOfItsStretch) {
  const FlatCard card;
  const hair::TriangleMeshDistance distance(card.vertices, card.triangles);
  // The chord's two segments: onto the card's edge (1 cm of it in air) and 0.3 m through
  // air. Grown as input strand then bridge, it is the bridge's chord; with the two rules
  // swapped, the input strand's.
  const Points3f chord = polyline({{0.05f, 0, 0}, {0.15f, 0, 0.02f}, {0.45f, 0, 0.02f}});
  const hair::StrandSet strands = hair::strand_set_from_polylines({chord, chord});
  const std::vector<int8_t> rules = {0, 2, 3, 0, 3, 2};
  const hair::KinkMeasures m =
      hair::measure_kinks(strands, distance, nullptr, 0.25, {}, &rules);
  EXPECT_EQ(m.air_chord_strands, 2);
  EXPECT_EQ(m.air_chord_strands_by_rule[3], 1);
  EXPECT_EQ(m.air_chord_strands_by_rule[2], 1);
  EXPECT_EQ(m.air_chord_strands_by_rule[1], 0);
  // Without rules every chord is counted at [0].
  EXPECT_EQ(hair::measure_kinks(strands, distance, nullptr, 0.25).air_chord_strands_by_rule[0], 2);
  // One rule per point, each 0-3.
  const std::vector<int8_t> short_rules = {0, 2, 3};
  EXPECT_THROW(hair::measure_kinks(strands, distance, nullptr, 0.25, {}, &short_rules), hair::Error);
  const std::vector<int8_t> bad_rules = {0, 2, 4, 0, 3, 2};
  EXPECT_THROW(hair::measure_kinks(strands, distance, nullptr, 0.25, {}, &bad_rules), hair::Error);
  // The stretch's length by segment sums to its length.
  const hair::AirAroundHair air(distance, nullptr, 0.01, 0.1);
  const hair::AirStretch stretch = hair::longest_air_stretch(chord, air, 0.0025);
  ASSERT_EQ(stretch.length_by_segment_m.size(), 2u);
  EXPECT_NEAR(stretch.length_by_segment_m[0] + stretch.length_by_segment_m[1], stretch.length_m, 1e-9);
  EXPECT_GT(stretch.length_by_segment_m[1], 0.29);
}

TEST(StrandSense, HairUnderACardLayerIsNotAir) {
  // A body: a 0.2 m square at z = -0.05; the card layer 5 cm over it at z = 0. A strand
  // 2.5 cm under the layer runs 2 cm or more from both, but the layer lies over it: not
  // air. The same strand 3 cm above the layer has nothing over it: air.
  const FlatCard card;
  Points3f body_vertices = card.vertices;
  body_vertices.col(2).setConstant(-0.05f);
  const hair::TriangleMeshDistance hair_distance(card.vertices, card.triangles);
  const hair::TriangleMeshDistance body_distance(body_vertices, card.triangles);
  const hair::AirAroundHair air(hair_distance, &body_distance, 0.01, 0.1);
  const Points3f under = polyline({{0, 0.05f, -0.025f}, {0, -0.05f, -0.025f}});
  const Points3f above = polyline({{0, 0.05f, 0.03f}, {0, -0.05f, 0.03f}});
  EXPECT_EQ(hair::longest_air_stretch_m(under, air, 0.0025), 0.0);
  EXPECT_NEAR(hair::longest_air_stretch_m(above, air, 0.0025), 0.1, 1e-6);
  // Without the body, far from the card is air wherever it is.
  EXPECT_NEAR(hair::longest_air_stretch_m(under, hair::AirAroundHair(hair_distance, nullptr, 0.01, 0.1), 0.0025),
              0.1, 1e-6);
  const hair::KinkMeasures m = hair::measure_kinks(hair::strand_set_from_polylines({under, above}),
                                                   hair_distance, &body_distance, 0.25);
  EXPECT_EQ(m.air_chord_strands, 1);
}

TEST(StrandSense, AHelixCurvesAsItsRadiusAndPitchSay) {
  // Curvature of a helix: r / (r^2 + c^2), whatever the point spacing of the strand.
  for (const auto& [r, c] : {std::pair{0.008, 0.002}, std::pair{0.02, 0.005}}) {
    const double expected = r / (r * r + c * c);
    for (int n : {12, 40}) {
      const hair::StrandSet strands = hair::strand_set_from_polylines({helix(r, c, 4, n)});
      EXPECT_NEAR(hair::mean_curvature_per_m(strands, 0.002), expected, 0.05 * expected)
          << "r " << r << " c " << c << " n " << n;
    }
  }
  // A straight strand does not curve; strands shorter than three steps are left out.
  const hair::StrandSet straight = hair::strand_set_from_polylines(
      {polyline({{0, 0, 0}, {0, -0.3f, 0}}), polyline({{0, 0, 0}, {0.001f, 0, 0}})});
  EXPECT_NEAR(hair::mean_curvature_per_m(straight, 0.005), 0.0, 1e-3);
}

}  // namespace
