// Where a braided cluster's strands gather into a wisp: a three-strand braid beside a
// sphere head with one stray strand in the same cluster, and a cap of strands that lie
// over the head and end all round it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hair/sim/guide_selection.h"
#include "hair/sim/wisp_gathering.h"
#include "unit/icosphere.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;

constexpr double kRadius = 0.1;

StrandSet strands_of(const std::vector<std::vector<Vec3>>& polylines) {
  std::vector<Points3f> blocks;
  for (const auto& polyline : polylines) {
    Points3f block(static_cast<Eigen::Index>(polyline.size()), 3);
    for (size_t i = 0; i < polyline.size(); ++i)
      block.row(static_cast<Eigen::Index>(i)) = polyline[i].cast<float>().transpose();
    blocks.push_back(block);
  }
  StrandSet strands = strand_set_from_polylines(blocks);
  strands.point_attributes["cluster"] =
      std::vector<int32_t>(static_cast<size_t>(strands.point_count()), 0);
  return strands;
}

BodySdf sphere_field() {
  testing::SphereMesh sphere = testing::icosphere(3, kRadius);
  return BodySdf(sphere.vertices, sphere.triangles, Vec3::Constant(-0.5), Vec3::Constant(0.5),
                 0.005, 0.03, "sphere");
}

/// Three strands twisted about the vertical line x = 0.2, z = 0, from y = 0 to -0.2.
std::vector<std::vector<Vec3>> three_strand_braid() {
  std::vector<std::vector<Vec3>> polylines;
  for (int s = 0; s < 3; ++s) {
    std::vector<Vec3> strand;
    for (int i = 0; i <= 40; ++i) {
      double y = -0.005 * i, angle = 2 * std::numbers::pi * (s / 3.0 + y / 0.05);
      strand.emplace_back(0.2 + 0.008 * std::cos(angle), y, 0.008 * std::sin(angle));
    }
    polylines.push_back(strand);
  }
  return polylines;
}

/// The strands of `polylines` as one braided cluster: its wisp gathered (the wisp, its
/// centre strand and the strands left out).
struct GatheredWisp {
  WispPlan wisp;
  std::vector<Vec3> centre;
  std::vector<GuideStrand> loose;
};
GatheredWisp gather_the_wisp(const std::vector<std::vector<Vec3>>& polylines) {
  StrandSet strands = strands_of(polylines);
  GuidePlan plan = plan_guides(strands, {static_cast<int8_t>(HairStyle::braided)}, 10);
  EXPECT_EQ(plan.wisps.size(), 1u);
  GatheredWisp gathered;
  if (plan.wisps.empty()) return gathered;
  gathered.wisp = plan.wisps[0];
  gathered.centre =
      gather_wisp(strands, gathered.wisp, 0.02, 0.015, sphere_field(), 0.001, gathered.loose);
  return gathered;
}

TEST(WispGathering, TheBraidIsAWispAndTheStrayIsLeftOut) {
  std::vector<std::vector<Vec3>> polylines = three_strand_braid();
  // A stray from the same place that ends 0.3 m away.
  std::vector<Vec3> stray;
  for (int i = 0; i <= 40; ++i) stray.emplace_back(0.2 + 0.0075 * i, -0.002 * i, 0.0);
  polylines.push_back(stray);
  auto [wisp, centre, loose] = gather_the_wisp(polylines);
  ASSERT_GE(centre.size(), 5u);
  EXPECT_EQ(wisp.member_strand.size(), 3u);
  ASSERT_EQ(loose.size(), 1u);
  EXPECT_EQ(loose[0].strand, 3);
  EXPECT_EQ(loose[0].style, HairStyle::normal);
  // The centre runs down the braid's axis, root end first.
  for (const Vec3& p : centre) {
    EXPECT_NEAR(p.x(), 0.2, 0.004);
    EXPECT_NEAR(p.z(), 0.0, 0.004);
  }
  EXPECT_GT(centre.front().y(), centre.back().y());
  EXPECT_NEAR(centre.back().y(), -0.2, 0.01);
}

