// grow_strands() on a hand-made head with known answers: a sphere with a scalp cap and
// four cards of parallel rails lying on it (root-type groups), one of them continued by
// a middle group and a tip group hanging below it. Roots on the scalp, nothing inside the
// body, strands under the continued card reaching the tip, the others ending with their
// card, clusters from the nearest root-type strand; points pushed out of the body where
// input strands run through it; determinism over thread counts and seeds; refused
// inputs; a scene without root-type groups.
#include <gtest/gtest.h>
#include <omp.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "hair/core/error.h"
#include "hair/geom/triangle_mesh_distance.h"
#include "hair/grow/card_surfaces.h"
#include "hair/grow/strand_growing.h"
#include "unit/icosphere.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;

constexpr double kRadius = 0.1;  // of the head sphere, metres
const Vec3 kCentre(0, 1.5, 0);
const Vec3 kUp = Vec3::UnitY();
constexpr double kScalpAboveCentre = 0.05;  // scalp: triangle centres higher than this
constexpr double kHeadHeight = 0.24;
constexpr int kCardCount = 4;
constexpr double kCardOffset = 0.004;  // rails lie this far outside the sphere
constexpr double kRailSpacing = 0.006;
constexpr int kRailsPerCard = 5;
constexpr double kOuterRail = kRailSpacing * (kRailsPerCard - 1) / 2;  // from the card's middle
constexpr double kCardFirstDeg = 20, kCardLastDeg = 110;  // polar angles of a rail's ends
constexpr int kRailPoints = 37;                           // 2.5 degrees (about 4.5 mm) apart
// Between the continued card, the middle and the tip: 2.5 steps (step_h H), within
// continue_radius_h H (19 mm) of a strand that stops a few millimetres short of the card's
// end.
constexpr double kGap = 0.012;
constexpr double kMiddleLength = 0.12, kTipLength = 0.08;
constexpr double kInputStep = 0.005;  // spacing of the straight input strands' points
constexpr int kStrandCount = 400;
// Groups: cards 0-3 (card 0 continued), then the middle and the tip.
constexpr int32_t kContinuedCard = 0, kMiddleGroup = 4, kTipGroup = 5;

double radians(double degrees) { return degrees * std::numbers::pi / 180; }

/// A sphere of kRadius about kCentre (tests/unit/icosphere.h), wound counter-clockwise
/// seen from outside.
void icosphere(int subdivisions, Points3f& vertices, Triangles3i& triangles) {
  testing::SphereMesh mesh = testing::icosphere(subdivisions, kRadius, kCentre);
  vertices = std::move(mesh.vertices);
  triangles = std::move(mesh.triangles);
}

Vec3 point_of(const Points3f& points, int64_t row) {
  return points.row(row).cast<double>().transpose();
}

Vec3 corner(const GrowInput& input, Eigen::Index t, int k) {
  return point_of(input.body_vertices, input.body_triangles(t, k));
}

/// Scalp flags on the body triangles whose centre satisfies `flagged`.
template <class Predicate>
std::vector<uint8_t> flags_where(const GrowInput& input, Predicate flagged) {
  std::vector<uint8_t> flags(static_cast<size_t>(input.body_triangles.rows()), 0);
  for (Eigen::Index t = 0; t < input.body_triangles.rows(); ++t) {
    Vec3 centre = (corner(input, t, 0) + corner(input, t, 1) + corner(input, t, 2)) / 3;
    flags[static_cast<size_t>(t)] = flagged(centre) ? 1 : 0;
  }
  return flags;
}

/// The head: the sphere (5120 triangles, edges about 7 mm), its scalp the cap above
/// kScalpAboveCentre, H kHeadHeight; no input strands yet.
GrowInput head_sphere_input(const std::string& source) {
  GrowInput input;
  icosphere(4, input.body_vertices, input.body_triangles);
  input.scalp_triangle =
      flags_where(input, [](const Vec3& c) { return c.y() > kCentre.y() + kScalpAboveCentre; });
  input.head_height_m = kHeadHeight;
  input.source = source;
  return input;
}

/// A straight input strand from `start` along the unit `direction` for `length` metres.
Points3f straight_rail(const Vec3& start, const Vec3& direction, double length) {
  int count = static_cast<int>(std::round(length / kInputStep)) + 1;
  Points3f points(count, 3);
  for (int i = 0; i < count; ++i)
    points.row(i) = (start + (length * i / (count - 1)) * direction).transpose().cast<float>();
  return points;
}

/// A card's frame: `out` horizontal, away from the vertical axis through the centre;
/// `side` horizontal, across the card.
struct CardFrame {
  Vec3 out, side;
};

CardFrame card_frame(int card) {
  double azimuth = radians(90.0 * card);
  Vec3 out(std::cos(azimuth), 0, std::sin(azimuth));
  return {out, kUp.cross(out)};
}

/// Polar angle (from +y) of `p` about the centre, in the plane of `card`.
double polar_in_card(int card, const Vec3& p) {
  Vec3 d = p - kCentre;
  return std::atan2(d.dot(card_frame(card).out), d.y());
}

/// Distance of `p` across `card` from its middle plane.
double lateral_in_card(int card, const Vec3& p) { return (p - kCentre).dot(card_frame(card).side); }

/// Whether `root` lies under `card` proper: below its rails' first points, and across the
/// card no farther than half a rail spacing beyond its outer rails. The scalp that roots
/// take reaches up to scalp_cover_h H (12 mm) beyond the rails, where the card's strands
/// are farther from a root than its own rails are from each other.
bool under_card(int card, const Vec3& root) {
  return polar_in_card(card, root) >= radians(kCardFirstDeg) &&
         std::abs(lateral_in_card(card, root)) <= kOuterRail + kRailSpacing / 2;
}

/// The scene: cards at azimuths 0 (+x), 90, 180 and 270 degrees about the vertical axis,
/// each a sheet of kRailsPerCard parallel rails kRailSpacing apart, every rail a vertical
/// arc kCardOffset outside the sphere from polar angle kCardFirstDeg (over the scalp) down
/// to kCardLastDeg (below the equator), root first. The middle group hangs straight down
/// from kGap below card 0's rail ends, the tip group from kGap below the middle's. Cards
/// 0-2 are in cluster 0, card 3 in cluster 2 (so that the roots' clusters differ), the
/// middle and the tip in cluster 1. The scalp is the cap above kScalpAboveCentre.
struct Scene {
  GrowInput input;
  std::vector<Vec3> continued_rail_ends;  ///< last points of card 0's rails
  std::vector<Vec3> tip_ends;             ///< last points of the tip group's strands
};

Scene make_scene(bool with_root_types = true, double middle_inset = 0, double gap = kGap) {
  Scene scene;
  scene.input = head_sphere_input("sphere");
  GrowInput& input = scene.input;

  std::vector<Points3f> polylines;
  std::vector<int32_t> strand_group;
  for (int card = 0; card < kCardCount; ++card) {
    CardFrame frame = card_frame(card);
    for (int k = 0; k < kRailsPerCard; ++k) {
      // In the plane `lateral` off the card's middle, the circle kCardOffset outside
      // the sphere.
      double lateral = kRailSpacing * k - kOuterRail;
      double rho = std::sqrt(std::pow(kRadius + kCardOffset, 2) - lateral * lateral);
      Points3f rail(kRailPoints, 3);
      for (int i = 0; i < kRailPoints; ++i) {
        double polar =
            radians(kCardFirstDeg + (kCardLastDeg - kCardFirstDeg) * i / (kRailPoints - 1));
        Vec3 p = kCentre + rho * (std::sin(polar) * frame.out + std::cos(polar) * kUp) +
                 lateral * frame.side;
        rail.row(i) = p.transpose().cast<float>();
      }
      if (card == kContinuedCard)
        scene.continued_rail_ends.push_back(point_of(rail, kRailPoints - 1));
      polylines.push_back(rail);
      strand_group.push_back(card);
    }
  }
  // The middle and the tip, `middle_inset` nearer the vertical axis than the card's end.
  const Vec3 inset = -middle_inset * card_frame(kContinuedCard).out;
  for (const Vec3& end : scene.continued_rail_ends) {
    polylines.push_back(straight_rail(end + inset - gap * kUp, -kUp, kMiddleLength));
    strand_group.push_back(kMiddleGroup);
  }
  for (const Vec3& end : scene.continued_rail_ends) {
    Vec3 start = end + inset - (gap + kGap + kMiddleLength) * kUp;
    polylines.push_back(straight_rail(start, -kUp, kTipLength));
    strand_group.push_back(kTipGroup);
    scene.tip_ends.push_back(start - kTipLength * kUp);
  }

  input.input_strands = strand_set_from_polylines(polylines);
  input.input_strands.strand_attributes["group"] = strand_group;
  if (with_root_types)
    input.group_type = {GroupType::root_connected, GroupType::root_free, GroupType::root_free,
                        GroupType::root_free,      GroupType::middle,    GroupType::tip};
  else
    input.group_type.assign(6, GroupType::middle);
  input.group_cluster = {0, 0, 0, 2, 1, 1};
  return scene;
}

GrowParams params_with(int strand_count, int seed = 1) {
  GrowParams params;
  params.strand_count = strand_count;
  params.seed = seed;
  return params;
}

double strand_length(const StrandSet& strands, int64_t s) {
  double length = 0;
  for (int64_t row = strands.offsets[s]; row + 1 < strands.offsets[s + 1]; ++row)
    length += (point_of(strands.points, row + 1) - point_of(strands.points, row)).norm();
  return length;
}

Vec3 root_of(const StrandSet& strands, int64_t s) {
  return point_of(strands.points, strands.offsets[s]);
}
Vec3 last_of(const StrandSet& strands, int64_t s) {
  return point_of(strands.points, strands.offsets[s + 1] - 1);
}

/// Group of the input-strand point nearest `p` (brute force), among the groups whose
/// type passes `eligible`.
template <class Eligible>
int32_t nearest_group(const GrowInput& input, const Vec3& p, Eligible eligible) {
  const StrandSet& strands = input.input_strands;
  const auto& group = std::get<std::vector<int32_t>>(strands.strand_attributes.at("group"));
  double best = std::numeric_limits<double>::infinity();
  int32_t nearest = -1;
  for (int64_t s = 0; s < strands.strand_count(); ++s) {
    int32_t g = group[static_cast<size_t>(s)];
    if (!eligible(input.group_type[static_cast<size_t>(g)])) continue;
    for (int64_t row = strands.offsets[s]; row < strands.offsets[s + 1]; ++row) {
      double distance = (point_of(strands.points, row) - p).norm();
      if (distance < best) {
        best = distance;
        nearest = g;
      }
    }
  }
  return nearest;
}

int32_t nearest_root_type_group(const GrowInput& input, const Vec3& p) {
  return nearest_group(input, p, [](GroupType type) {
    return type == GroupType::root_free || type == GroupType::root_connected;
  });
}

/// The rules of strand `s`'s points.
std::vector<GrowRule> rules_of(const GrowResult& result, int64_t s) {
  return {result.point_rule.begin() + result.strands.offsets[s],
          result.point_rule.begin() + result.strands.offsets[s + 1]};
}

int64_t count_rule(const std::vector<GrowRule>& rules, GrowRule rule) {
  return std::count(rules.begin(), rules.end(), rule);
}

const std::vector<int32_t>& int_attribute(const StrandSet& strands, const std::string& name) {
  return std::get<std::vector<int32_t>>(strands.strand_attributes.at(name));
}

