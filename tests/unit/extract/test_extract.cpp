// extract_strands on hand-made hair with known roots: every strand must run root to tip
// whatever the vertex order, triangulation or texture, and the rule used is recorded.
#include <gtest/gtest.h>
#include <omp.h>

#include "hair/extract/extract.h"
#include "unit/synthetic_hair.h"

namespace hair {
namespace {

using testing::falling_polyline;
using testing::hair_strip;
using testing::head_point;
using testing::snowman_body;
using testing::StripOptions;

/// Distance from a point to the snowman's head sphere.
double head_distance(const Eigen::Vector3f& p) {
  return std::abs((p.cast<double>() - Eigen::Vector3d(0, 1.6, 0)).norm() - 0.1);
}

/// Strips hanging from the head all around, each built a different way.
struct HangingHair {
  PolyMesh mesh;
  std::vector<std::string> labels;  ///< per patch
};

HangingHair hanging_hair() {
  HangingHair hair;
  std::vector<std::pair<std::string, StripOptions>> variants = {
      {"ordered", {}},
      {"reversed", {.reverse_order = true}},
      {"shuffled", {.shuffle_order = true, .seed = 3}},
      {"shuffled without uv", {.shuffle_order = true, .with_uv = false, .seed = 4}},
      {"reversed without uv", {.reverse_order = true, .with_uv = false}},
      {"triangulated", {.triangulate = true}},
      {"triangulated and shuffled", {.shuffle_order = true, .triangulate = true, .seed = 5}},
      {"four rails", {.rails = 4}},
      {"single quad", {.segments = 1}},
      {"single quad reversed", {.segments = 1, .reverse_order = true}},
      {"long grid", {.rails = 6, .segments = 30}},
      {"long grid shuffled", {.rails = 6, .segments = 30, .shuffle_order = true, .seed = 6}},
  };
  for (size_t i = 0; i < variants.size(); ++i) {
    double azimuth =
        2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(variants.size());
    Eigen::Vector3d root = head_point(azimuth, 1.0);
    Eigen::Vector3d outward = (root - Eigen::Vector3d(0, 1.6, 0)).normalized();
    Eigen::Vector3d across = outward.cross(Eigen::Vector3d::UnitY()).normalized();
    const StripOptions& options = variants[i].second;
    double length = options.segments == 1 ? 0.08 : 0.3;
    auto centre = falling_polyline(root, outward, length, options.segments, 0.5 * length);
    testing::append_mesh(hair.mesh, hair_strip(centre, across, 0.03, options));
    hair.labels.push_back(variants[i].first);
  }
  return hair;
}

TEST(ExtractStrands, EveryStrandOfHangingStripsRunsRootToTip) {
  HangingHair hair = hanging_hair();
  ExtractResult result = extract_strands(hair.mesh, snowman_body(), {}, "hair", "body");
  ASSERT_EQ(result.group_count(), static_cast<int32_t>(hair.labels.size()));
  for (int32_t g = 0; g < result.group_count(); ++g) {
    ASSERT_GE(result.group_first_strand[g + 1] - result.group_first_strand[g], 2) << hair.labels[g];
    for (int32_t s = result.group_first_strand[g]; s < result.group_first_strand[g + 1]; ++s) {
      auto strand = result.strands.strand(s);
      EXPECT_LT(head_distance(strand.row(0).transpose()), 0.01) << hair.labels[g];
      EXPECT_GT(head_distance(strand.row(strand.rows() - 1).transpose()), 0.04) << hair.labels[g];
    }
  }
}

TEST(ExtractStrands, RecordsWhichRuleDecidedEachGroup) {
  HangingHair hair = hanging_hair();
  ExtractResult result = extract_strands(hair.mesh, snowman_body(), {}, "hair", "body");
  for (int32_t g = 0; g < result.group_count(); ++g) {
    const std::string& label = hair.labels[g];
    OrientationRule rule = result.group_rule[g];
    if (label == "ordered" || label == "four rails" || label == "long grid") {
      EXPECT_EQ(rule, OrientationRule::vertex_order) << label;
    }
    // Reversed ids are contradicted by the head distance, which then decides.
    if (label == "reversed" || label == "long grid shuffled") {
      EXPECT_EQ(rule, OrientationRule::scalp_distance) << label;
    }
    EXPECT_GE(result.group_confidence[g], 0.0f);
    EXPECT_LE(result.group_confidence[g], 1.0f);
  }
  EXPECT_EQ(result.stats.groups_by_rule[static_cast<size_t>(OrientationRule::height)], 0);
}

TEST(ExtractStrands, TriangulatedStripsArePairedBackIntoQuads) {
  HangingHair hair = hanging_hair();
  ExtractResult result = extract_strands(hair.mesh, snowman_body(), {}, "hair", "body");
  EXPECT_GT(result.stats.triangles_paired, 0);
  EXPECT_EQ(result.stats.triangles_left, 0);
  for (int32_t g = 0; g < result.group_count(); ++g)
    if (hair.labels[g].starts_with("triangulated")) {
      EXPECT_EQ(result.group_first_strand[g + 1] - result.group_first_strand[g], 2);  // two rails
      EXPECT_EQ(result.strands.strand_size(result.group_first_strand[g]), 11);
    }
}

TEST(ExtractStrands, StrandsKeepTheirSourceVerticesAndGroups) {
  HangingHair hair = hanging_hair();
  ExtractResult result = extract_strands(hair.mesh, snowman_body(), {}, "hair", "body");
  const auto& source =
      std::get<std::vector<int32_t>>(result.strands.point_attributes.at("source_vertex"));
  const auto& group = std::get<std::vector<int32_t>>(result.strands.strand_attributes.at("group"));
  for (int64_t i = 0; i < result.strands.point_count(); ++i)
    ASSERT_TRUE(result.strands.points.row(i).isApprox(result.hair_mesh.vertices.row(source[i])));
  for (int64_t s = 0; s < result.strands.strand_count(); ++s)
    EXPECT_TRUE(s >= result.group_first_strand[group[s]] &&
                s < result.group_first_strand[group[s] + 1]);
}

TEST(ExtractStrands, CardDrapedOverTheCrownIsPartedAtItsTop) {
  // From the left shoulder up over the crown and down to the right shoulder.
  std::vector<Eigen::Vector3d> centre;
  for (int i = 0; i <= 40; ++i) {
    double t = i / 40.0;
    double polar = std::numbers::pi * (t - 0.5) * 1.1;  // -99 to +99 degrees over the top
    Eigen::Vector3d on_head(0.108 * std::sin(polar), 1.6 + 0.108 * std::cos(polar), 0);
    if (std::abs(polar) > std::numbers::pi / 2)
      on_head.y() -= 0.3 * (std::abs(polar) - std::numbers::pi / 2);
    centre.push_back(on_head);
  }
  // Hang the ends well off the head.
  centre.front() += Eigen::Vector3d(-0.05, -0.15, 0);
  centre.back() += Eigen::Vector3d(0.05, -0.15, 0);
  PolyMesh card = hair_strip(centre, Eigen::Vector3d::UnitZ(), 0.04, {.shuffle_order = true});
  ExtractResult result = extract_strands(card, snowman_body(), {}, "hair", "body");
  ASSERT_EQ(result.group_count(), 1);
  EXPECT_EQ(result.group_rule[0], OrientationRule::parting);
  ASSERT_EQ(result.strands.strand_count(), 4);
  for (int64_t s = 0; s < 4; ++s) {
    auto strand = result.strands.strand(s);
    EXPECT_GT(strand(0, 1), 1.69f);                 // starts at the crown
    EXPECT_LT(strand(strand.rows() - 1, 1), 1.5f);  // ends hanging low
  }
}

TEST(ExtractStrands, CapRunsIntoTheTailThatContinuesIt) {
  // A ponytail: cap rails on the head from the forehead over the top to a band at the
  // back that sits higher than the forehead, and a tail hanging from the band. Height
  // alone would take the band for the root; the tail starting there says otherwise.
  Eigen::Vector3d band = head_point(-std::numbers::pi / 2, 0.9);
  std::vector<Eigen::Vector3d> cap_centre;
  for (int i = 0; i <= 20; ++i) {
    double polar = -1.3 + (0.9 + 1.3) * i / 20.0;  // front (z>0) over the top to the back
    cap_centre.push_back({0, 1.6 + 0.105 * std::cos(polar), 0.105 * std::sin(-polar)});
  }
  cap_centre.back() = band;
  PolyMesh mesh = hair_strip(cap_centre, Eigen::Vector3d::UnitX(), 0.05,
                             {.rails = 5, .segments = 20, .shuffle_order = true, .with_uv = false});
  auto tail =
      falling_polyline(band + Eigen::Vector3d(0, 0, -0.003), Eigen::Vector3d(0, -1, -0.6), 0.3, 12);
  testing::append_mesh(mesh, hair_strip(tail, Eigen::Vector3d::UnitX(), 0.03,
                                        {.rails = 3, .segments = 12, .with_uv = false}));
  ExtractResult result = extract_strands(mesh, snowman_body(), {}, "hair", "body");
  ASSERT_EQ(result.group_count(), 2);
  EXPECT_EQ(result.group_rule[0], OrientationRule::continuation);
  for (int32_t s = result.group_first_strand[0]; s < result.group_first_strand[1]; ++s) {
    auto strand = result.strands.strand(s);
    EXPECT_GT(strand(0, 2), 0.05f);                   // root at the front
    EXPECT_LT(strand(strand.rows() - 1, 2), -0.05f);  // tip at the band, behind
  }
}

/// A lock wound level round the back of the head, 4 cm off it, in `pieces` cards meeting
/// end to end, the lock running from azimuth 0.3 on; `reversed` marks the pieces whose
/// vertex ids run from tip to root. A braid's pieces cross nearly level like this: neither
/// the head distance nor the height says which way a piece runs, so the ids decide.
PolyMesh level_lock(int pieces, const std::vector<bool>& reversed) {
  PolyMesh mesh;
  constexpr double radius_m = 0.14, piece_rad = 0.5, gap_rad = 0.01;
  for (int k = 0; k < pieces; ++k) {
    std::vector<Eigen::Vector3d> centre;
    for (int i = 0; i <= 6; ++i) {
      double azimuth = 0.3 + piece_rad * k + (piece_rad - gap_rad) * i / 6.0;
      centre.push_back({radius_m * std::cos(azimuth), 1.6, -radius_m * std::sin(azimuth)});
    }
    testing::append_mesh(
        mesh,
        hair_strip(centre, Eigen::Vector3d::UnitY(), 0.02,
                   {.rails = 3, .segments = 6, .reverse_order = reversed[k], .with_uv = false}));
  }
  return mesh;
}

/// Whether every strand of group `g` runs the lock's way (its azimuth grows).
bool group_runs_along_the_lock(const ExtractResult& result, int32_t g) {
  for (int32_t s = result.group_first_strand[g]; s < result.group_first_strand[g + 1]; ++s) {
    auto strand = result.strands.strand(s);
    auto azimuth = [&](Eigen::Index i) { return std::atan2(-strand(i, 2), strand(i, 0)); };
    if (!(azimuth(strand.rows() - 1) > azimuth(0))) return false;
  }
  return true;
}

TEST(ExtractStrands, APieceNumberedBackwardsInALockOffTheHeadFollowsTheLock) {
  // The middle piece of five is numbered tip to root; the pieces on either side run on
  // through both its ends, so it is turned (rule continuation).
  ExtractResult result = extract_strands(level_lock(5, {false, false, true, false, false}),
                                         snowman_body(), {}, "hair", "body");
  ASSERT_EQ(result.group_count(), 5);
  EXPECT_EQ(result.stats.continuation_overruled_ids, 1);
  EXPECT_EQ(result.group_rule[2], OrientationRule::continuation);
  for (int32_t g = 0; g < 5; ++g) EXPECT_TRUE(group_runs_along_the_lock(result, g)) << g;

  // Two backward pieces side by side: each has one neighbour running on through one end
  // and one running against it through the other, so neither is turned (the ids stay).
  ExtractResult pair = extract_strands(level_lock(5, {false, true, true, false, false}),
                                       snowman_body(), {}, "hair", "body");
  ASSERT_EQ(pair.group_count(), 5);
  EXPECT_EQ(pair.stats.continuation_overruled_ids, 0);
  EXPECT_EQ(pair.group_rule[1], OrientationRule::vertex_order);
  EXPECT_EQ(pair.group_rule[2], OrientationRule::vertex_order);
}

TEST(ExtractStrands, APieceOnTheHeadKeepsItsIdsWhereStrandsMeetHeadOn) {
  // The same lock laid on the head (5 mm off it, inside height_min_head_distance_h):
  // cap strands converging head-on at a band or a whorl meet end to end just as one
  // lock's pieces do, so on the head the ids are not overruled.
  PolyMesh mesh;
  for (int k = 0; k < 3; ++k) {
    std::vector<Eigen::Vector3d> centre;
    for (int i = 0; i <= 6; ++i) {
      double azimuth = 0.3 + 0.5 * k + 0.49 * i / 6.0;
      centre.push_back({0.105 * std::cos(azimuth), 1.6, -0.105 * std::sin(azimuth)});
    }
    testing::append_mesh(
        mesh, hair_strip(centre, Eigen::Vector3d::UnitY(), 0.02,
                         {.rails = 3, .segments = 6, .reverse_order = k == 1, .with_uv = false}));
  }
  ExtractResult result = extract_strands(mesh, snowman_body(), {}, "hair", "body");
  ASSERT_EQ(result.group_count(), 3);
  EXPECT_EQ(result.stats.continuation_overruled_ids, 0);
  EXPECT_EQ(result.group_rule[1], OrientationRule::vertex_order);
}

/// A short cap: nine strips lying on the head 5 mm off it, from 40 to 100 degrees off
/// the crown at azimuths 40 degrees apart, textured root to tip; `reversed` of them
/// (every third) numbered tip to root. The head distance does not change along them; the
/// height falls from every root.
PolyMesh short_cap_lying_on_the_head(int reversed) {
  PolyMesh mesh;
  for (int k = 0; k < 9; ++k) {
    const double azimuth = 40.0 * k * std::numbers::pi / 180;
    std::vector<Eigen::Vector3d> lying;
    for (int i = 0; i <= 12; ++i) {
      double polar = (40.0 + 60.0 * i / 12.0) * std::numbers::pi / 180;
      lying.push_back({0.105 * std::sin(polar) * std::cos(azimuth), 1.6 + 0.105 * std::cos(polar),
                       -0.105 * std::sin(polar) * std::sin(azimuth)});
    }
    const Eigen::Vector3d across(std::sin(azimuth), 0, std::cos(azimuth));
    testing::append_mesh(
        mesh,
        hair_strip(lying, across, 0.02,
                   {.rails = 3, .segments = 12, .reverse_order = k % 3 == 0 && k / 3 < reversed}));
  }
  return mesh;
}

TEST(ExtractStrands, ACapOfStripsNumberedEitherWayLearnsItsTextureFromTheRestAndFollowsIt) {
  // Three of nine strips numbered tip to root: their ids alone decided against their
  // height, so they do not teach the texture's convention; the six others do (v grows
  // to the tip on all of them), and the three are then turned by their height and
  // texture. Learnt from all nine, v would agree on 6 of 9, under the 85% asked.
  ExtractResult result =
      extract_strands(short_cap_lying_on_the_head(3), snowman_body(), {}, "hair", "body");
  ASSERT_EQ(result.group_count(), 9);
  EXPECT_EQ(result.stats.uv_growth_sign, 1);
  EXPECT_EQ(result.stats.height_and_texture_overruled_ids, 3);
  for (int32_t s = 0; s < result.strands.strand_count(); ++s) {
    auto strand = result.strands.strand(s);
    EXPECT_GT(strand(0, 1), strand(strand.rows() - 1, 1)) << s;  // from the higher end
  }
}

/// `count` strips hanging from the head at azimuths 0.5 rad apart from `first_azimuth`,
/// the first `reversed` numbered tip to root: the head distance decides each of them.
void append_hanging_strips(PolyMesh& mesh, int count, int reversed, double first_azimuth) {
  for (int i = 0; i < count; ++i) {
    Eigen::Vector3d root = head_point(first_azimuth + 0.5 * i, 1.0);
    Eigen::Vector3d outward = (root - Eigen::Vector3d(0, 1.6, 0)).normalized();
    Eigen::Vector3d across = outward.cross(Eigen::Vector3d::UnitY()).normalized();
    testing::append_mesh(mesh, hair_strip(falling_polyline(root, outward, 0.3, 10, 0.15), across,
                                          0.03, {.segments = 10, .reverse_order = i < reversed}));
  }
}

TEST(ExtractStrands, IdsAreIgnoredWhereTheHeadDistanceContradictsMostOfThemNotAHandful) {
  // Twelve hanging strips, nine numbered tip to root: the head distance decides all and
  // contradicts the ids on most, so the mesh's ids are not trusted.
  PolyMesh backwards;
  append_hanging_strips(backwards, 12, 9, 0.0);
  ExtractResult ignored = extract_strands(backwards, snowman_body(), {}, "hair", "body");
  EXPECT_FALSE(ignored.stats.vertex_order_trusted);
  // A cap of nine strips lying on the head, numbered right (the head distance silent),
  // and three strips hanging below it, two numbered tip to root: the head distance
  // contradicts the ids on two of the three regions where it decides, but those are
  // two of twelve regions with ordered ids, so the ids are kept.
  PolyMesh cap = short_cap_lying_on_the_head(0);
  append_hanging_strips(cap, 3, 2, 0.2);
  ExtractResult kept = extract_strands(cap, snowman_body(), {}, "hair", "body");
  ASSERT_EQ(kept.group_count(), 12);
  EXPECT_TRUE(kept.stats.vertex_order_trusted);
  for (int32_t g = 0; g < 9; ++g) EXPECT_EQ(kept.group_rule[g], OrientationRule::vertex_order) << g;
  for (int32_t s = 0; s < kept.strands.strand_count(); ++s) {
    auto strand = kept.strands.strand(s);
    Eigen::Vector3f first = strand.row(0).transpose(),
                    last = strand.row(strand.rows() - 1).transpose();
    EXPECT_LT(head_distance(first), head_distance(last) + 1e-3) << s;  // from the head
    if (s < 27) {  // the cap's strips, from the higher end
      EXPECT_GT(first.y(), last.y()) << s;
    }
  }
}

/// A lock of `pieces` cards wound level half round the back of the head (2.5 rad),
/// numbered and textured root to tip (`with_uv`), 5.5 cm off the head but for piece
/// `weaving`, which weaves in to 2.5 cm as a braid's piece crosses towards the head: its
/// head distance falls by 3 cm over its 4-7 cm, so it alone says that piece runs from its
/// far end, against its ids; the pieces after it run on at 2.5 cm.
PolyMesh lock_with_a_piece_weaving_in(int pieces, int weaving, bool with_uv) {
  PolyMesh mesh;
  const double piece_rad = 2.5 / pieces, gap_rad = 0.01, far_m = 0.155, near_m = 0.125;
  for (int k = 0; k < pieces; ++k) {
    std::vector<Eigen::Vector3d> centre;
    for (int i = 0; i <= 6; ++i) {
      double azimuth = 0.3 + piece_rad * k + (piece_rad - gap_rad) * i / 6.0;
      double radius_m = k < weaving   ? far_m
                        : k > weaving ? near_m
                                      : far_m + (near_m - far_m) * i / 6.0;
      centre.push_back({radius_m * std::cos(azimuth), 1.6, -radius_m * std::sin(azimuth)});
    }
    testing::append_mesh(mesh, hair_strip(centre, Eigen::Vector3d::UnitY(), 0.02,
                                          {.rails = 3, .segments = 6, .with_uv = with_uv}));
  }
  return mesh;
}

TEST(ExtractStrands, APieceWeavingTowardsTheHeadFollowsItsIdsAndTheLock) {
  // Untextured: the head distance decides the weaving piece against its ids, and the
  // pieces on either side run on through both its ends: two cues against one, so it is
  // turned back (rule continuation).
  ExtractResult untextured = extract_strands(lock_with_a_piece_weaving_in(5, 2, false),
                                             snowman_body(), {}, "hair", "body");
  ASSERT_EQ(untextured.group_count(), 5);
  EXPECT_EQ(untextured.stats.continuation_overruled_ids, 1);
  EXPECT_EQ(untextured.group_rule[2], OrientationRule::continuation);
  for (int32_t g = 0; g < 5; ++g) EXPECT_TRUE(group_runs_along_the_lock(untextured, g)) << g;

  // Textured root to tip as the other seven pieces are (the mesh's convention): the
  // texture's v backs the ids before continuation is asked (rule uv).
  ExtractResult textured =
      extract_strands(lock_with_a_piece_weaving_in(8, 2, true), snowman_body(), {}, "hair", "body");
  ASSERT_EQ(textured.group_count(), 8);
  EXPECT_EQ(textured.stats.uv_growth_sign, 1);
  EXPECT_EQ(textured.stats.ids_and_texture_overruled_head_distance, 1);
  EXPECT_EQ(textured.group_rule[2], OrientationRule::uv);
  for (int32_t g = 0; g < 8; ++g) EXPECT_TRUE(group_runs_along_the_lock(textured, g)) << g;
}

/// Eight strips hanging from the head, numbered and textured root to tip (the head
/// distance decides them and teaches extract the mesh's texture convention: 8 of the 9
/// regions' v grows from the end decided as the root, over the 85% asked), and one
/// lying down the side of the head from 40 to 100 degrees off the crown, 5 mm off it,
/// numbered tip to root: its head distance does not change, but it falls 10 cm from its
/// root.
PolyMesh hanging_strips_and_one_lying_backwards(bool lying_with_uv) {
  PolyMesh mesh;
  for (int i = 0; i < 8; ++i) {
    double azimuth = 0.9 + 0.6 * i;
    Eigen::Vector3d root = head_point(azimuth, 1.0);
    Eigen::Vector3d outward = (root - Eigen::Vector3d(0, 1.6, 0)).normalized();
    Eigen::Vector3d across = outward.cross(Eigen::Vector3d::UnitY()).normalized();
    testing::append_mesh(mesh, hair_strip(falling_polyline(root, outward, 0.3, 10, 0.15), across,
                                          0.03, {.segments = 10}));
  }
  std::vector<Eigen::Vector3d> lying;
  for (int i = 0; i <= 12; ++i) {
    double polar = (40.0 + 60.0 * i / 12.0) * std::numbers::pi / 180;
    lying.push_back({0.105 * std::sin(polar), 1.6 + 0.105 * std::cos(polar), 0});
  }
  testing::append_mesh(
      mesh,
      hair_strip(lying, Eigen::Vector3d::UnitZ(), 0.02,
                 {.rails = 3, .segments = 12, .reverse_order = true, .with_uv = lying_with_uv}));
  return mesh;
}

TEST(ExtractStrands, HairLyingDownTheHeadNumberedBackwardsFollowsItsHeightAndTexture) {
  ExtractResult result = extract_strands(hanging_strips_and_one_lying_backwards(true),
                                         snowman_body(), {}, "hair", "body");
  ASSERT_EQ(result.group_count(), 9);
  EXPECT_EQ(result.stats.uv_growth_sign, 1);
  EXPECT_EQ(result.stats.height_and_texture_overruled_ids, 1);
  EXPECT_EQ(result.group_rule[8], OrientationRule::height);
  for (int32_t s = result.group_first_strand[8]; s < result.group_first_strand[9]; ++s) {
    auto strand = result.strands.strand(s);
    EXPECT_GT(strand(0, 1), strand(strand.rows() - 1, 1));  // from the higher end, its root
  }
  // Without a texture the height alone does not overrule the ids (hair brushed up rises
  // from its root): the strip is read as numbered.
  ExtractResult untextured = extract_strands(hanging_strips_and_one_lying_backwards(false),
                                             snowman_body(), {}, "hair", "body");
  ASSERT_EQ(untextured.group_count(), 9);
  EXPECT_EQ(untextured.stats.height_and_texture_overruled_ids, 0);
  EXPECT_EQ(untextured.group_rule[8], OrientationRule::vertex_order);
}

TEST(ExtractStrands, MeasuresTheHeadAndMarksTheScalp) {
  ExtractResult result = extract_strands(hanging_hair().mesh, snowman_body(), {}, "hair", "body");
  EXPECT_NEAR(result.head.head_top_y, 1.7, 0.01);
  EXPECT_GE(result.head.neck_y, 1.39);
  EXPECT_LE(result.head.neck_y, 1.57);
  int64_t scalp = 0;
  for (Eigen::Index t = 0; t < result.body_triangles.rows(); ++t) {
    if (!result.scalp_triangle[t]) continue;
    ++scalp;
    Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
    for (int k = 0; k < 3; ++k)
      centroid += result.body_vertices.row(result.body_triangles(t, k)).transpose() / 3;
    EXPECT_GE(centroid.y(), result.head.neck_y);  // on the head
  }
  EXPECT_GT(scalp, 0);
}

TEST(ExtractStrands, UnitScaleConvertsToMetresAndHeadHeightCanBeGiven) {
  PolyMesh hair = hanging_hair().mesh, body = snowman_body();
  hair.vertices *= 10.0f;  // decimetres
  body.vertices *= 10.0f;
  ExtractParams params;
  params.unit_scale = 0.1;
  ExtractResult result = extract_strands(hair, body, params, "hair", "body");
  EXPECT_NEAR(result.head.head_top_y, 1.7, 0.01);
  EXPECT_LT(result.strands.points.cwiseAbs().maxCoeff(), 2.0f);
  params.head_height_m = 0.2;
  result = extract_strands(hair, body, params, "hair", "body");
  EXPECT_DOUBLE_EQ(result.head.head_height, 0.2);
  EXPECT_NEAR(result.head.neck_y, result.head.head_top_y - 0.2, 1e-9);
}

TEST(ExtractStrands, SameResultForAnyThreadCountAndRun) {
  HangingHair hair = hanging_hair();
  int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  ExtractResult one = extract_strands(hair.mesh, snowman_body(), {}, "hair", "body");
  omp_set_num_threads(std::max(2, threads));
  ExtractResult many = extract_strands(hair.mesh, snowman_body(), {}, "hair", "body");
  omp_set_num_threads(threads);
  EXPECT_EQ(one.strands.offsets, many.strands.offsets);
  EXPECT_TRUE(one.strands.points == many.strands.points);
  EXPECT_EQ(one.group_rule, many.group_rule);
  EXPECT_EQ(one.group_confidence, many.group_confidence);
  EXPECT_EQ(one.scalp_triangle, many.scalp_triangle);
}

TEST(ExtractStrands, PatchWithoutQuadsGivesOneStrandAlongItsAxis) {
  // A fan of triangles around a root vertex: no pairs form quads at right angles.
  PolyMesh fan;
  fan.vertices.resize(7, 3);
  Eigen::Vector3d root = head_point(0.3, 1.2);
  fan.vertices.row(0) = root.cast<float>().transpose();
  for (int i = 1; i < 7; ++i)
    fan.vertices.row(i) =
        (root + Eigen::Vector3d(0.01 * std::cos(i), -0.05 * i, 0.01 * std::sin(i)))
            .cast<float>()
            .transpose();
  for (int32_t i = 1; i < 6; ++i) fan.append_face(std::vector<int32_t>{0, i, i + 1});
  ExtractParams params;
  params.max_quad_corner_deviation_deg = 5;
  ExtractResult result = extract_strands(fan, snowman_body(), params, "hair", "body");
  ASSERT_EQ(result.group_count(), 1);
  EXPECT_EQ(result.group_kind[0], PatchKind::triangle_soup);
  ASSERT_EQ(result.strands.strand_count(), 1);
  auto strand = result.strands.strand(0);
  EXPECT_GT(strand(0, 1), strand(strand.rows() - 1, 1));  // from the head down
}

}  // namespace
}  // namespace hair

