// followed_card_flow_agreement(): grown strands judged against the card they follow, where
// cards cross.
#include <gtest/gtest.h>

#include "hair/core/error.h"
#include "hair/grow/followed_card_flow.h"

namespace hair {
namespace {

/// Two crossing cards, each one quad: card 0 in the plane y = 0 along x (0 to 10 cm, 2 cm
/// wide), its flow along x; card 1 3 mm above it across the middle, along z (10 cm long,
/// 1 cm wide), its flow along z.
struct CrossingCards {
  PolyMesh mesh;
  std::vector<int32_t> face_group{0, 1};
  PaintedFlow flow;
  CrossingCards() {
    mesh.vertices.resize(8, 3);
    mesh.vertices << 0, 0, -0.01, 0.1, 0, -0.01, 0.1, 0, 0.01, 0, 0, 0.01,  //
        0.045, 0.003, -0.05, 0.055, 0.003, -0.05, 0.055, 0.003, 0.05, 0.045, 0.003, 0.05;
    mesh.face_offsets = {0, 4, 8};
    mesh.face_vertices = {0, 1, 2, 3, 4, 5, 6, 7};
    flow.direction = {Eigen::Vector3f::UnitX(), Eigen::Vector3f::UnitZ()};
    flow.coherence = {0.9f, 0.9f};
    flow.alpha_fall = {0, 0};
  }
};

/// A strand 2 mm over card 0 along x, from x = 1 cm to 9 cm in 5 mm steps: under card 1
/// (1 mm below it) between x = 4.5 and 5.5 cm.
StrandSet strand_along_card_zero() {
  Points3f points(17, 3);
  for (int i = 0; i < 17; ++i) points.row(i) << 0.01f + 0.005f * i, 0.002f, 0.0f;
  return strand_set_from_polylines({points});
}

TEST(FollowedCardFlow, AStrandOnItsCardCountsAlongWhereAnotherCardCrossesNearer) {
  const CrossingCards cards;
  const StrandSet strand = strand_along_card_zero();
  const std::vector<int32_t> following_card_zero(17, 0);
  const std::vector<int8_t> along_input_strand(17, 2), along_field(17, 1);
  int64_t judged = 0;
  // Grown along card 0's input strand: every segment judged against card 0.
  EXPECT_DOUBLE_EQ(
      followed_card_flow_agreement(cards.mesh, cards.face_group, cards.flow, strand,
                                   following_card_zero, along_input_strand, 0.3, 30, 0.05, judged),
      1.0);
  EXPECT_EQ(judged, 16);
  // Grown along the field: judged against the nearest face, card 1's flow across it
  // where the strand passes under card 1 (the segments with a midpoint at x 4.5-5.5 cm).
  const double share =
      followed_card_flow_agreement(cards.mesh, cards.face_group, cards.flow, strand,
                                   following_card_zero, along_field, 0.3, 30, 0.05, judged);
  EXPECT_EQ(judged, 16);
  EXPECT_DOUBLE_EQ(share, 14.0 / 16.0);
}

TEST(FollowedCardFlow, UnclearOrFarFacesAreNotJudgedAndMismatchedArraysAreRefused) {
  CrossingCards cards;
  const StrandSet strand = strand_along_card_zero();
  const std::vector<int32_t> groups(17, 0);
  const std::vector<int8_t> rules(17, 2);
  int64_t judged = 0;
  cards.flow.coherence[0] = 0.1f;  // card 0's strokes unclear
  EXPECT_DOUBLE_EQ(followed_card_flow_agreement(cards.mesh, cards.face_group, cards.flow, strand,
                                                groups, rules, 0.3, 30, 0.05, judged),
                   0.0);
  EXPECT_EQ(judged, 0);
  cards.flow.coherence[0] = 0.9f;
  followed_card_flow_agreement(cards.mesh, cards.face_group, cards.flow, strand, groups, rules, 0.3,
                               30, 0.001, judged);  // every face beyond 1 mm
  EXPECT_EQ(judged, 0);
  EXPECT_THROW(followed_card_flow_agreement(cards.mesh, {0}, cards.flow, strand, groups, rules, 0.3,
                                            30, 0.05, judged),
               Error);
  EXPECT_THROW(
      followed_card_flow_agreement(cards.mesh, cards.face_group, cards.flow, strand,
                                   std::vector<int32_t>(3, 0), rules, 0.3, 30, 0.05, judged),
      Error);
}

}  // namespace
}  // namespace hair