/// Whether two results hold the same strands, rules and attributes, bit for bit.
bool identical(const GrowResult& a, const GrowResult& b) {
  return a.strands.offsets == b.strands.offsets && a.strands.points == b.strands.points &&
         a.point_rule == b.point_rule &&
         int_attribute(a.strands, "cluster") == int_attribute(b.strands, "cluster") &&
         int_attribute(a.strands, "root_triangle") == int_attribute(b.strands, "root_triangle") &&
         std::get<Points3f>(a.strands.strand_attributes.at("root_normal")) ==
             std::get<Points3f>(b.strands.strand_attributes.at("root_normal")) &&
         a.points_pushed_out == b.points_pushed_out;
}

/// The scene grown once with kStrandCount strands, shared by the tests that only look.
class GrowOnSphere : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scene_ = new Scene(make_scene());
    result_ = new GrowResult(grow_strands(scene_->input, params_with(kStrandCount)));
  }
  static void TearDownTestSuite() {
    delete result_;
    delete scene_;
    result_ = nullptr;
    scene_ = nullptr;
  }
  static const GrowInput& input() { return scene_->input; }
  static const StrandSet& grown() { return result_->strands; }

  static Scene* scene_;
  static GrowResult* result_;
};
Scene* GrowOnSphere::scene_ = nullptr;
GrowResult* GrowOnSphere::result_ = nullptr;

TEST_F(GrowOnSphere, GrowsTheRequestedStrandsEachFromOneRoot) {
  ASSERT_EQ(grown().strand_count(), kStrandCount);
  ASSERT_EQ(static_cast<int64_t>(result_->point_rule.size()), grown().point_count());
  EXPECT_NO_THROW(check_strand_set(grown()));  // polylines of 2+ finite points
  const int max_points = GrowParams{}.max_points_per_strand;
  for (int64_t s = 0; s < grown().strand_count(); ++s) {
    std::vector<GrowRule> rules = rules_of(*result_, s);
    EXPECT_EQ(rules.front(), GrowRule::root) << "strand " << s;
    EXPECT_EQ(count_rule(rules, GrowRule::root), 1) << "strand " << s;
    // Every step moves on (no strand stalls until it runs out of points).
    EXPECT_LT(grown().strand_size(s), max_points) << "strand " << s;
    for (int64_t row = grown().offsets[s] + 1; row < grown().offsets[s + 1]; ++row)
      ASSERT_GT((point_of(grown().points, row) - point_of(grown().points, row - 1)).norm(), 1e-4)
          << "strand " << s << ", point " << row - grown().offsets[s];
  }
  EXPECT_FALSE(result_->roots_from_any_type);
  EXPECT_GT(result_->scalp_triangles_used, 0);
  EXPECT_GT(result_->root_spacing_m, 0);
  // The scalp area used lies under the cards: less than the whole cap (2 pi r h).
  EXPECT_GT(result_->scalp_area_m2, 0);
  EXPECT_LT(result_->scalp_area_m2, 2 * std::numbers::pi * kRadius * (kRadius - kScalpAboveCentre));
}

TEST_F(GrowOnSphere, RootsLieOnFlaggedScalpTriangles) {
  const auto& triangle = int_attribute(grown(), "root_triangle");
  const auto& normal = std::get<Points3f>(grown().strand_attributes.at("root_normal"));
  ASSERT_EQ(static_cast<int64_t>(triangle.size()), grown().strand_count());
  ASSERT_EQ(normal.rows(), grown().strand_count());
  for (int64_t s = 0; s < grown().strand_count(); ++s) {
    Vec3 root = root_of(grown(), s);
    int32_t t = triangle[static_cast<size_t>(s)];
    ASSERT_GE(t, 0);
    ASSERT_LT(t, input().body_triangles.rows());
    EXPECT_TRUE(input().scalp_triangle[static_cast<size_t>(t)]) << "strand " << s;
    Vec3 nearest = closest_point_on_triangle(root, corner(input(), t, 0), corner(input(), t, 1),
                                             corner(input(), t, 2));
    EXPECT_LT((nearest - root).norm(), 1e-6) << "strand " << s << " off its root triangle";
    // The icosphere's flat triangles sag less than 0.1 mm below the sphere.
    EXPECT_NEAR((root - kCentre).norm(), kRadius, 5e-4) << "strand " << s;
    Vec3 outward = (root - kCentre).normalized();
    EXPECT_GT(normal.row(s).cast<double>().dot(outward.transpose()), 0.99) << "strand " << s;
  }
}

TEST_F(GrowOnSphere, NoPointEntersTheBody) {
  double deepest_m = 0;
  int64_t inside = 0;
  for (int64_t row = 0; row < grown().point_count(); ++row) {
    double depth = kRadius - (point_of(grown().points, row) - kCentre).norm();
    deepest_m = std::max(deepest_m, depth);
    if (depth > 1e-3) ++inside;
  }
  std::printf("[ grow     ] sphere: %lld points, deepest %.3f mm inside, %lld pushed out\n",
              static_cast<long long>(grown().point_count()), 1e3 * deepest_m,
              static_cast<long long>(result_->points_pushed_out));
  EXPECT_EQ(inside, 0) << "points more than 1 mm inside the sphere";
}

TEST_F(GrowOnSphere, EachStrandTakesTheClusterOfTheNearestRootTypeStrand) {
  const auto& cluster = int_attribute(grown(), "cluster");
  ASSERT_EQ(static_cast<int64_t>(cluster.size()), grown().strand_count());
  std::vector<int64_t> per_cluster(3, 0);
  for (int64_t s = 0; s < grown().strand_count(); ++s) {
    int32_t group = nearest_root_type_group(input(), root_of(grown(), s));
    int32_t expected = input().group_cluster[static_cast<size_t>(group)];
    EXPECT_EQ(cluster[static_cast<size_t>(s)], expected) << "strand " << s;
    ++per_cluster[static_cast<size_t>(expected)];
  }
  // Roots in both clusters of cards; none in cluster 1 (middle and tip only), so no
  // field there.
  EXPECT_GT(per_cluster[0], 0);
  EXPECT_GT(per_cluster[2], 0);
  ASSERT_EQ(result_->clusters.size(), 3u);
  for (size_t c = 0; c < 3; ++c)
    EXPECT_EQ(result_->clusters[c].strand_count, per_cluster[c]) << "cluster " << c;
  EXPECT_GT(result_->clusters[0].field_voxel_count, 0);
  EXPECT_GT(result_->clusters[2].field_voxel_count, 0);
  EXPECT_EQ(result_->clusters[1].field_voxel_count, 0);
}

TEST_F(GrowOnSphere, StrandsUnderTheContinuedCardReachTheTip) {
  // Roots under card 0 proper (under_card()). Those beside it or above its rails' first
  // points are only counted: their field phase can stop short of the card's end, or
  // leave the field beside the card, out of reach of the middle group.
  const auto& cluster = int_attribute(grown(), "cluster");
  double tip_end_y = scene_->tip_ends.front().y();
  auto reaches_tip = [&](int64_t s) {
    return std::abs(last_of(grown(), s).y() - tip_end_y) <= 0.01;
  };
  int64_t checked = 0, elsewhere = 0, elsewhere_reaching = 0;
  for (int64_t s = 0; s < grown().strand_count(); ++s) {
    Vec3 root = root_of(grown(), s);
    if (nearest_root_type_group(input(), root) != kContinuedCard) continue;
    if (!under_card(kContinuedCard, root)) {
      ++elsewhere;
      if (reaches_tip(s)) ++elsewhere_reaching;
      continue;
    }
    ++checked;
    // Down to the tip's end (at most a step past it), beside one of the tip strands.
    EXPECT_TRUE(reaches_tip(s)) << "strand " << s << " ends at y " << last_of(grown(), s).y()
                                << ", the tip at " << tip_end_y;
    double beside = std::numeric_limits<double>::infinity();
    for (const Vec3& end : scene_->tip_ends)
      beside = std::min(beside, Vec3(last_of(grown(), s) - end).cwiseProduct(Vec3(1, 0, 1)).norm());
    EXPECT_LT(beside, 0.01) << "strand " << s;
    std::vector<GrowRule> rules = rules_of(*result_, s);
    EXPECT_GT(count_rule(rules, GrowRule::bridge), 0) << "strand " << s;
    EXPECT_GT(count_rule(rules, GrowRule::input_strand), 0) << "strand " << s;
    EXPECT_EQ(cluster[static_cast<size_t>(s)], 0) << "strand " << s;  // its root's cluster
  }
  std::printf(
      "[ grow     ] sphere: %lld strands under the continued card reach its tip; of %lld "
      "rooted beside or above it, %lld do\n",
      static_cast<long long>(checked), static_cast<long long>(elsewhere),
      static_cast<long long>(elsewhere_reaching));
  EXPECT_GT(checked, 20);
  EXPECT_GT(result_->continuations_other_cluster, 0);  // card (cluster 0) into the middle (1)
}

TEST_F(GrowOnSphere, StrandsUnderOtherCardsEndWithTheirCard) {
  // Roots under the cards proper (under_card()); the others are only counted.
  double lowest_ratio = std::numeric_limits<double>::infinity(), highest_ratio = 0;
  int64_t checked = 0, elsewhere = 0, elsewhere_off = 0;
  for (int64_t s = 0; s < grown().strand_count(); ++s) {
    Vec3 root = root_of(grown(), s);
    int32_t card = nearest_root_type_group(input(), root);
    if (card == kContinuedCard) continue;
    // What remains of the card below the root: the arc from the root's polar angle to
    // the rails' last, kCardOffset out.
    double remaining =
        (kRadius + kCardOffset) * (radians(kCardLastDeg) - polar_in_card(card, root));
    double ratio = strand_length(grown(), s) / remaining;
    if (!under_card(card, root)) {
      ++elsewhere;
      if (std::abs(ratio - 1) > 0.1) ++elsewhere_off;
      continue;
    }
    ++checked;
    lowest_ratio = std::min(lowest_ratio, ratio);
    highest_ratio = std::max(highest_ratio, ratio);
    EXPECT_NEAR(ratio, 1, 0.1) << "strand " << s << " of card " << card;
    // Its end: at the card's end, in its own plane across the card.
    Vec3 last = last_of(grown(), s);
    EXPECT_NEAR(polar_in_card(card, last), radians(kCardLastDeg), radians(8)) << "strand " << s;
    EXPECT_NEAR(lateral_in_card(card, last), lateral_in_card(card, root), 0.005) << "strand " << s;
  }
  std::printf(
      "[ grow     ] sphere: %lld strands under the other cards are %.3f to %.3f times what "
      "remains of their card; of %lld rooted beside or above them, %lld are off by over 10%%\n",
      static_cast<long long>(checked), lowest_ratio, highest_ratio,
      static_cast<long long>(elsewhere), static_cast<long long>(elsewhere_off));
  EXPECT_GT(checked, 60);
}