namespace hair {
namespace {

TEST(DecideOrientation, IdsGiveWayWhereTheHeadDistanceLeansAndTheHeightDecidesAgainstThem) {
  // Medium hair lying down the side of the head from its root, numbered tip to root
  // (the ids vote to reverse its rails): along the rails the head distance grows by
  // only 1.5 cm over 15 cm (slope 0.1, under the 0.2 that decides), but the height
  // falls by 12 cm (height slope 0.8), so both say the rails start at the root.
  OrientationThresholds thresholds;
  OrientationEvidence lying{.vertex_order_vote = -1,
                            .has_ordered_rails = true,
                            .scalp_distance_slope = 0.1,
                            .height_slope = 0.8};
  auto decision = decide_orientation(lying, thresholds, std::nullopt);
  ASSERT_TRUE(decision.has_value());
  EXPECT_EQ(decision->rule, OrientationRule::height);
  EXPECT_FALSE(decision->reverse);  // the rails run from their root, not as the ids say
  EXPECT_NEAR(decision->confidence, 0.8, 1e-6);

  // Either cue alone leaves the ids: the distance under its lean (a cap lying flat, or
  // a piece hanging level beside the head)...
  OrientationEvidence flat = lying;
  flat.scalp_distance_slope = 0.02;
  EXPECT_EQ(decide_orientation(flat, thresholds, std::nullopt)->rule,
            OrientationRule::vertex_order);
  // ...the height faint...
  OrientationEvidence level = lying;
  level.height_slope = 0.1;
  EXPECT_EQ(decide_orientation(level, thresholds, std::nullopt)->rule,
            OrientationRule::vertex_order);
  // ...or the two at odds (short hair brushed up: its root nearer the head but lower).
  OrientationEvidence brushed_up = lying;
  brushed_up.height_slope = -0.8;
  decision = decide_orientation(brushed_up, thresholds, std::nullopt);
  EXPECT_EQ(decision->rule, OrientationRule::vertex_order);
  EXPECT_TRUE(decision->reverse);
}

TEST(DecideOrientation, AClearAlphaFadeDecidesAfterTheHeadDistanceAndContinuation) {
  OrientationThresholds thresholds;
  OrientationEvidence evidence;
  evidence.alpha_fade_vote = -0.9;  // the alpha falls towards the rails' first points
  evidence.alpha_fade_mean_fall = 0.1;
  // Not in the first pass, which feeds continuation: only with the mesh's conventions.
  EXPECT_FALSE(decide_orientation(evidence, thresholds, std::nullopt).has_value());
  const MeshConventions conventions{true, 1};
  evidence.uv_growth = 0.9;  // and before the texture's v convention
  auto decision = decide_orientation(evidence, thresholds, conventions);
  ASSERT_TRUE(decision.has_value());
  EXPECT_TRUE(decision->reverse);
  EXPECT_EQ(decision->rule, OrientationRule::alpha_fade);
  EXPECT_NEAR(decision->confidence, 0.9, 1e-6);

  // A decisive head distance comes first.
  evidence.scalp_distance_slope = 0.5;
  decision = decide_orientation(evidence, thresholds, conventions);
  ASSERT_TRUE(decision.has_value());
  EXPECT_EQ(decision->rule, OrientationRule::scalp_distance);
  EXPECT_FALSE(decision->reverse);

  // A faint or split fade does not decide: the texture's v does.
  evidence.scalp_distance_slope = 0;
  evidence.alpha_fade_mean_fall = 0.01;
  EXPECT_EQ(decide_orientation(evidence, thresholds, conventions)->rule, OrientationRule::uv);
  evidence.alpha_fade_mean_fall = 0.1;
  evidence.alpha_fade_vote = 0.3;
  EXPECT_EQ(decide_orientation(evidence, thresholds, conventions)->rule, OrientationRule::uv);
}

TEST(DecideOrientation, AFadeSpreadOverManyFacesCountsWhereTheTexturesVBacksIt) {
  // 0.01 a face, 0.8 from one end of the rails to the other: too faint per face for the
  // fade alone, enough along the whole rail where the texture's v convention backs it
  // (paint over vertex ids).
  OrientationThresholds thresholds;
  OrientationEvidence evidence;
  evidence.alpha_fade_vote = 0.95;
  evidence.alpha_fade_mean_fall = 0.01;
  evidence.alpha_fade_rail_fall = 0.8;
  EXPECT_FALSE(alpha_fade_decides(evidence, thresholds, false));
  EXPECT_TRUE(alpha_fade_decides(evidence, thresholds, true));
  evidence.alpha_fade_rail_fall = 0.1;  // a faint fade along the rail too
  EXPECT_FALSE(alpha_fade_decides(evidence, thresholds, true));
  evidence.alpha_fade_rail_fall = 0.8;
  evidence.alpha_fade_vote = 0.4;  // split
  EXPECT_FALSE(alpha_fade_decides(evidence, thresholds, true));
  // The fade alone still asks the fall per face.
  evidence.alpha_fade_vote = 0.95;
  evidence.uv_growth = 0.9;
  EXPECT_EQ(decide_orientation(evidence, thresholds, MeshConventions{true, 1})->rule,
            OrientationRule::uv);
}

}  // namespace
}  // namespace hair
