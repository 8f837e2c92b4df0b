// Hair does not go round the head: rings of a shell about the axis from the head's centre
// through it, against the lines from its whorl out, on hand-made families whose answers
// geometry gives (a ring winds 360 degrees about its axis, a meridian none).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "hair/extract/circling_rails.h"

namespace {

using hair::EdgeFamily;
using hair::FamilyCircling;
using hair::Points3f;

/// A cap over the unit-ish sphere of `radius` about `axis` (a unit vector from the origin):
/// `rings` closed rings at polar angles 20..80 degrees from the axis and `spokes` meridians
/// from the whorl out, their vertices appended to `vertices`.
struct Cap {
  Points3f vertices;
  EdgeFamily rings, spokes;
};

Cap cap_about(const Eigen::Vector3d& axis, double radius, int ring_count, int spoke_count) {
  const Eigen::Vector3d a = axis.normalized();
  const Eigen::Vector3d e1 =
      (std::abs(a.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY())
          .cross(a)
          .normalized();
  const Eigen::Vector3d e2 = a.cross(e1);
  Cap cap;
  std::vector<Eigen::Vector3d> points;
  // Vertex (ring i, spoke j) at polar angle 20 + 60 i / (rings - 1), azimuth 360 j / spokes.
  for (int i = 0; i < ring_count; ++i)
    for (int j = 0; j < spoke_count; ++j) {
      const double polar = (20 + 60.0 * i / (ring_count - 1)) * std::numbers::pi / 180;
      const double azimuth = 2 * std::numbers::pi * j / spoke_count;
      points.push_back(radius * (std::cos(polar) * a + std::sin(polar) * (std::cos(azimuth) * e1 +
                                                                          std::sin(azimuth) * e2)));
    }
  cap.vertices.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (size_t v = 0; v < points.size(); ++v)
    cap.vertices.row(static_cast<Eigen::Index>(v)) = points[v].cast<float>().transpose();
  const auto id = [&](int i, int j) { return static_cast<int32_t>(i * spoke_count + j); };
  for (int i = 0; i < ring_count; ++i) {
    std::vector<int32_t> ring;
    for (int j = 0; j <= spoke_count; ++j) ring.push_back(id(i, j % spoke_count));
    cap.rings.chains.push_back(ring);
  }
  for (int j = 0; j < spoke_count; ++j) {
    std::vector<int32_t> spoke;
    for (int i = 0; i < ring_count; ++i) spoke.push_back(id(i, j));
    cap.spokes.chains.push_back(spoke);
  }
  return cap;
}

TEST(CirclingRails, RingsWindRoundTheAxisAndSpokesDoNot) {
  const Cap cap = cap_about(Eigen::Vector3d::UnitY(), 0.12, 6, 24);
  const FamilyCircling rings = hair::family_circling(
      cap.vertices, cap.rings, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitY());
  const FamilyCircling spokes = hair::family_circling(
      cap.vertices, cap.spokes, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitY());
  EXPECT_NEAR(rings.circling_share, 1.0, 0.01);
  EXPECT_NEAR(rings.mean_sweep_deg, 360.0, 1e-6);
  EXPECT_NEAR(spokes.circling_share, 0.0, 1e-6);
  EXPECT_NEAR(spokes.mean_sweep_deg, 0.0, 1e-6);
  // The rings are longer (2 pi r sin(polar) against an arc of 60 degrees), yet the spokes
  // are the hair.
  EXPECT_GT(rings.mean_chain_length, 1.5 * spokes.mean_chain_length);
  EXPECT_EQ(hair::family_across_rings({rings, spokes}, {}), 1);
  EXPECT_EQ(hair::family_across_rings({spokes, rings}, {}), 0);
}

TEST(CirclingRails, AWhorlOffTheTopIsFoundFromTheCapsOwnMiddle) {
  // A cap whose whorl lies 35 degrees back from the crown: about the vertical axis its
  // rings neither circle nor sweep far, about the axis through the cap's middle they do.
  const Eigen::Vector3d whorl(0, std::cos(35 * std::numbers::pi / 180),
                              -std::sin(35 * std::numbers::pi / 180));
  const Cap cap = cap_about(whorl, 0.12, 6, 24);
  const Eigen::Vector3d axis =
      hair::region_axis_direction(cap.vertices, cap.rings, Eigen::Vector3d::Zero());
  EXPECT_GT(axis.dot(whorl),
            0.995);  // within 6 degrees (a closed ring counts its first vertex twice)
  const std::array<FamilyCircling, 2> about_whorl = {
      hair::family_circling(cap.vertices, cap.rings, Eigen::Vector3d::Zero(), axis),
      hair::family_circling(cap.vertices, cap.spokes, Eigen::Vector3d::Zero(), axis)};
  EXPECT_EQ(hair::family_across_rings(about_whorl, {}), 1);
  // A piece at the centre itself: straight up.
  EXPECT_TRUE(hair::region_axis_direction(cap.vertices, EdgeFamily{}, Eigen::Vector3d::Zero())
                  .isApprox(Eigen::Vector3d::UnitY()));
}

TEST(CirclingRails, ABraidWoundRoundTheHeadAndHangingCardsKeepTheirLength) {
  // A braid wound round the head: its along chains circle, its across chains are 2 cm,
  // the braid's width, not strands.
  FamilyCircling wound{0.95, 340, 0.7}, across{0.05, 2, 0.02};
  EXPECT_EQ(hair::family_across_rings({wound, across}, {}), -1);
  // Neither family circling (a card hanging down, its width across): no say.
  FamilyCircling down{0.05, 3, 0.3}, width{0.6, 40, 0.05};
  EXPECT_EQ(hair::family_across_rings({down, width}, {}), -1);
  // Both circling: no say.
  EXPECT_EQ(hair::family_across_rings({wound, wound}, {}), -1);
  // A family winding far but mostly across its way round (a spiral down the axis) does
  // not circle.
  FamilyCircling spiral{0.5, 360, 0.8};
  EXPECT_EQ(hair::family_across_rings({spiral, down}, {}), -1);
}

}  // namespace