// cluster-all's continued roots: a root-type group in a cluster that does not start at the
// root carries no roots, and strands reach it across a gap wider than continue_radius_h.
TEST(StrandGrowing, ContinuedRootGroupsCarryNoRootsAndAreReachedAcrossTheirGap) {
  // The middle group typed root (as typeify types a piece with nothing within 0.08 H
  // before it) 0.04 m (0.17 H) below card 0's ends; card 3's cluster (2) does not start
  // at the root either.
  Scene scene = make_scene(true, 0, 0.04);
  scene.input.group_type[kMiddleGroup] = GroupType::root_connected;
  scene.input.cluster_starts_at_root = {1, 0, 0};
  GrowResult result = grow_strands(scene.input, params_with(kStrandCount));
  const auto& cluster = int_attribute(result.strands, "cluster");
  double tip_end_y = scene.tip_ends.front().y();
  int64_t reaching = 0;
  for (int64_t s = 0; s < result.strands.strand_count(); ++s) {
    EXPECT_EQ(cluster[static_cast<size_t>(s)], 0) << "strand " << s;
    if (std::abs(last_of(result.strands, s).y() - tip_end_y) <= 0.01) ++reaching;
  }
  EXPECT_GT(reaching, 20);
  EXPECT_EQ(result.clusters[2].strand_count, 0);
  EXPECT_EQ(result.clusters[2].field_voxel_count, 0);

  // The gap is beyond continue_radius_h (0.08 H = 0.019 m): with the continued roots'
  // reach cut to it, no strand gets there.
  GrowParams near = params_with(kStrandCount);
  near.continued_root_radius_h = near.continue_radius_h;
  GrowResult cut = grow_strands(scene.input, near);
  for (int64_t s = 0; s < cut.strands.strand_count(); ++s)
    EXPECT_GT(last_of(cut.strands, s).y(), tip_end_y + 0.05) << "strand " << s;
}

// Leaving the cluster it is rooted in, a strand enters any strand of a cluster that does
// not start at the root, whatever its type, across the same gap, where that strand hangs
// off the scalp: a tail whose pieces typeify typed middle or tip (ponytail01's), after
// its band. Not where it ends over the scalp (continued_tip_off_scalp_h).
TEST(StrandGrowing, StrandsLeavingTheirClusterReachATailThatHangsOffTheScalp) {
  // The middle group (typed middle) 0.04 m (0.17 H) below card 0's ends, its cluster (1)
  // not starting at the root; its tip and the tip group's hang far below the scalp cap.
  Scene scene = make_scene(true, 0, 0.04);
  ASSERT_EQ(scene.input.group_type[kMiddleGroup], GroupType::middle);
  scene.input.cluster_starts_at_root = {1, 0, 1};
  const double tip_end_y = scene.tip_ends.front().y();
  const auto reaching_tip = [&](const GrowResult& result) {
    int64_t reaching = 0;
    for (int64_t s = 0; s < result.strands.strand_count(); ++s)
      if (std::abs(last_of(result.strands, s).y() - tip_end_y) <= 0.01) ++reaching;
    return reaching;
  };
  const GrowResult result = grow_strands(scene.input, params_with(kStrandCount));
  const int64_t reaching = reaching_tip(result);
  EXPECT_GT(reaching, 20);

  // With the bar above where the middle's strands end (about 0.25 m, 1 H, from the
  // scalp), they count as lying over it, and no strand crosses the gap.
  GrowParams over = params_with(kStrandCount);
  over.continued_tip_off_scalp_h = 2;
  const int64_t reaching_over = reaching_tip(grow_strands(scene.input, over));
  std::printf(
      "[ grow     ] sphere: %lld strands cross the 0.04 m gap into a hanging middle group "
      "(%lld with the bar above it)\n",
      static_cast<long long>(reaching), static_cast<long long>(reaching_over));
  EXPECT_EQ(reaching_over, 0);
}

// A ponytail's nape strands rise to the band and its tail hangs down from there: the
// strand turns by more than a right angle where it enters the tail. Here the middle group
// (the tail, cluster 1, not starting at the root) leaves card 0's ends outwards, level, at
// about 110 degrees to the card's end, and bends down through a quarter circle of 1 cm to
// hang 12 cm. next_entry() lets a strand at the card's end into it (up to
// continued_root_max_angle_deg, 120 degrees); its first step along the middle must not
// then count as turning back. Before, it did, and the strand went on elsewhere (on
// ponytail01 up over the crown: 30 of its strands flew off the cap in the shake).
TEST(StrandGrowing, StrandsEnteringATailAtMoreThanARightAngleHangDownIt) {
  Scene scene = make_scene(true, 0, kGap);
  GrowInput& input = scene.input;
  input.cluster_starts_at_root = {1, 0, 1};
  const Vec3 out = card_frame(kContinuedCard).out;
  const StrandSet& old_strands = input.input_strands;
  const auto& group = std::get<std::vector<int32_t>>(old_strands.strand_attributes.at("group"));
  std::vector<Points3f> polylines;
  std::vector<int32_t> strand_group;
  for (int64_t s = 0; s < old_strands.strand_count(); ++s) {
    if (group[static_cast<size_t>(s)] == kMiddleGroup) continue;
    polylines.push_back(old_strands.strand(s));
    strand_group.push_back(group[static_cast<size_t>(s)]);
  }
  constexpr double kBend = 0.01;
  std::vector<double> hanging_tip_y;
  for (const Vec3& end : scene.continued_rail_ends) {
    const Vec3 start = end + 0.004 * out;
    std::vector<Vec3> points;
    for (int i = 0; i <= 6; ++i) {  // level out, then a quarter circle down
      const double angle = std::numbers::pi / 2 * i / 6;
      points.push_back(start + kBend * (std::sin(angle) * out + (std::cos(angle) - 1) * kUp));
    }
    for (int i = 1; i <= 24; ++i) points.push_back(points.back() - kInputStep * kUp);
    Points3f rail(static_cast<Eigen::Index>(points.size()), 3);
    for (size_t i = 0; i < points.size(); ++i)
      rail.row(static_cast<Eigen::Index>(i)) = points[i].transpose().cast<float>();
    polylines.push_back(rail);
    strand_group.push_back(kMiddleGroup);
    hanging_tip_y.push_back(points.back().y());
  }
  input.input_strands = strand_set_from_polylines(polylines);
  input.input_strands.strand_attributes["group"] = strand_group;

  const GrowResult result = grow_strands(input, params_with(kStrandCount));
  const auto& point_cluster =
      std::get<std::vector<int32_t>>(result.strands.point_attributes.at("cluster"));
  int64_t under = 0, hanging = 0;
  for (int64_t s = 0; s < result.strands.strand_count(); ++s) {
    if (!under_card(kContinuedCard, root_of(result.strands, s))) continue;
    ++under;
    const int64_t last = result.strands.offsets[s + 1] - 1;
    if (point_cluster[static_cast<size_t>(last)] == 1 &&
        last_of(result.strands, s).y() < hanging_tip_y.front() + 0.03)
      ++hanging;
  }
  std::printf(
      "[ grow     ] sphere: %lld of the %lld strands under card 0 turn into a tail leaving at "
      "about 110 degrees and hang down it\n",
      static_cast<long long>(hanging), static_cast<long long>(under));
  ASSERT_GT(under, 20);
  EXPECT_GT(hanging, under / 2);
}

/// Height of `p` above the sphere.
double height_above_sphere(const Vec3& p) { return (p - kCentre).norm() - kRadius; }

// A spike card standing on the crown (a mohawk's): 5 rails 4 mm apart across x, each
// rising straight up (+y) from 2 mm above the sphere's top for 6 cm, one root-free group.
// Its strands grow from its base: roots within standing_cover_h (0.02 H, 4.8 mm) of its
// rails across the card, though the sphere's triangles are 7 mm across, where the old
// rule (whole triangles within scalp_cover_h, 12 mm, of any rail point) spread them over a
// disc round the base and they grew up beside the card.
TEST(StrandGrowing, ASpikeStandingOnTheHeadGrowsFromItsBaseNotADiscAroundIt) {
  GrowInput input = head_sphere_input("sphere");
  std::vector<Points3f> rails;
  for (int k = 0; k < 5; ++k) {
    const Vec3 base = kCentre + (kRadius + 0.002) * kUp + (0.004 * k - 0.008) * Vec3::UnitX();
    rails.push_back(straight_rail(base, kUp, 0.06));
  }
  input.input_strands = strand_set_from_polylines(rails);
  input.input_strands.strand_attributes["group"] = std::vector<int32_t>(5, 0);
  input.group_type = {GroupType::root_free};
  input.group_cluster = {0};

  // Across the card (z) at the roots, and of the grown points off the root: the mean.
  const auto across = [](const GrowResult& result) {
    double roots = 0, points = 0;
    int64_t point_count = 0;
    const StrandSet& strands = result.strands;
    for (int64_t s = 0; s < strands.strand_count(); ++s) {
      roots += std::abs(root_of(strands, s).z());
      for (int64_t row = strands.offsets[s] + 1; row < strands.offsets[s + 1]; ++row, ++point_count)
        points += std::abs(strands.points(row, 2));
    }
    return std::pair{roots / static_cast<double>(strands.strand_count()),
                     points / static_cast<double>(point_count)};
  };
  const GrowResult standing = grow_strands(input, params_with(kStrandCount));
  GrowParams disc = params_with(kStrandCount);
  disc.standing_cover_h = disc.scalp_cover_h;
  const GrowResult around = grow_strands(input, disc);
  const auto [standing_roots_m, standing_points_m] = across(standing);
  const auto [disc_roots_m, disc_points_m] = across(around);
  std::printf(
      "[ grow     ] spike: roots %.1f mm across the card on average, grown points %.1f mm "
      "(standing_cover_h as scalp_cover_h, a disc round its base: %.1f and %.1f mm); %lld and "
      "%lld scalp triangles\n",
      1e3 * standing_roots_m, 1e3 * standing_points_m, 1e3 * disc_roots_m, 1e3 * disc_points_m,
      static_cast<long long>(standing.scalp_triangles_used),
      static_cast<long long>(around.scalp_triangles_used));
  for (int64_t s = 0; s < standing.strands.strand_count(); ++s)
    EXPECT_LE(std::abs(root_of(standing.strands, s).z()), 0.0050);
  EXPECT_LT(standing.scalp_triangles_used, around.scalp_triangles_used);
  EXPECT_LT(standing_roots_m, 0.6 * disc_roots_m);
  EXPECT_LT(standing_points_m, 0.6 * disc_points_m);
}

/// A rail of card 0's frame (+x) `lateral` off its middle plane, `offset` outside the
/// sphere, from polar angle `first_deg` to `last_deg`, root first.
Points3f card_zero_rail(double lateral, double offset, double first_deg, double last_deg) {
  const CardFrame frame = card_frame(0);
  const double rho = std::sqrt(std::pow(kRadius + offset, 2) - lateral * lateral);
  Points3f rail(kRailPoints, 3);
  for (int i = 0; i < kRailPoints; ++i) {
    const double polar = radians(first_deg + (last_deg - first_deg) * i / (kRailPoints - 1));
    const Vec3 p = kCentre + rho * (std::sin(polar) * frame.out + std::cos(polar) * kUp) +
                   lateral * frame.side;
    rail.row(i) = p.transpose().cast<float>();
  }
  return rail;
}