TEST(WispGathering, AStrandThatEndsPartWayDownTheBraidJoinsTheWisp) {
  // The braid of the test above, and a fourth strand that comes in from the side and
  // runs down the braid's axis to y = -0.1, half way: it ends within the bundle, not at
  // its tip, so it joins the wisp where it comes near the centre strand.
  std::vector<std::vector<Vec3>> polylines = three_strand_braid();
  std::vector<Vec3> joining;
  for (int i = 0; i <= 10; ++i) joining.emplace_back(0.3 - 0.01 * i, -0.005 * i, 0.0);
  for (int i = 1; i <= 10; ++i) joining.emplace_back(0.2, -0.05 - 0.005 * i, 0.0);
  polylines.push_back(joining);
  auto [wisp, centre, loose] = gather_the_wisp(polylines);
  ASSERT_GE(centre.size(), 5u);
  EXPECT_TRUE(loose.empty());
  ASSERT_EQ(wisp.member_strand.size(), 4u);
  EXPECT_EQ(wisp.member_strand[3], 3);
  // It enters where it comes within twice the radius of the axis (x <= 0.23), not at its
  // root, and hangs from the point before.
  int64_t first = wisp.member_first_point[3];
  EXPECT_GT(first, 5);
  EXPECT_LE(joining[static_cast<size_t>(first)].x(), 0.2 + 0.03 + 1e-9);
  EXPECT_GT(joining[static_cast<size_t>(first - 1)].x(), 0.2 + 0.03 - 0.011);
}

TEST(WispGathering, StrandsThatGatherOnlyOverTheLastStepAreNoWisp) {
  // Three straight strands from roots 0.1 m apart to one tip 0.2 m below: 0.0089 m apart
  // on average one step (0.02 m) from the tip, 0.018 m two steps up, over the radius
  // (0.015 m). Two samples gather: a centre strand of two points, on which simulate can
  // build no tetrahedron to bind the members to (two_braids of hair-synth, seed 1,
  // crashed simulate so).
  std::vector<std::vector<Vec3>> polylines;
  for (int s = 0; s < 3; ++s) {
    double angle = 2 * std::numbers::pi * s / 3;
    Vec3 root(0.3 + 0.1 * std::cos(angle), 0, 0.1 * std::sin(angle)), tip(0.3, -0.2, 0);
    std::vector<Vec3> strand;
    for (int i = 0; i <= 40; ++i) strand.push_back(root + (tip - root) * (i / 40.0));
    polylines.push_back(strand);
  }
  auto [wisp, centre, loose] = gather_the_wisp(polylines);
  EXPECT_TRUE(centre.empty());
  EXPECT_TRUE(loose.empty());
}

TEST(WispGathering, ACapThatEndsAllRoundTheHeadIsNoWisp) {
  // Strands over the sphere from its crown down to its equator, all round it.
  std::vector<std::vector<Vec3>> polylines;
  for (int s = 0; s < 12; ++s) {
    double phi = 2 * std::numbers::pi * s / 12;
    std::vector<Vec3> strand;
    for (int i = 0; i <= 30; ++i) {
      double theta = 0.1 + (std::numbers::pi / 2 - 0.1) * i / 30;
      strand.push_back((kRadius + 0.003) * Vec3(std::sin(theta) * std::sin(phi), std::cos(theta),
                                                std::sin(theta) * std::cos(phi)));
    }
    polylines.push_back(strand);
  }
  StrandSet strands = strands_of(polylines);
  GuidePlan plan = plan_guides(strands, {static_cast<int8_t>(HairStyle::braided)}, 10);
  ASSERT_EQ(plan.wisps.size(), 1u);
  WispPlan wisp = plan.wisps[0];
  const WispPlan before = wisp;
  std::vector<GuideStrand> loose;
  EXPECT_TRUE(gather_wisp(strands, wisp, 0.02, 0.015, sphere_field(), 0.001, loose).empty());
  EXPECT_TRUE(loose.empty());
  EXPECT_EQ(wisp.member_strand, before.member_strand);  // untouched
}

}  // namespace
}  // namespace hair
