// painted_field_seeds() on hand-made cards: a flat square card (two triangles) whose paint
// runs along x, with input strands of its group beside it, so that the seeds' sense,
// where they lie and when a face says nothing are known; and a card between two strands
// whose paint runs diagonally, to see the field follow the paint between them.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hair/grow/orientation_field.h"
#include "hair/grow/painted_field_seeds.h"

namespace hair {
namespace {

/// A square card [0, side] x [0, side] at z = 0, two triangles of `group`, painted along
/// `axis`.
struct Card {
  Points3f vertices;
  Triangles3i triangles;
  std::vector<int32_t> triangle_group;
  Points3f triangle_flow;
};

Card square_card(float side, int32_t group, const Eigen::Vector3f& axis, float y0 = 0) {
  Card card;
  card.vertices.resize(4, 3);
  card.vertices << 0, y0, 0, side, y0, 0, side, y0 + side, 0, 0, y0 + side, 0;
  card.triangles.resize(2, 3);
  card.triangles << 0, 1, 2, 0, 2, 3;
  card.triangle_group = {group, group};
  card.triangle_flow.resize(2, 3);
  card.triangle_flow.row(0) = axis.transpose();
  card.triangle_flow.row(1) = axis.transpose();
  return card;
}

/// Straight strands from `from` to `to` (rows: one strand each), 11 points, with groups.
StrandSet straight_strands(const std::vector<std::pair<Eigen::Vector3f, Eigen::Vector3f>>& ends,
                           const std::vector<int32_t>& groups) {
  std::vector<Points3f> polylines;
  for (const auto& [from, to] : ends) {
    Points3f points(11, 3);
    for (int i = 0; i <= 10; ++i) points.row(i) = (from + (to - from) * (i / 10.0f)).transpose();
    polylines.push_back(points);
  }
  StrandSet strands = strand_set_from_polylines(polylines);
  strands.strand_attributes["group"] = groups;
  return strands;
}

TEST(PaintedFieldSeeds, SeedsCoverTheFaceAlongItsPaintTheWayItsGroupsStrandsRun) {
  const float side = 0.04f;
  Card card = square_card(side, 0, Eigen::Vector3f::UnitX());
  // Group 0's strand runs along -x across the card's middle.
  const StrandSet strands = straight_strands(
      {{Eigen::Vector3f(side, side / 2, 0.002f), Eigen::Vector3f(0, side / 2, 0.002f)}}, {0});
  PaintedFieldSeedParams params;
  params.spacing_m = 0.0025;
  params.sign_radius_m = 0.03;
  const StrandSet seeds = painted_field_seeds(card.vertices, card.triangles, card.triangle_group,
                                              card.triangle_flow, {1}, strands, params);
  // k = ceil(0.0566 / 0.0025) = 23 divisions a side: 23^2 sub-triangles a triangle.
  ASSERT_EQ(seeds.strand_count(), 2 * 23 * 23);
  const auto& group = std::get<std::vector<int32_t>>(seeds.strand_attributes.at("group"));
  std::vector<int> per_cell(64, 0);  // 8 x 8 cells of 5 mm
  for (int64_t s = 0; s < seeds.strand_count(); ++s) {
    EXPECT_EQ(group[static_cast<size_t>(s)], 0);
    ASSERT_EQ(seeds.strand_size(s), 2);
    const Eigen::Vector3f segment =
        seeds.points.row(seeds.offsets[s] + 1) - seeds.points.row(seeds.offsets[s]);
    EXPECT_NEAR(segment.x(), -0.5 * params.spacing_m, 1e-7);  // along -x, as the strand
    EXPECT_NEAR(segment.y(), 0, 1e-7);
    const Eigen::Vector3f middle =
        0.5f * (seeds.points.row(seeds.offsets[s]) + seeds.points.row(seeds.offsets[s] + 1));
    ASSERT_GE(middle.x(), 0);
    ASSERT_LE(middle.x(), side);
    ASSERT_GE(middle.y(), 0);
    ASSERT_LE(middle.y(), side);
    ++per_cell[static_cast<size_t>(std::min(7, static_cast<int>(middle.x() / 0.005f)) * 8 +
                                   std::min(7, static_cast<int>(middle.y() / 0.005f)))];
  }
  for (int count : per_cell) EXPECT_GE(count, 4);  // every 5 mm of the card is seeded
}

TEST(PaintedFieldSeeds, AFaceSaysNothingWhereItsGroupsStrandsDisagreeOrCrossItsPaint) {
  const float side = 0.04f;
  PaintedFieldSeedParams params;
  params.sign_radius_m = 0.03;
  // A parting: two strands of the group beside each other, running apart.
  const StrandSet parted = straight_strands(
      {{Eigen::Vector3f(0.02f, 0.018f, 0.002f), Eigen::Vector3f(0, 0.018f, 0.002f)},
       {Eigen::Vector3f(0.02f, 0.022f, 0.002f), Eigen::Vector3f(side, 0.022f, 0.002f)}},
      {0, 0});
  Card card = square_card(side, 0, Eigen::Vector3f::UnitX());
  EXPECT_EQ(painted_field_seeds(card.vertices, card.triangles, card.triangle_group,
                                card.triangle_flow, {1}, parted, params)
                .strand_count(),
            0);
  // Strokes across the strands (along y, the strand along x).
  const StrandSet along_x = straight_strands(
      {{Eigen::Vector3f(0, side / 2, 0.002f), Eigen::Vector3f(side, side / 2, 0.002f)}}, {0});
  Card across = square_card(side, 0, Eigen::Vector3f::UnitY());
  EXPECT_EQ(painted_field_seeds(across.vertices, across.triangles, across.triangle_group,
                                across.triangle_flow, {1}, along_x, params)
                .strand_count(),
            0);
  // Strokes at 45 degrees to it still seed, signed its way.
  Card diagonal = square_card(side, 0, Eigen::Vector3f(-1, -1, 0).normalized());
  const StrandSet seeds =
      painted_field_seeds(diagonal.vertices, diagonal.triangles, diagonal.triangle_group,
                          diagonal.triangle_flow, {1}, along_x, params);
  ASSERT_GT(seeds.strand_count(), 0);
  EXPECT_GT(seeds.points(1, 0) - seeds.points(0, 0), 0);
}

TEST(PaintedFieldSeeds, OnlyTheSeedingGroupsFacesSeedSignedByTheirOwnStrands) {
  const float side = 0.04f;
  PaintedFieldSeedParams params;
  params.sign_radius_m = 0.03;
  const StrandSet group0 = straight_strands(
      {{Eigen::Vector3f(0, side / 2, 0.002f), Eigen::Vector3f(side, side / 2, 0.002f)}}, {0});
  // The card is group 1's; only group 0 has strands.
  Card card = square_card(side, 1, Eigen::Vector3f::UnitX());
  EXPECT_EQ(painted_field_seeds(card.vertices, card.triangles, card.triangle_group,
                                card.triangle_flow, {1, 1}, group0, params)
                .strand_count(),
            0);
  // Group 0's card, but group 0 does not seed (its strands do not carry roots).
  Card own = square_card(side, 0, Eigen::Vector3f::UnitX());
  EXPECT_EQ(painted_field_seeds(own.vertices, own.triangles, own.triangle_group, own.triangle_flow,
                                {0}, group0, params)
                .strand_count(),
            0);
  // A face without clear paint (zero axis) and a triangle of no group.
  own.triangle_flow.row(0).setZero();
  own.triangle_group[1] = -1;
  EXPECT_EQ(painted_field_seeds(own.vertices, own.triangles, own.triangle_group, own.triangle_flow,
                                {1}, group0, params)
                .strand_count(),
            0);
}

TEST(PaintedFieldSeeds, BetweenTwoStrandsTheFieldFollowsThePaint) {
  // Two rails of one card 6 cm apart along x; between them the card's paint runs at 40
  // degrees to them (the hair turns between its rails, as it does round a whorl). The field
  // from the rails alone runs along x there; seeded by the paint, it turns with it.
  const StrandSet rails =
      straight_strands({{Eigen::Vector3f(0, 0, 0), Eigen::Vector3f(0.06f, 0, 0)},
                        {Eigen::Vector3f(0, 0.06f, 0), Eigen::Vector3f(0.06f, 0.06f, 0)}},
                       {0, 0});
  const double angle = 40 * std::acos(-1.0) / 180;
  const Eigen::Vector3f axis(static_cast<float>(std::cos(angle)),
                             static_cast<float>(std::sin(angle)), 0);
  Card card = square_card(0.02f, 0, axis, 0.02f);
  card.vertices.col(0).array() += 0.02f;  // the card spans [0.02, 0.04] in x and y
  PaintedFieldSeedParams params;
  params.spacing_m = 0.0025;
  params.sign_radius_m = 0.04;
  const StrandSet seeds = painted_field_seeds(card.vertices, card.triangles, card.triangle_group,
                                              card.triangle_flow, {1}, rails, params);
  ASSERT_GT(seeds.strand_count(), 0);
  std::vector<Points3f> polylines{rails.strand(0), rails.strand(1)};
  OrientationFieldParams field_params{0.005, 0.03};
  const OrientationField plain =
      OrientationField::build(strand_set_from_polylines(polylines), {0, 1}, field_params);
  for (int64_t s = 0; s < seeds.strand_count(); ++s) polylines.emplace_back(seeds.strand(s));
  std::vector<int64_t> ids(polylines.size());
  for (size_t i = 0; i < ids.size(); ++i) ids[i] = static_cast<int64_t>(i);
  const OrientationField painted =
      OrientationField::build(strand_set_from_polylines(polylines), ids, field_params);
  const Eigen::Vector3d centre(0.03, 0.03, 0);
  ASSERT_TRUE(plain.direction(centre));
  ASSERT_TRUE(painted.direction(centre));
  EXPECT_GT(plain.direction(centre)->x(), 0.99);
  EXPECT_GT(painted.direction(centre)->dot(axis.cast<double>()), 0.99);
}

}  // namespace
}  // namespace hair