// A cap gathered into a tail, as braid01's: a crown card (group 1, polar 5-60 degrees)
// ends on the cap, 4 mm over the card that runs on from 35 degrees down to the band
// (group 0, to 110 degrees); the tail (group 2, its cluster not starting at the root)
// hangs from 4 cm below the band. With gather_along_field_h (0.5 H) the strands rooted under the
// crown card go on along their cluster's field past its end and into the tail (107 of
// 107); without, most end with the crown card, 4.4 cm from the start of anything to
// continue into (10 of 107 reach the tail, their field phase measured on the lower card).
TEST(StrandGrowing, CapStrandsWhoseCardEndsOnTheCapGoOnAlongTheFieldIntoTheTail) {
  GrowInput input = head_sphere_input("gathered cap");
  std::vector<Points3f> polylines;
  std::vector<int32_t> strand_group;
  std::vector<Vec3> band_ends;
  for (int k = 0; k < kRailsPerCard; ++k) {
    const double lateral = kRailSpacing * k - kOuterRail;
    polylines.push_back(card_zero_rail(lateral, kCardOffset, 35, kCardLastDeg));
    strand_group.push_back(0);
    band_ends.push_back(point_of(polylines.back(), kRailPoints - 1));
    polylines.push_back(card_zero_rail(lateral, kCardOffset + 0.004, 5, 60));
    strand_group.push_back(1);
  }
  std::vector<Vec3> tail_ends;
  for (const Vec3& end : band_ends) {
    polylines.push_back(straight_rail(end - 0.04 * kUp, -kUp, kMiddleLength));
    strand_group.push_back(2);
    tail_ends.push_back(end - (0.04 + kMiddleLength) * kUp);
  }
  input.input_strands = strand_set_from_polylines(polylines);
  input.input_strands.strand_attributes["group"] = strand_group;
  input.group_type = {GroupType::root_connected, GroupType::root_free, GroupType::middle};
  input.group_cluster = {0, 0, 1};
  input.cluster_starts_at_root = {1, 0};

  // Crown roots: under the crown card before the other begins, polar under 30 degrees.
  const auto crown_strands_in_tail = [&](const GrowResult& result, int64_t& crown) {
    crown = 0;
    int64_t in_tail = 0;
    for (int64_t s = 0; s < result.strands.strand_count(); ++s) {
      const Vec3 root = root_of(result.strands, s);
      if (polar_in_card(0, root) >= radians(30) ||
          std::abs(lateral_in_card(0, root)) > kOuterRail || root.x() <= 0)
        continue;
      ++crown;
      const Vec3 tip = last_of(result.strands, s);
      if (tip.y() < tail_ends.front().y() + 0.02) ++in_tail;
    }
    return in_tail;
  };
  GrowParams params = params_with(kStrandCount);
  EXPECT_EQ(params.gather_along_field_h, 0);  // off by default: docs/grow.md, "Into the tail"
  int64_t crown = 0, crown_off = 0;
  const int64_t ended = crown_strands_in_tail(grow_strands(input, params), crown_off);
  params.gather_along_field_h = 0.5;
  const int64_t gathered = crown_strands_in_tail(grow_strands(input, params), crown);
  std::printf(
      "[ grow     ] gathered cap: %lld of %lld crown strands reach the tail (%lld of %lld "
      "without gathering along the field)\n",
      static_cast<long long>(gathered), static_cast<long long>(crown),
      static_cast<long long>(ended), static_cast<long long>(crown_off));
  ASSERT_GT(crown, 10);
  EXPECT_GE(gathered, 0.8 * static_cast<double>(crown));
  EXPECT_LT(ended, 0.2 * static_cast<double>(crown_off));
}

// Layers: card 0 gets an outer layer, its rails copied kOuterHeight (14 mm) above the
// sphere (the inner ones lie 4 mm above it), a group of its own in the same cluster.
constexpr double kOuterHeight = 0.014;
Scene make_layered_scene() {
  Scene scene = make_scene();
  GrowInput& input = scene.input;
  const StrandSet& inner = input.input_strands;
  const auto& group = std::get<std::vector<int32_t>>(inner.strand_attributes.at("group"));
  std::vector<Points3f> polylines;
  std::vector<int32_t> strand_group = group;
  for (int64_t s = 0; s < inner.strand_count(); ++s) polylines.push_back(inner.strand(s));
  const auto outer_group = static_cast<int32_t>(input.group_type.size());
  for (int64_t s = 0; s < inner.strand_count(); ++s) {
    if (group[static_cast<size_t>(s)] != kContinuedCard) continue;
    Points3f rail = inner.strand(s);
    for (Eigen::Index i = 0; i < rail.rows(); ++i) {
      Vec3 p = point_of(rail, i);
      Vec3 out = kCentre + (p - kCentre) * (kRadius + kOuterHeight) / (p - kCentre).norm();
      rail.row(i) = out.transpose().cast<float>();
    }
    polylines.push_back(rail);
    strand_group.push_back(outer_group);
  }
  input.input_strands = strand_set_from_polylines(polylines);
  input.input_strands.strand_attributes["group"] = strand_group;
  input.group_type.push_back(GroupType::root_free);
  input.group_cluster.push_back(input.group_cluster[kContinuedCard]);
  return scene;
}

/// Card 0 (group 0, root-free, cluster 0: five rails 6 mm apart, 4 mm out, polar 10-45
/// degrees) and a middle card (group 1, cluster 1) of five rails `lateral_m` to its side
/// and `offset_m` out, from polar `first_deg` to 75 degrees: what cards stacked on a cap
/// (short01's spikes) leave a strand at the end of its own.
GrowInput card_and_next_card(double lateral_m, double offset_m, double first_deg) {
  GrowInput input = head_sphere_input("sphere");
  std::vector<Points3f> rails;
  std::vector<int32_t> group;
  for (int k = 0; k < 5; ++k) {
    rails.push_back(card_zero_rail(0.006 * k - 0.012, kCardOffset, 10, 45));
    group.push_back(0);
  }
  for (int k = 0; k < 5; ++k) {
    rails.push_back(card_zero_rail(0.006 * k - 0.012 + lateral_m, offset_m, first_deg, 75));
    group.push_back(1);
  }
  input.input_strands = strand_set_from_polylines(rails);
  input.input_strands.strand_attributes["group"] = group;
  input.group_type = {GroupType::root_free, GroupType::middle};
  input.group_cluster = {0, 1};
  return input;
}

/// Of the strands rooted under card 0 proper (polar 10 degrees on, within its width):
/// how many, how many bridge into the next card, how many of those bridges run back
/// (a bridge segment against the segment before the bridge), and how many end past
/// polar 60 degrees (on the next card).
struct NextCardCounts {
  int64_t rooted = 0, bridged = 0, bridged_back = 0, ending_beyond = 0;
};
NextCardCounts next_card_counts(const GrowResult& result) {
  NextCardCounts counts;
  const StrandSet& strands = result.strands;
  for (int64_t s = 0; s < strands.strand_count(); ++s) {
    const Vec3 root = root_of(strands, s);
    if (polar_in_card(0, root) < radians(10) || std::abs(lateral_in_card(0, root)) > 0.012)
      continue;
    ++counts.rooted;
    bool bridged = false, back = false;
    for (int64_t row = strands.offsets[s] + 2; row < strands.offsets[s + 1]; ++row) {
      if (result.point_rule[static_cast<size_t>(row)] != GrowRule::bridge) continue;
      bridged = true;
      int64_t before = row - 1;
      while (before > strands.offsets[s] + 1 &&
             result.point_rule[static_cast<size_t>(before)] == GrowRule::bridge)
        --before;
      const Vec3 along = point_of(strands.points, before) - point_of(strands.points, before - 1);
      if ((point_of(strands.points, row) - point_of(strands.points, row - 1)).dot(along) < 0)
        back = true;
    }
    counts.bridged += bridged ? 1 : 0;
    counts.bridged_back += back ? 1 : 0;
    counts.ending_beyond += polar_in_card(0, last_of(strands, s)) > radians(60) ? 1 : 0;
  }
  return counts;
}

// Across a gap hair goes on ahead (GrowParams::bridge_max_angle_deg). A card lying beside
// the end of a strand's own, its nearest rail 15 mm to the side and level with it, is not bridged
// to (sideways across the hair); a card stacked 6 mm over the end of its own and starting 7 degrees
// (13 mm) behind it is entered ahead, not by a bridge back to its start. With bridge_max_angle_deg
// 0 and no turn limit (max_turn_deg 180), the strands hop sideways into the card beside and run
// back into the stacked one.
TEST(StrandGrowing, BridgesGoOnAheadNotBackOrSidewaysToTheNextCard) {
  GrowParams ahead = params_with(kStrandCount);
  GrowParams to_start = ahead;
  to_start.bridge_max_angle_deg = 0;
  to_start.max_turn_deg = 180;
  GrowParams no_fold = ahead;  // bridges to the start, but no step may fold the strand back
  no_fold.bridge_max_angle_deg = 0;

  const GrowInput beside = card_and_next_card(0.039, kCardOffset, 45);
  const NextCardCounts beside_ahead = next_card_counts(grow_strands(beside, ahead));
  const NextCardCounts beside_start = next_card_counts(grow_strands(beside, to_start));
  const GrowInput stacked = card_and_next_card(0, kCardOffset + 0.006, 38);
  const NextCardCounts stacked_ahead = next_card_counts(grow_strands(stacked, ahead));
  const NextCardCounts stacked_start = next_card_counts(grow_strands(stacked, to_start));
  std::printf(
      "[ grow     ] next card beside: %lld of %lld strands bridge into it (%lld to its start); "
      "stacked behind: %lld of %lld reach it, %lld bridging back (to its start: %lld, %lld)\n",
      static_cast<long long>(beside_ahead.bridged), static_cast<long long>(beside_ahead.rooted),
      static_cast<long long>(beside_start.bridged),
      static_cast<long long>(stacked_ahead.ending_beyond),
      static_cast<long long>(stacked_ahead.rooted),
      static_cast<long long>(stacked_ahead.bridged_back),
      static_cast<long long>(stacked_start.ending_beyond),
      static_cast<long long>(stacked_start.bridged_back));
  ASSERT_GT(beside_ahead.rooted, 30);
  EXPECT_EQ(beside_ahead.bridged, 0);
  EXPECT_EQ(beside_ahead.ending_beyond, 0);
  EXPECT_GT(beside_start.bridged, beside_start.rooted / 10);  // the old way hops sideways
  ASSERT_GT(stacked_ahead.rooted, 30);
  EXPECT_GT(stacked_ahead.ending_beyond, stacked_ahead.rooted * 3 / 4);
  EXPECT_GE(stacked_ahead.ending_beyond, stacked_start.ending_beyond);
  EXPECT_EQ(stacked_ahead.bridged_back, 0);
  EXPECT_GT(stacked_start.bridged_back, stacked_start.ending_beyond / 2);
  // A bridge back to the stacked card's start is a fold: without the bridge's own angle
  // limit, max_turn_deg still keeps every strand from running back.
  EXPECT_EQ(next_card_counts(grow_strands(stacked, no_fold)).bridged_back, 0);
}

