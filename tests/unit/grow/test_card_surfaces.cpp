// CardSurfaces and fan_triangulation_with_groups() on hand-made cards: two parallel unit
// squares a centimetre apart (groups 0 and 2; group 1 has no faces), so that the nearest
// point of a card is known.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "hair/extract/painted_flow.h"
#include "hair/grow/card_surfaces.h"

namespace hair {
namespace {

struct TwoCards {
  Points3f vertices;
  Triangles3i triangles;
  std::vector<int32_t> triangle_group;
};

/// A quad at z = 0 (group 0) and a triangle and a quad at z = 0.01 (group 2).
TwoCards two_cards() {
  TwoCards cards;
  cards.vertices.resize(8, 3);
  cards.vertices << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,  //
      0, 0, 0.01f, 1, 0, 0.01f, 1, 1, 0.01f, 0, 1, 0.01f;
  const std::vector<int64_t> face_offsets{0, 4, 7, 11};
  const std::vector<int32_t> face_vertices{0, 1, 2, 3, 4, 5, 6, 4, 5, 6, 7};
  fan_triangulation_with_groups(face_offsets, face_vertices, {0, 2, 2}, cards.triangles,
                                cards.triangle_group);
  return cards;
}

TEST(CardSurfaces, FacesFanIntoTrianglesThatKeepTheirGroup) {
  TwoCards cards = two_cards();
  ASSERT_EQ(cards.triangles.rows(), 5);  // 2 + 1 + 2
  EXPECT_EQ(cards.triangle_group, (std::vector<int32_t>{0, 0, 2, 2, 2}));
  Triangles3i triangles;
  std::vector<int32_t> groups;
  EXPECT_THROW(fan_triangulation_with_groups({0, 3}, {0, 1, 2}, {0, 1}, triangles, groups),
               std::invalid_argument);
}

TEST(CardSurfaces, NearestPointOfEachGroupsOwnFaces) {
  TwoCards cards = two_cards();
  CardSurfaces surfaces(cards.vertices, cards.triangles, cards.triangle_group, 3);
  EXPECT_TRUE(surfaces.has(0));
  EXPECT_FALSE(surfaces.has(1));  // no faces
  EXPECT_TRUE(surfaces.has(2));
  EXPECT_FALSE(surfaces.has(3));
  EXPECT_FALSE(surfaces.has(-1));
  // Just above card 2: nearest to it at 2 mm, and to card 0 at 12 mm, which lies under it.
  const Eigen::Vector3d point(0.3, 0.6, 0.012);
  const auto on_lower = surfaces.nearest(0, point);
  const auto on_upper = surfaces.nearest(2, point);
  ASSERT_TRUE(on_lower && on_upper);
  EXPECT_NEAR(on_lower->distance, 0.012, 1e-6);
  EXPECT_NEAR(on_upper->distance, 0.002, 1e-6);
  EXPECT_TRUE(on_lower->closest_point.isApprox(Eigen::Vector3d(0.3, 0.6, 0), 1e-6));
  // Beyond the card's edge: its edge is nearest.
  const auto beside = surfaces.nearest(0, Eigen::Vector3d(1.5, 0.5, 0));
  ASSERT_TRUE(beside);
  EXPECT_NEAR(beside->distance, 0.5, 1e-6);
  EXPECT_FALSE(surfaces.nearest(1, point));
  // Built empty: no group has faces.
  EXPECT_FALSE(CardSurfaces().nearest(0, point));
}

TEST(CardSurfaces, EachTriangleTakesItsFacesPaintWhereItIsClear) {
  // A quad whose strokes are clear (two triangles), a triangle whose strokes are not, a
  // second quad just clear (the threshold itself).
  const std::vector<int64_t> face_offsets{0, 4, 7, 11};
  Points3f face_flow(3, 3);
  face_flow << 1, 0, 0, 0, 1, 0, 0, 0, 1;
  const std::vector<float> coherence{0.9f, 0.29f, static_cast<float>(kClearFlowCoherence)};
  const Points3f flow = fan_painted_flow(face_offsets, face_flow, coherence, kClearFlowCoherence);
  ASSERT_EQ(flow.rows(), 5);
  Points3f expected(5, 3);
  expected << 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 1;
  EXPECT_EQ(flow, expected);
  EXPECT_THROW(fan_painted_flow(face_offsets, face_flow, {0.9f, 0.9f}, kClearFlowCoherence),
               std::invalid_argument);
  EXPECT_THROW(fan_painted_flow(face_offsets, face_flow.topRows(2), coherence, kClearFlowCoherence),
               std::invalid_argument);
}

}  // namespace
}  // namespace hair