/// Faces without a group over the `rows` x `columns` grid of points in
/// input.hair_vertices (row-major; with `wrap`, the last column joins the first), as quads
/// fanned into triangles, each painted with `flow_at(its centre)`.
void add_painted_grid(GrowInput& input, int rows, int columns, bool wrap,
                      const std::function<Vec3(const Vec3&)>& flow_at) {
  std::vector<int64_t> face_offsets{0};
  std::vector<int32_t> face_vertices, face_group;
  for (int i = 0; i + 1 < rows; ++i)
    for (int j = 0; j + 1 < columns || (wrap && j < columns); ++j) {
      const int next = (j + 1) % columns;
      for (int v :
           {i * columns + j, (i + 1) * columns + j, (i + 1) * columns + next, i * columns + next})
        face_vertices.push_back(v);
      face_offsets.push_back(static_cast<int64_t>(face_vertices.size()));
      face_group.push_back(-1);
    }
  fan_triangulation_with_groups(face_offsets, face_vertices, face_group, input.hair_triangles,
                                input.hair_triangle_group);
  input.hair_triangle_flow.resize(input.hair_triangles.rows(), 3);
  for (Eigen::Index t = 0; t < input.hair_triangles.rows(); ++t) {
    Vec3 centre = Vec3::Zero();
    for (int k = 0; k < 3; ++k) centre += point_of(input.hair_vertices, input.hair_triangles(t, k));
    input.hair_triangle_flow.row(t) = flow_at(centre / 3).transpose().cast<float>();
  }
}

/// Three cards down card 0's meridian: a root card (group 0, polar 10-30 degrees, 4 mm
/// out), a card stacked 6 mm over its end (group 1, 25-45 degrees) and one more beyond a
/// 5 degree (9 mm) gap (group 2, 50-62 degrees, its tip over the scalp), both middle and
/// of their own clusters; under the gap a painted patch (4 mm out, polar 40-55 degrees,
/// 3 cm wide, no group) whose strokes run down the meridian (`paint_along`) or round the
/// head across it.
GrowInput cards_over_painted_gap(bool paint_along) {
  GrowInput input = head_sphere_input("painted gap");
  std::vector<Points3f> rails;
  std::vector<int32_t> group;
  const std::array<std::array<double, 3>, 3> cards{
      {{kCardOffset, 10, 30}, {kCardOffset + 0.006, 25, 45}, {kCardOffset + 0.006, 50, 62}}};
  for (int32_t c = 0; c < 3; ++c)
    for (int k = 0; k < 5; ++k) {
      rails.push_back(card_zero_rail(0.006 * k - 0.012, cards[c][0], cards[c][1], cards[c][2]));
      group.push_back(c);
    }
  input.input_strands = strand_set_from_polylines(rails);
  input.input_strands.strand_attributes["group"] = group;
  input.group_type = {GroupType::root_free, GroupType::middle, GroupType::middle};
  input.group_cluster = {0, 1, 2};
  // The patch: a 7 x 4 grid of points, quads fanned into triangles.
  const CardFrame frame = card_frame(0);
  constexpr int kAlong = 7, kAcross = 4;
  input.hair_vertices.resize(kAlong * kAcross, 3);
  for (int i = 0; i < kAlong; ++i)
    for (int j = 0; j < kAcross; ++j)
      input.hair_vertices.row(i * kAcross + j) =
          card_zero_rail(0.01 * j - 0.015, kCardOffset, 40 + 2.5 * i, 40 + 2.5 * i).row(0);
  const Vec3 down_the_gap = frame.out * std::cos(radians(47.5)) - kUp * std::sin(radians(47.5));
  const Vec3 flow = paint_along ? down_the_gap : frame.side;
  add_painted_grid(input, kAlong, kAcross, false, [&](const Vec3&) { return flow; });
  return input;
}

/// How many strands rooted under the root card of cards_over_painted_gap() end on the
/// card beyond the gap (past polar 50 degrees).
int64_t strands_past_the_gap(const GrowResult& result) {
  int64_t past = 0;
  for (int64_t s = 0; s < result.strands.strand_count(); ++s)
    if (polar_in_card(0, root_of(result.strands, s)) >= radians(10) &&
        std::abs(lateral_in_card(0, root_of(result.strands, s))) <= 0.012 &&
        polar_in_card(0, last_of(result.strands, s)) > radians(50))
      ++past;
  return past;
}

// Nor does a bridge cut across the painted hair (GrowParams::bridge_paint_max_angle_deg):
// from the end of the stacked card, the strands bridge the 9 mm gap down the meridian into
// the card beyond where the paint under the gap runs down the meridian too, and end with
// their card where it runs round the head, across the gap; without the check they bridge
// either way. Out of the field, into the stacked card, no such check: the strands reach it
// whatever the paint.
TEST(StrandGrowing, BridgesFromCardToCardDoNotCutAcrossThePaint) {
  // The hair mesh here is the painted patch alone, not the cards: everywhere else is air
  // to the field's air stop, which is left off.
  GrowParams params = params_with(kStrandCount);
  params.field_air_stop_h = 0;
  GrowParams unchecked = params;
  unchecked.bridge_paint_max_angle_deg = 0;
  const GrowInput along = cards_over_painted_gap(true);
  const GrowInput across = cards_over_painted_gap(false);
  const int64_t past_along = strands_past_the_gap(grow_strands(along, params));
  const GrowResult across_result = grow_strands(across, params);
  const int64_t past_across = strands_past_the_gap(across_result);
  const int64_t past_unchecked = strands_past_the_gap(grow_strands(across, unchecked));
  int64_t on_stacked = 0;
  for (int64_t s = 0; s < across_result.strands.strand_count(); ++s)
    if (polar_in_card(0, last_of(across_result.strands, s)) > radians(40)) ++on_stacked;
  std::printf(
      "[ grow     ] painted gap: %lld strands bridge it where the paint runs along it, %lld where "
      "it runs across (%lld without the check); %lld reach the stacked card's end\n",
      static_cast<long long>(past_along), static_cast<long long>(past_across),
      static_cast<long long>(past_unchecked), static_cast<long long>(on_stacked));
  EXPECT_GT(past_along, 30);
  EXPECT_EQ(past_across, 0);
  EXPECT_GE(past_unchecked, past_along);
  EXPECT_GT(on_stacked, 30);
}

/// Height over the sphere of a shell card at polar angle `polar_deg`: 4 mm at its root
/// (10 degrees), rising smoothly to 3.5 cm by 40 degrees and staying so.
double shell_height_m(double polar_deg) {
  const double t = std::clamp((polar_deg - 10) / 30, 0.0, 1.0);
  return 0.004 + 0.031 * t * t * (3 - 2 * t);
}

/// A card down the back of the head (card 2's frame, azimuth 180 degrees), five rails 6 mm
/// apart from polar 10 to 100 degrees, standing off the head as shell_height_m() says: a
/// bob's shell. Root-free, one cluster; the scalp every triangle over kScalpAboveCentre.
GrowInput shell_card_input() {
  GrowInput input = head_sphere_input("sphere");
  const CardFrame frame = card_frame(2);
  std::vector<Points3f> rails;
  for (int k = 0; k < 5; ++k) {
    const double lateral = 0.006 * k - 0.012;
    Points3f rail(kRailPoints, 3);
    for (int i = 0; i < kRailPoints; ++i) {
      const double polar_deg = 10 + 90.0 * i / (kRailPoints - 1);
      const double r = kRadius + shell_height_m(polar_deg);
      const double rho = std::sqrt(r * r - lateral * lateral);
      const Vec3 p =
          kCentre +
          rho * (std::sin(radians(polar_deg)) * frame.out + std::cos(radians(polar_deg)) * kUp) +
          lateral * frame.side;
      rail.row(i) = p.transpose().cast<float>();
    }
    rails.push_back(rail);
  }
  input.input_strands = strand_set_from_polylines(rails);
  input.input_strands.strand_attributes["group"] = std::vector<int32_t>(5, 0);
  input.group_type = {GroupType::root_free};
  input.group_cluster = {0};
  return input;
}

// A shell of hair 3.5 cm off the back of the head (GrowParams::field_shell_seeds): the
// scalp under it carries roots (where the field reaches it) and their strands rise to the
// shell and run down it to its end (within 8 degrees, 1.9 cm: they pass it by up to 7).
// Without the seeds under it, roots lie only where the card comes down to the head (its
// first 1.4 cm), and nothing grows from under the shell.
TEST(StrandGrowing, HairStandingOffTheHeadIsRootedUnderItAndRisesToIt) {
  const GrowInput input = shell_card_input();
  GrowParams with = params_with(kStrandCount);
  GrowParams without = with;
  without.field_shell_seeds = false;
  const GrowResult seeded = grow_strands(input, with);
  const GrowResult bare = grow_strands(input, without);
  const Vec3 card_end =
      point_of(input.input_strands.points, input.input_strands.offsets[3] - 1);  // middle rail
  // Strands rooted under the shell proper: 30 degrees down or more, within the card's width.
  const auto under_shell = [](const Vec3& root) {
    return polar_in_card(2, root) >= radians(30) && std::abs(lateral_in_card(2, root)) <= 0.012;
  };
  int64_t seeded_under = 0, reaching_end = 0, bare_under = 0;
  for (int64_t s = 0; s < seeded.strands.strand_count(); ++s) {
    if (!under_shell(root_of(seeded.strands, s))) continue;
    ++seeded_under;
    const Vec3 last = last_of(seeded.strands, s);
    if (std::abs(polar_in_card(2, last) - radians(100)) < radians(8) &&
        std::abs((last - kCentre).norm() - (card_end - kCentre).norm()) < 0.01)
      ++reaching_end;
  }
  for (int64_t s = 0; s < bare.strands.strand_count(); ++s)
    if (under_shell(root_of(bare.strands, s))) ++bare_under;
  std::printf(
      "[ grow     ] shell 3.5 cm off: %lld scalp triangles carry roots (%lld without the seeds "
      "under it); %lld strands rooted under it (%lld without), %lld of them ending at its end\n",
      static_cast<long long>(seeded.scalp_triangles_used),
      static_cast<long long>(bare.scalp_triangles_used), static_cast<long long>(seeded_under),
      static_cast<long long>(bare_under), static_cast<long long>(reaching_end));
  EXPECT_GT(seeded.scalp_triangles_used, 2 * bare.scalp_triangles_used);
  EXPECT_EQ(bare_under, 0);
  EXPECT_GT(seeded_under, 20);
  EXPECT_GT(reaching_end, seeded_under * 8 / 10);
}

// With layers, the strands rooted under card 0 split between the two heights; without,
// the field from the scalp keeps them all low.
TEST(StrandGrowing, StrandsSpreadOverTheLayersOfACluster) {
  Scene scene = make_layered_scene();
  const GrowInput& input = scene.input;

  // Share of the strands rooted under card 0 whose points over the card's middle (polar
  // 50 to 80 degrees) lie above halfway between the layers, on average.
  auto outer_share = [&](const GrowParams& params) {
    GrowResult result = grow_strands(input, params);
    int64_t under = 0, outer = 0;
    for (int64_t s = 0; s < result.strands.strand_count(); ++s) {
      if (!under_card(kContinuedCard, root_of(result.strands, s))) continue;
      double sum = 0;
      int count = 0;
      for (int64_t row = result.strands.offsets[s]; row < result.strands.offsets[s + 1]; ++row) {
        Vec3 p = point_of(result.strands.points, row);
        double polar = polar_in_card(kContinuedCard, p);
        if (polar < radians(50) || polar > radians(80)) continue;
        sum += height_above_sphere(p);
        ++count;
      }
      if (count == 0) continue;
      ++under;
      if (sum / count > 0.009) ++outer;
    }
    EXPECT_GT(under, 20);
    return static_cast<double>(outer) / static_cast<double>(std::max<int64_t>(under, 1));
  };
  GrowParams layered = params_with(kStrandCount);
  GrowParams flat = layered;
  flat.layer_radius_h = 0;
  double with_layers = outer_share(layered), without = outer_share(flat);
  std::printf(
      "[ grow     ] sphere, two layers over card 0: %.2f of its strands outer with "
      "layers, %.2f without\n",
      with_layers, without);
  EXPECT_GT(with_layers, 0.25);
  EXPECT_LT(with_layers, 0.75);
  EXPECT_LT(without, 0.1);
}

// A strand rooted on the scalp under the outer layer climbs 10-14 mm to it along the
// field, at an even slope over layer_climb_h (0.08 H, 19 mm) from its root: under hair
// lying on the head (short01's cap, 7 mm over the scalp) it rises gently, about 20 degrees,
// and under a shell standing off it (bob01's, 2-4 cm) steeply, as hair with volume at its
// roots does, instead of climbing at most layer_pull of a step per step (about 27 degrees)
// over several centimetres, under the shell all the while (bob01's fidelity 0.0190 H, its
// strands' first centimetres in the hair's volume). No one step rises like a root hair
// standing up, and the climb is over within its length (and the 3 steps between two
// look-ups of the layer's height). (short01: when the climb came all at once, in the
// third step, that step ran along the paint 25% of the time, the next ones 90%.)
TEST(StrandGrowing, StrandsClimbToTheirLayerAtAnEvenSlopeWithinTheClimbLength) {
  Scene scene = make_layered_scene();
  struct Climb {
    std::vector<double> rise_deg;  ///< field segments after the first, off the tangent plane
    std::vector<double> reach_m;   ///< along a strand reaching the outer layer, to 12 mm up
  };
  auto climb_of = [&](const GrowParams& params) {
    const GrowResult result = grow_strands(scene.input, params);
    const StrandSet& grown = result.strands;
    Climb climb;
    for (int64_t s = 0; s < grown.strand_count(); ++s) {
      if (!under_card(kContinuedCard, root_of(grown, s))) continue;
      // A strand of the outer layer: along the field, 10 mm or more above the sphere.
      bool outer = false;
      for (int64_t row = grown.offsets[s] + 1; row < grown.offsets[s + 1]; ++row)
        outer |= result.point_rule[static_cast<size_t>(row)] == GrowRule::field &&
                 height_above_sphere(point_of(grown.points, row)) >= 0.010;
      double along_m = 0;
      bool reached = !outer;
      for (int64_t row = grown.offsets[s] + 1; row < grown.offsets[s + 1]; ++row) {
        const Vec3 a = point_of(grown.points, row - 1), b = point_of(grown.points, row);
        along_m += (b - a).norm();
        if (!reached && height_above_sphere(b) > kOuterHeight - 0.002) {
          reached = true;
          climb.reach_m.push_back(along_m);
        }
        if (row == grown.offsets[s] + 1 ||
            result.point_rule[static_cast<size_t>(row)] != GrowRule::field)
          continue;
        const Vec3 radial = ((a + b) / 2 - kCentre).normalized();
        climb.rise_deg.push_back(std::asin(std::abs((b - a).normalized().dot(radial))) * 180 /
                                 std::numbers::pi);
      }
    }
    std::sort(climb.rise_deg.begin(), climb.rise_deg.end());
    std::sort(climb.reach_m.begin(), climb.reach_m.end());
    return climb;
  };
  const GrowParams params = params_with(kStrandCount);
  GrowParams by_pull = params;
  by_pull.layer_climb_h = 0;
  const Climb even = climb_of(params), pulled = climb_of(by_pull);
  ASSERT_GT(even.rise_deg.size(), 200u);
  ASSERT_GT(even.reach_m.size(), 20u);
  ASSERT_GT(pulled.reach_m.size(), 20u);
  auto p99 = [](const std::vector<double>& sorted) { return sorted[sorted.size() * 99 / 100]; };
  auto median = [](const std::vector<double>& sorted) { return sorted[sorted.size() / 2]; };
  const double climb_m = params.layer_climb_h * kHeadHeight;
  const double step_m = params.step_h * kHeadHeight;
  const double slope_deg = std::atan(kOuterHeight / climb_m) * 180 / std::numbers::pi;
  std::printf(
      "[ grow     ] sphere, two layers over card 0: field segments rise off the scalp by "
      "%.1f degrees at the 99th percentile (%.1f by layer_pull); the outer layer reached "
      "%.1f mm from the root at the median, %.1f at most (%.1f, %.1f by layer_pull)\n",
      p99(even.rise_deg), p99(pulled.rise_deg), 1e3 * median(even.reach_m),
      1e3 * even.reach_m.back(), 1e3 * median(pulled.reach_m), 1e3 * pulled.reach_m.back());
  EXPECT_LT(p99(even.rise_deg), slope_deg + 5);
  EXPECT_LT(p99(pulled.rise_deg), 35.0);
  EXPECT_LT(p99(even.reach_m), climb_m + 3 * step_m);
  EXPECT_LT(median(even.reach_m), median(pulled.reach_m));
}

// A strand that follows a group off its rails (rooted beside a card, it leaves the field
// at the band's edge and goes on along the card's closest rail) drifts back to within
// follow_keep_h of them.
TEST(StrandGrowing, StrandsFollowingAGroupDriftBackToItsRails) {
  Scene scene = make_scene();
  const StrandSet& rails = scene.input.input_strands;
  // Mean distance of the last point of every input_strand run to the nearest rail point.
  auto mean_offset = [&](const GrowParams& params) {
    GrowResult result = grow_strands(scene.input, params);
    double sum = 0;
    int64_t runs = 0;
    for (int64_t s = 0; s < result.strands.strand_count(); ++s)
      for (int64_t row = result.strands.offsets[s]; row < result.strands.offsets[s + 1]; ++row) {
        bool run_end = result.point_rule[static_cast<size_t>(row)] == GrowRule::input_strand &&
                       (row + 1 == result.strands.offsets[s + 1] ||
                        result.point_rule[static_cast<size_t>(row + 1)] != GrowRule::input_strand);
        if (!run_end) continue;
        double nearest = std::numeric_limits<double>::infinity();
        for (int64_t r = 0; r < rails.point_count(); ++r)
          nearest = std::min(
              nearest, (point_of(rails.points, r) - point_of(result.strands.points, row)).norm());
        sum += nearest;
        ++runs;
      }
    EXPECT_GT(runs, 20);
    return sum / static_cast<double>(std::max<int64_t>(runs, 1));
  };
  GrowParams pulled = params_with(kStrandCount);
  GrowParams kept = pulled;
  kept.follow_pull = 0;
  double with_pull = mean_offset(pulled), without = mean_offset(kept);
  std::printf(
      "[ grow     ] sphere: input-strand runs end %.2f mm from a rail with the pull, "
      "%.2f mm without\n",
      1e3 * with_pull, 1e3 * without);
  EXPECT_LT(with_pull, 0.02 * kHeadHeight);
  EXPECT_LT(with_pull, without);
}

/// The scene's cards as faces: quads between neighbouring rails of each card (their
/// group), over the rails' own points; the middle and the tip have no faces.
void add_card_faces(GrowInput& input) {
  const StrandSet& rails = input.input_strands;
  input.hair_vertices = rails.points;
  std::vector<int64_t> face_offsets{0};
  std::vector<int32_t> face_vertices, face_group;
  for (int card = 0; card < kCardCount; ++card)
    for (int k = 0; k + 1 < kRailsPerCard; ++k) {
      const int64_t a = rails.offsets[card * kRailsPerCard + k];
      const int64_t b = rails.offsets[card * kRailsPerCard + k + 1];
      for (int i = 0; i + 1 < kRailPoints; ++i) {
        for (int64_t v : {a + i, a + i + 1, b + i + 1, b + i})
          face_vertices.push_back(static_cast<int32_t>(v));
        face_offsets.push_back(static_cast<int64_t>(face_vertices.size()));
        face_group.push_back(card);
      }
    }
  fan_triangulation_with_groups(face_offsets, face_vertices, face_group, input.hair_triangles,
                                input.hair_triangle_group);
}

TEST(StrandGrowing, StrandsFollowingACardLieOnItsSurfaceSpreadAcrossIt) {
  Scene scene = make_scene();
  add_card_faces(scene.input);
  // The cards lie on the sphere kCardOffset outside the head: a point's distance from
  // that sphere is its distance from the card's surface.
  struct OnCards {
    double mean_off_surface_m = 0, lateral_spread_m = 0;
    int64_t points = 0;
  };
  auto on_cards = [&](const GrowParams& params) {
    GrowResult result = grow_strands(scene.input, params);
    const auto& group = std::get<std::vector<int32_t>>(result.strands.point_attributes.at("group"));
    OnCards found;
    double lateral_sum = 0, lateral_squares = 0;
    for (int64_t row = 0; row < result.strands.point_count(); ++row) {
      const int32_t card = group[static_cast<size_t>(row)];
      if (result.point_rule[static_cast<size_t>(row)] != GrowRule::input_strand || card < 0 ||
          card >= kCardCount)
        continue;
      const Vec3 p = point_of(result.strands.points, row);
      found.mean_off_surface_m += std::abs((p - kCentre).norm() - (kRadius + kCardOffset));
      const double lateral = lateral_in_card(card, p);
      lateral_sum += lateral;
      lateral_squares += lateral * lateral;
      ++found.points;
    }
    const auto n = static_cast<double>(std::max<int64_t>(found.points, 1));
    found.mean_off_surface_m /= n;
    found.lateral_spread_m =
        std::sqrt(std::max(0.0, lateral_squares / n - (lateral_sum / n) * (lateral_sum / n)));
    return found;
  };
  GrowParams held = params_with(kStrandCount);
  GrowParams free = held;
  free.follow_card_keep_h = 0;
  const OnCards with_hold = on_cards(held), without = on_cards(free);
  std::printf(
      "[ grow     ] sphere: along the cards %.2f mm off their surface with the hold, %.2f mm "
      "without; spread across them (standard deviation) %.1f mm and %.1f mm (rails +-%.0f "
      "mm)\n",
      1e3 * with_hold.mean_off_surface_m, 1e3 * without.mean_off_surface_m,
      1e3 * with_hold.lateral_spread_m, 1e3 * without.lateral_spread_m, 1e3 * kOuterRail);
  EXPECT_GT(with_hold.points, 200);
  EXPECT_LT(with_hold.mean_off_surface_m, 0.5 * without.mean_off_surface_m);
  EXPECT_LT(with_hold.mean_off_surface_m, 2 * held.follow_card_keep_h * kHeadHeight);
  // On the surface, not gathered onto the rails or the card's middle: strands spread
  // across the card at least as widely as hair spread evenly over it would (the standard
  // deviation of a uniform spread over +-kOuterRail).
  EXPECT_GT(with_hold.lateral_spread_m, kOuterRail / std::sqrt(3.0));
}

TEST(StrandGrowing, StrandsAlongInputStrandsThroughTheBodyArePushedOut) {
  // The middle group 1.7 cm nearer the axis: its first centimetres run about 6 mm inside
  // the sphere. Strands bridged to it and following it unchecked would go as deep; the
  // body's signed distance keeps every point outside. (At 2 cm its start lies beyond
  // continue_radius_h of the strands' ends, which keep the card's 4 mm off the sphere.)
  Scene scene = make_scene(/*with_root_types=*/true, /*middle_inset=*/0.017);
  double deepest_input_m = 0;
  for (int64_t row = 0; row < scene.input.input_strands.point_count(); ++row)
    deepest_input_m =
        std::max(deepest_input_m,
                 kRadius - (point_of(scene.input.input_strands.points, row) - kCentre).norm());
  ASSERT_GT(deepest_input_m, 0.005);
  GrowResult result = grow_strands(scene.input, params_with(200));
  ASSERT_EQ(result.strands.strand_count(), 200);
  double deepest_m = 0;
  for (int64_t row = 0; row < result.strands.point_count(); ++row)
    deepest_m =
        std::max(deepest_m, kRadius - (point_of(result.strands.points, row) - kCentre).norm());
  std::printf(
      "[ grow     ] sphere, middle group %.1f mm deep: %lld points pushed out, deepest "
      "%.3f mm inside\n",
      1e3 * deepest_input_m, static_cast<long long>(result.points_pushed_out), 1e3 * deepest_m);
  EXPECT_GT(result.continuations_other_cluster, 0);  // strands did go into the middle group
  EXPECT_LT(deepest_m, 1e-3);
}

// A card that dives into the skin (bob01's front cards run into the forehead): card 3's
// rails run down the sphere to its equator and there turn straight in, towards the axis,
// for 3 cm. Every step of a strand there is pushed back out of the body where it started;
// such a strand used to tremble in place, 0.5 to 0.8 mm a step, until it was max_length_h
// long in points. Now each strand of card 3's cluster ends where the card meets the body,
// and every step it made along the field or the card advanced.
TEST(StrandGrowing, StrandsEndWhereTheirCardDivesIntoTheBody) {
  Scene scene = make_scene();
  GrowInput& input = scene.input;
  constexpr int32_t kDivingCard = 3;
  constexpr double kDiveLength = 0.03;
  const auto& group = int_attribute(input.input_strands, "group");
  std::vector<Points3f> polylines;
  std::vector<Vec3> corners;  // where each diving rail turns in
  for (int64_t s = 0; s < input.input_strands.strand_count(); ++s) {
    const int64_t first = input.input_strands.offsets[s];
    const int64_t count = input.input_strands.offsets[s + 1] - first;
    Points3f rail = input.input_strands.points.middleRows(first, count);
    if (group[static_cast<size_t>(s)] == kDivingCard) {
      const int equator = (kRailPoints - 1) * 70 / 90;  // polar 90 of 20..110 degrees
      const Vec3 corner = point_of(rail, equator);
      Points3f dive = straight_rail(corner, -card_frame(kDivingCard).out, kDiveLength);
      Points3f diving(equator + dive.rows(), 3);
      diving.topRows(equator) = rail.topRows(equator);
      diving.bottomRows(dive.rows()) = dive;
      rail = diving;
      corners.push_back(corner);
    }
    polylines.push_back(rail);
  }
  StrandSet strands = strand_set_from_polylines(polylines);
  strands.strand_attributes["group"] = group;
  input.input_strands = std::move(strands);

  GrowResult result = grow_strands(input, params_with(kStrandCount));
  const double step_m = GrowParams{}.step_h * kHeadHeight;
  const auto& cluster = int_attribute(result.strands, "cluster");
  int64_t diving_strands = 0, most_points = 0, short_steps = 0;
  double farthest_from_corner_m = 0;
  for (int64_t s = 0; s < result.strands.strand_count(); ++s) {
    if (cluster[static_cast<size_t>(s)] != input.group_cluster[kDivingCard]) continue;
    ++diving_strands;
    most_points = std::max(most_points, result.strands.offsets[s + 1] - result.strands.offsets[s]);
    for (int64_t row = result.strands.offsets[s] + 1; row < result.strands.offsets[s + 1]; ++row) {
      const GrowRule rule = result.point_rule[static_cast<size_t>(row)];
      if ((rule == GrowRule::field || rule == GrowRule::input_strand) &&
          (point_of(result.strands.points, row) - point_of(result.strands.points, row - 1)).norm() <
              0.25 * step_m)
        ++short_steps;
    }
    double nearest_corner_m = std::numeric_limits<double>::infinity();
    for (const Vec3& corner : corners)
      nearest_corner_m = std::min(nearest_corner_m, (last_of(result.strands, s) - corner).norm());
    farthest_from_corner_m = std::max(farthest_from_corner_m, nearest_corner_m);
  }
  std::printf(
      "[ grow     ] sphere, card diving into the body: %lld strands, at most %lld points, "
      "%lld steps under a quarter step, last points at most %.1f mm from the card's turn; "
      "%lld strands ended at the body\n",
      static_cast<long long>(diving_strands), static_cast<long long>(most_points),
      static_cast<long long>(short_steps), 1e3 * farthest_from_corner_m,
      static_cast<long long>(result.strands_ended_at_body));
  ASSERT_GT(diving_strands, 20);
  EXPECT_EQ(short_steps, 0);
  // From the scalp to the equator is 70 degrees of a 0.104 m circle, 0.127 m: 27 steps.
  EXPECT_LT(most_points, 40);
  // The card is 24 mm wide; its strands end at the body by the turn, within two steps.
  EXPECT_LT(farthest_from_corner_m, kOuterRail + 2 * step_m);
  EXPECT_GE(result.strands_ended_at_body, diving_strands / 2);
}

// A cap's rails that end over the scalp (a traced cap's streamlines at its hairline, 4 mm
// over the head): a root beyond their tips has a tip as its reference and cannot leave it.
// Its one step lies along the hair there, down the head as the rails end, not standing
// straight up out of the scalp.
TEST(StrandGrowing, AStrandThatCannotLeaveItsRootLiesAlongTheHairThere) {
  GrowInput input = head_sphere_input("sphere");
  std::vector<Points3f> rails;
  constexpr double kLastDeg = 40;  // the scalp reaches 60 degrees from the crown
  for (int k = 0; k < 12; ++k) {
    const double azimuth = radians(30.0 * k);
    const Vec3 out(std::cos(azimuth), 0, std::sin(azimuth));
    Points3f rail(15, 3);
    for (int i = 0; i < 15; ++i) {
      const double polar = radians(5 + (kLastDeg - 5) * i / 14.0);
      rail.row(i) =
          (kCentre + (kRadius + kCardOffset) * (std::sin(polar) * out + std::cos(polar) * kUp))
              .transpose()
              .cast<float>();
    }
    rails.push_back(rail);
  }
  input.input_strands = strand_set_from_polylines(rails);
  input.input_strands.strand_attributes["group"] = std::vector<int32_t>(12, 0);
  input.group_type = {GroupType::root_connected};
  input.group_cluster = {0};
  const GrowResult result = grow_strands(input, params_with(kStrandCount));
  int64_t stubs = 0;
  for (int64_t s = 0; s < result.strands.strand_count(); ++s) {
    if (result.strands.strand_size(s) != 2) continue;
    const Vec3 root = root_of(result.strands, s);
    const Vec3 radial = (root - kCentre).normalized();
    const double polar_deg = std::acos(radial.dot(kUp)) * 180 / std::numbers::pi;
    if (polar_deg < kLastDeg) continue;  // beyond the rails' tips
    ++stubs;
    const Vec3 step = (last_of(result.strands, s) - root).normalized();
    // Down the head: along the meridian, away from the crown (within 40 degrees: the rail
    // whose tip is the reference may lie 15 degrees round the head).
    const Vec3 down = (radial * radial.dot(kUp) - kUp).normalized();
    EXPECT_GT(step.dot(down), std::cos(radians(40))) << "strand " << s << " at " << polar_deg;
    EXPECT_LT(std::abs(step.dot(radial)), std::sin(radians(30))) << "strand " << s;
    EXPECT_GE((last_of(result.strands, s) - kCentre).norm(), kRadius - 1e-4) << "strand " << s;
  }
  std::printf("[ grow     ] sphere: %lld strands beyond the rails' tips take one step along them\n",
              static_cast<long long>(stubs));
  EXPECT_GT(stubs, 20);
}

/// Twelve rails down the meridians of the cap (30 degrees apart round the head, polar
/// 5-40 degrees, 4 mm out; one root-connected group) and, over them, a painted cap without
/// groups (4 mm out, polar 2-50 degrees) whose strokes run `paint_turn_deg` round the head
/// from down the meridian.
GrowInput meridians_under_turned_paint(double paint_turn_deg) {
  GrowInput input = head_sphere_input("turned paint");
  std::vector<Points3f> rails;
  auto on_sphere = [](double polar_deg, double azimuth_deg, double offset) {
    const double polar = radians(polar_deg), azimuth = radians(azimuth_deg);
    const Vec3 out(std::cos(azimuth), 0, std::sin(azimuth));
    return Vec3(kCentre + (kRadius + offset) * (std::sin(polar) * out + std::cos(polar) * kUp));
  };
  for (int k = 0; k < 12; ++k) {
    Points3f rail(15, 3);
    for (int i = 0; i < 15; ++i)
      rail.row(i) = on_sphere(5 + 35.0 * i / 14, 30.0 * k, kCardOffset).transpose().cast<float>();
    rails.push_back(rail);
  }
  input.input_strands = strand_set_from_polylines(rails);
  input.input_strands.strand_attributes["group"] = std::vector<int32_t>(12, 0);
  input.group_type = {GroupType::root_connected};
  input.group_cluster = {0};
  constexpr int kRings = 13, kRound = 72;  // polar 2-50 degrees every 4, azimuth every 5
  input.hair_vertices.resize(kRings * kRound, 3);
  for (int i = 0; i < kRings; ++i)
    for (int j = 0; j < kRound; ++j)
      input.hair_vertices.row(i * kRound + j) =
          on_sphere(2 + 4.0 * i, 5.0 * j, kCardOffset).transpose().cast<float>();
  add_painted_grid(input, kRings, kRound, true, [&](const Vec3& centre) {
    const Vec3 radial = (centre - kCentre).normalized();
    const Vec3 down = (radial * radial.dot(kUp) - kUp).normalized();
    return Vec3(std::cos(radians(paint_turn_deg)) * down +
                std::sin(radians(paint_turn_deg)) * radial.cross(down));
  });
  return input;
}

/// Per strand of at least `step + 1` segments rooted 10-35 degrees from the crown: the
/// angle (degrees) between its `step`-th segment (1: the first) and `reference` there,
/// both taken along the sphere's surface.
std::vector<double> heading_angles_deg(const GrowResult& result, int step,
                                       const std::function<Vec3(const Vec3&)>& reference) {
  std::vector<double> angles;
  const StrandSet& strands = result.strands;
  for (int64_t s = 0; s < strands.strand_count(); ++s) {
    const Vec3 root = root_of(strands, s);
    const double polar_deg =
        std::acos((root - kCentre).normalized().dot(kUp)) * 180 / std::numbers::pi;
    if (polar_deg < 10 || polar_deg > 35 || strands.strand_size(s) < step + 2) continue;
    const Vec3 a = point_of(strands.points, strands.offsets[s] + step - 1);
    const Vec3 b = point_of(strands.points, strands.offsets[s] + step);
    const Vec3 radial = (0.5 * (a + b) - kCentre).normalized();
    Vec3 over = (b - a) - (b - a).dot(radial) * radial;
    Vec3 ref = reference(0.5 * (a + b));
    ref -= ref.dot(radial) * radial;
    angles.push_back(std::acos(std::clamp(over.normalized().dot(ref.normalized()), -1.0, 1.0)) *
                     180 / std::numbers::pi);
  }
  std::sort(angles.begin(), angles.end());
  return angles;
}

// Near its root a strand heads the way the paint over it runs (GrowParams::
// root_heading_paint_h): the field, from rails down the meridians, says down; the paint over
// them runs 40 degrees round the head. The first step heads along the paint with the check,
// down the meridian without; by the sixth step (past 0.06 H) the strands follow the field
// again; paint 80 degrees round (beyond 60) is hair crossing over, and the strands head down.
TEST(StrandGrowing, NearTheRootAStrandHeadsTheWayThePaintOverItRuns) {
  auto down = [](const Vec3& p) {
    const Vec3 radial = (p - kCentre).normalized();
    return Vec3((radial * radial.dot(kUp) - kUp).normalized());
  };
  auto turned = [&](double deg) {
    return [&, deg](const Vec3& p) {
      const Vec3 d = down(p), round = (p - kCentre).normalized().cross(d);
      return Vec3(std::cos(radians(deg)) * d + std::sin(radians(deg)) * round);
    };
  };
  const GrowParams params = params_with(kStrandCount);
  GrowParams field_alone = params;
  field_alone.root_heading_paint_h = 0;
  const GrowInput turned_40 = meridians_under_turned_paint(40);
  const GrowResult with_paint = grow_strands(turned_40, params);
  const GrowResult without = grow_strands(turned_40, field_alone);
  const GrowResult turned_80 = grow_strands(meridians_under_turned_paint(80), params);
  const auto median = [](const std::vector<double>& v) {
    return v.empty() ? 1e9 : v[v.size() / 2];
  };
  const std::vector<double> first_to_paint = heading_angles_deg(with_paint, 1, turned(40));
  const std::vector<double> first_without = heading_angles_deg(without, 1, turned(40));
  const std::vector<double> sixth_to_down = heading_angles_deg(with_paint, 6, down);
  const std::vector<double> first_80_to_down = heading_angles_deg(turned_80, 1, down);
  std::printf(
      "[ grow     ] paint 40 degrees round: first step %.1f degrees off it at the median (%.1f "
      "without the paint), sixth %.1f off down; paint 80 degrees round: first step %.1f off "
      "down (%zu, %zu, %zu, %zu strands)\n",
      median(first_to_paint), median(first_without), median(sixth_to_down),
      median(first_80_to_down), first_to_paint.size(), first_without.size(), sixth_to_down.size(),
      first_80_to_down.size());
  // Beyond the rails' tips (40 degrees), under the paint (to 48), a strand cannot leave its
  // root: its one step lies along the paint too (stub_direction(), then the paint's way).
  std::vector<double> stub_to_paint;
  for (int64_t s = 0; s < with_paint.strands.strand_count(); ++s) {
    const Vec3 root = root_of(with_paint.strands, s);
    const double polar_deg =
        std::acos((root - kCentre).normalized().dot(kUp)) * 180 / std::numbers::pi;
    if (with_paint.strands.strand_size(s) != 2 || polar_deg < 41 || polar_deg > 48) continue;
    const Vec3 radial = (root - kCentre).normalized();
    Vec3 step = last_of(with_paint.strands, s) - root;
    step -= step.dot(radial) * radial;
    stub_to_paint.push_back(
        std::acos(std::clamp(std::abs(step.normalized().dot(turned(40)(root))), -1.0, 1.0)) * 180 /
        std::numbers::pi);
  }
  std::sort(stub_to_paint.begin(), stub_to_paint.end());
  std::printf("[ grow     ] %zu strands that cannot leave their root: %.1f degrees off the paint\n",
              stub_to_paint.size(), median(stub_to_paint));
  ASSERT_GT(stub_to_paint.size(), 10u);
  EXPECT_LT(median(stub_to_paint), 5);
  ASSERT_GT(first_to_paint.size(), 50u);
  ASSERT_GT(sixth_to_down.size(), 50u);
  EXPECT_LT(median(first_to_paint), 5);
  EXPECT_GT(median(first_without), 30);
  EXPECT_LT(median(sixth_to_down), 15);
  EXPECT_LT(median(first_80_to_down), 15);
}

TEST(StrandGrowing, SameResultForOneAndTwoThreads) {
  Scene scene = make_scene();
  const int threads_before = omp_get_max_threads();
  omp_set_num_threads(1);
  GrowResult one = grow_strands(scene.input, params_with(kStrandCount));
  omp_set_num_threads(2);
  GrowResult two = grow_strands(scene.input, params_with(kStrandCount));
  omp_set_num_threads(threads_before);
  EXPECT_TRUE(identical(one, two));
}

TEST(StrandGrowing, AnotherSeedGivesOtherRoots) {
  Scene scene = make_scene();
  GrowResult first = grow_strands(scene.input, params_with(200, 1));
  GrowResult other = grow_strands(scene.input, params_with(200, 2));
  ASSERT_EQ(other.strands.strand_count(), 200);
  // Roots of the other seed that coincide with one of the first seed's.
  int64_t shared = 0;
  for (int64_t s = 0; s < 200; ++s)
    for (int64_t r = 0; r < 200; ++r)
      if ((root_of(other.strands, s) - root_of(first.strands, r)).norm() < 1e-6) ++shared;
  EXPECT_LT(shared, 10);
}

/// The kind of hair::Error grow_strands() throws for `input` and its message, or -1.
struct Refusal {
  int kind = -1;
  std::string message;
};
Refusal refusal_of(const GrowInput& input) {
  try {
    grow_strands(input, params_with(50));
  } catch (const Error& error) {
    return {static_cast<int>(error.kind()), error.what()};
  }
  return {};
}

TEST(StrandGrowing, RefusesInputItCannotGrowFrom) {
  const int bad_input = static_cast<int>(ErrorKind::bad_input);
  const Scene scene = make_scene();
  EXPECT_EQ(refusal_of(scene.input).kind, -1);  // the scene itself grows

  GrowInput no_strands = scene.input;
  no_strands.input_strands = StrandSet{};
  no_strands.input_strands.strand_attributes["group"] = std::vector<int32_t>{};
  Refusal refused = refusal_of(no_strands);
  EXPECT_EQ(refused.kind, bad_input);
  EXPECT_NE(refused.message.find("no input strands"), std::string::npos) << refused.message;
  for (double height : {0.0, -0.24, std::nan("")}) {
    GrowInput input = scene.input;
    input.head_height_m = height;
    refused = refusal_of(input);
    EXPECT_EQ(refused.kind, bad_input) << height;
    EXPECT_NE(refused.message.find("head height"), std::string::npos) << refused.message;
  }
  for (size_t size :
       {size_t{0}, scene.input.scalp_triangle.size() - 1, scene.input.scalp_triangle.size() + 1}) {
    GrowInput input = scene.input;
    input.scalp_triangle.resize(size, 1);
    refused = refusal_of(input);
    EXPECT_EQ(refused.kind, bad_input) << size;
    EXPECT_NE(refused.message.find("scalp flags"), std::string::npos) << refused.message;
  }
  // A scalp that no root-type strand covers: the lower cap (the middle and tip groups
  // hang outside it, and they do not carry roots anyway), or no scalp at all.
  GrowInput lower_cap = scene.input;
  lower_cap.scalp_triangle =
      flags_where(lower_cap, [](const Vec3& c) { return c.y() < kCentre.y() - 0.07; });
  GrowInput no_scalp = scene.input;
  std::fill(no_scalp.scalp_triangle.begin(), no_scalp.scalp_triangle.end(), 0);
  for (const GrowInput& input : {lower_cap, no_scalp}) {
    refused = refusal_of(input);
    EXPECT_EQ(refused.kind, bad_input);
    EXPECT_NE(refused.message.find("no scalp triangle"), std::string::npos) << refused.message;
    EXPECT_NE(refused.message.find("sphere"), std::string::npos) << refused.message;
  }
}

TEST(StrandGrowing, WithoutRootTypeGroupsRootsTakeAnyStrand) {
  Scene scene = make_scene(/*with_root_types=*/false);
  GrowResult result = grow_strands(scene.input, params_with(200));
  EXPECT_TRUE(result.roots_from_any_type);
  ASSERT_EQ(result.strands.strand_count(), 200);
  const auto& cluster = int_attribute(result.strands, "cluster");
  double shortest_m = std::numeric_limits<double>::infinity();
  for (int64_t s = 0; s < 200; ++s) {
    // The cluster of the nearest strand of any type; no field anywhere (no root-type
    // strands), so the strand follows input strands from its root.
    int32_t group =
        nearest_group(scene.input, root_of(result.strands, s), [](GroupType) { return true; });
    EXPECT_EQ(cluster[static_cast<size_t>(s)],
              scene.input.group_cluster[static_cast<size_t>(group)])
        << "strand " << s;
    std::vector<GrowRule> rules = rules_of(result, s);
    EXPECT_EQ(count_rule(rules, GrowRule::field), 0) << "strand " << s;
    EXPECT_GT(count_rule(rules, GrowRule::input_strand), 0) << "strand " << s;
    shortest_m = std::min(shortest_m, strand_length(result.strands, s));
  }
  for (const GrownCluster& grown_cluster : result.clusters)
    EXPECT_EQ(grown_cluster.field_voxel_count, 0);
  std::printf("[ grow     ] sphere, no root-type group: shortest strand %.3f m\n", shortest_m);
  // Every strand runs down its card from the scalp's edge at least (polar 60 to 110
  // degrees, about 9 cm).
  EXPECT_GT(shortest_m, 0.08);
}

// Hair typed middle but for one card of four (tiny curl cards typed middle, a handful
// root): the root-type strands cover about a quarter of the scalp under the hair. Above
// min_typed_root_scalp_share the types place the roots, under it roots take any strand.
TEST(StrandGrowing, RootsTakeAnyStrandWhereRootTypeStrandsCoverLittleOfTheScalp) {
  Scene scene = make_scene();
  GrowResult typed = grow_strands(scene.input, params_with(200));
  EXPECT_FALSE(typed.roots_from_any_type);
  EXPECT_NEAR(typed.typed_root_scalp_share, 1.0, 1e-9);

  scene.input.group_type = {GroupType::middle,    GroupType::middle, GroupType::middle,
                            GroupType::root_free, GroupType::middle, GroupType::tip};
  GrowParams params = params_with(200);
  params.min_typed_root_scalp_share = 0.1;
  GrowResult one_card = grow_strands(scene.input, params);
  EXPECT_FALSE(one_card.roots_from_any_type);
  EXPECT_GT(one_card.typed_root_scalp_share, 0.15);
  EXPECT_LT(one_card.typed_root_scalp_share, 0.4);
  // Every root under card 3 (its cluster, 2).
  const auto& cluster = int_attribute(one_card.strands, "cluster");
  for (int32_t c : cluster) EXPECT_EQ(c, 2);

  params.min_typed_root_scalp_share = 0.5;
  GrowResult any = grow_strands(scene.input, params);
  EXPECT_TRUE(any.roots_from_any_type);
  EXPECT_NEAR(any.typed_root_scalp_share, one_card.typed_root_scalp_share, 1e-12);
  // Roots under every card: clusters 0 and 2 both carry roots.
  const auto& any_cluster = int_attribute(any.strands, "cluster");
  EXPECT_GT(std::count(any_cluster.begin(), any_cluster.end(), 0), 50);
  EXPECT_GT(std::count(any_cluster.begin(), any_cluster.end(), 2), 20);
  EXPECT_GT(any.scalp_triangles_used, 2 * one_card.scalp_triangles_used);
}

}  // namespace
}  // namespace hair
