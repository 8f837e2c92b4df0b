// Tails that hold together (BundleCohesion) and the measures of how guides keep their
// groom (guide_motion_measures), on hand-made guides.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hair/sim/bundle_cohesion.h"
#include "hair/sim/guide_motion_measures.h"
#include "hair/sim/simulation_setup.h"
#include "unit/strand_rest_state.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;

/// Five strands from a ring of radius `root_radius_m` on the crown, drawn together to a
/// ring of 1 cm by `band_y_m` below, then hanging 20 cm (a ponytail through its band).
std::vector<std::vector<Vec3>> tail(double root_radius_m, double band_radius_m) {
  std::vector<std::vector<Vec3>> strands;
  for (int s = 0; s < 5; ++s) {
    const double angle = 2 * std::numbers::pi * s / 5;
    const Vec3 across(std::cos(angle), 0, std::sin(angle));
    std::vector<Vec3> points;
    for (int i = 0; i <= 4; ++i)  // from the root to the band
      points.push_back((root_radius_m + (band_radius_m - root_radius_m) * i / 4) * across -
                       Vec3(0, 0.02 * i, 0));
    for (int i = 1; i <= 8; ++i) points.push_back(points[4] - Vec3(0, 0.025 * i, 0));
    strands.push_back(points);
  }
  return strands;
}

/// Seven strands rooted along the middle of the scalp, from the front hairline over the
/// crown to the nape (an arc of 216 degrees, radius 9 cm), each drawn straight to one band
/// behind the nape at (0, -0.1, -0.1) and hanging 10 to 25 cm below it, fanning out by
/// 1 cm every 2.5 cm: the nearer the front a root, the farther along its strand the band
/// (a low tail, hair pulled back). With `band` false, they hang straight down from their
/// roots, fanning out alike.
std::vector<std::vector<Vec3>> low_tail(bool band) {
  std::vector<std::vector<Vec3>> strands;
  const Vec3 band_point(0, -0.1, -0.1);
  for (int s = 0; s < 7; ++s) {
    const double angle = std::numbers::pi * (0.1 + 0.2 * s);  // from the front, over the top, to the nape
    const Vec3 root(0.01 * (s % 2), 0.09 * std::sin(angle), 0.09 * std::cos(angle));
    std::vector<Vec3> points{root};
    const Vec3 to_band = band ? band_point : root - Vec3(0, 0.1, 0);
    const int steps = std::max(1, static_cast<int>(std::ceil((to_band - root).norm() / 0.02)));
    for (int i = 1; i <= steps; ++i) points.push_back(root + (to_band - root) * i / steps);
    const double around = 2 * std::numbers::pi * s / 7;
    const Vec3 fan(std::cos(around), 0, std::sin(around));
    const int hanging = 4 + s;  // the tail's strands 10 to 25 cm long below the band
    for (int i = 1; i <= hanging; ++i) points.push_back(to_band - Vec3(0, 0.025 * i, 0) + 0.01 * i * fan);
    strands.push_back(points);
  }
  return strands;
}

struct Guides {
  std::vector<SimulatedGuide> guides;
  std::vector<RunningStrand> running;
};

Guides make_guides(const std::vector<std::vector<Vec3>>& strands) {
  Guides made;
  for (size_t s = 0; s < strands.size(); ++s) {
    SimulatedGuide guide;
    guide.strand = static_cast<int64_t>(s);
    guide.cluster = 0;
    guide.rest_m = strands[s];
    made.guides.push_back(guide);
    RunningStrand strand;
    strand.model = testing::hair_strand(strands[s]);
    strand.state = testing::rest_state(strand.model);
    made.running.push_back(std::move(strand));
  }
  return made;
}

TEST(BundleCohesion, AGatheredClusterIsABundleALooseOneIsNot) {
  const Guides gathered = make_guides(tail(0.05, 0.01));
  const BundleCohesion cohesion(gathered.guides, gathered.running, 1600);
  EXPECT_TRUE(cohesion.active());
  EXPECT_EQ(cohesion.bundle_count(), 1);
  EXPECT_EQ(cohesion.guide_count(), 5);
  // Hair hanging loose from the same ring, not drawn together.
  const Guides loose = make_guides(tail(0.05, 0.05));
  EXPECT_FALSE(BundleCohesion(loose.guides, loose.running, 1600).active());
  // Off.
  EXPECT_FALSE(BundleCohesion(gathered.guides, gathered.running, 0).active());
}

TEST(BundleCohesion, StrandsThatMeetOneBandAtDifferentLengthsAreABundle) {
  // At equal arc fractions a low tail's strands are never together (the crown's meet the
  // band halfway, the nape's at once), but they all pass through the band.
  const Guides drawn = make_guides(low_tail(true));
  EXPECT_EQ(BundleCohesion(drawn.guides, drawn.running, 1600).bundle_count(), 1);
  // The same roots with the hair hanging straight down: loose, not a bundle.
  const Guides hanging = make_guides(low_tail(false));
  EXPECT_FALSE(BundleCohesion(hanging.guides, hanging.running, 1600).active());
}

TEST(BundleCohesion, DrawsBackOnlyWhatStraysFartherThanAtRest) {
  Guides g = make_guides(tail(0.05, 0.01));
  BundleCohesion cohesion(g.guides, g.running, 1600);
  std::vector<std::vector<Vec3>> acceleration(g.running.size());
  cohesion.accelerations(g.running, 1.0 / 60, acceleration);
  for (const auto& strand : acceleration)
    for (const Vec3& a : strand) EXPECT_LT(a.norm(), 1e-9);  // at rest: nothing
  // Strand 0's tip swung 5 cm out: drawn back towards the others, at 1600/s^2 times
  // (about) the excess.
  AltitudeStrand& model = g.running[0].model;
  const auto tip = static_cast<size_t>(model.hair_particle.back());
  g.running[0].state.position_m[tip] += Vec3(0.05, 0, 0);
  cohesion.accelerations(g.running, 1.0 / 60, acceleration);
  EXPECT_LT(acceleration[0][tip].x(), -0.5 * 1600 * 0.03);
  EXPECT_GT(acceleration[0][tip].x(), -1600 * 0.06);
  // Swung 1 cm in instead: closer to the centre than at rest, left alone.
  g.running[0].state.position_m[tip] -= Vec3(0.06, 0, 0);
  cohesion.accelerations(g.running, 1.0 / 60, acceleration);
  EXPECT_LT(acceleration[0][tip].norm(), 1e-9);
}

TEST(BundleCohesion, ALongStepNeverThrowsAStrayParticlePastWhereItBelongs) {
  Guides g = make_guides(tail(0.05, 0.01));
  BundleCohesion cohesion(g.guides, g.running, 1600);
  EXPECT_DOUBLE_EQ(cohesion.stiffness_for_step(1.0 / 60), 1600);  // the default step: as set
  EXPECT_DOUBLE_EQ(cohesion.stiffness_for_step(0.25), 16);        // 1 / dt^2
  // Strand 0's tip 5 cm out, at rest; one semi-implicit Euler step of 250 ms with the
  // cohesion alone brings it back at most to its rest distance from the centre line, where
  // the set 1600/s^2 would throw it 100 times the excess the other way.
  AltitudeStrand& model = g.running[0].model;
  const auto tip = static_cast<size_t>(model.hair_particle.back());
  const Vec3 rest = g.running[0].state.position_m[tip];
  g.running[0].state.position_m[tip] += Vec3(0.05, 0, 0);
  std::vector<std::vector<Vec3>> acceleration(g.running.size());
  const double dt_s = 0.25;
  cohesion.accelerations(g.running, dt_s, acceleration);
  const Vec3 moved = acceleration[0][tip] * dt_s * dt_s;
  EXPECT_LT(moved.x(), -0.02);            // drawn back by a good part of the excess
  EXPECT_GT(moved.x(), -0.05 - 1e-12);    // but not past where it was at rest
  EXPECT_LT(std::abs(moved.y()) + std::abs(moved.z()), 0.05);
  (void)rest;
}

TEST(BundleCohesion, ALoneGuideHangingInATailFollowsIt) {
  // The tail's five guides (cluster 0), a guide of cluster 1 hanging inside it (the path
  // of guide 0, half way to the centre) and one of cluster 2 hanging 10 cm beside it.
  std::vector<std::vector<Vec3>> strands = tail(0.05, 0.01);
  std::vector<Vec3> inside = strands[0], beside = strands[0];
  for (Vec3& p : inside) p.x() *= 0.5;
  for (Vec3& p : beside) p.x() += 0.1;
  strands.push_back(inside);
  strands.push_back(beside);
  Guides g = make_guides(strands);
  g.guides[5].cluster = 1;
  g.guides[6].cluster = 2;
  BundleCohesion cohesion(g.guides, g.running, 1600, 1);
  EXPECT_EQ(cohesion.bundle_count(), 1);
  EXPECT_EQ(cohesion.guide_count(), 5);
  EXPECT_EQ(cohesion.follower_count(), 1);
  EXPECT_TRUE(cohesion.member(5));
  EXPECT_FALSE(cohesion.member(6));
  // At rest nothing; the follower's tip swung 5 cm out is drawn back, and a follower
  // leaves the centre line as it was (the members' tips pull as before).
  std::vector<std::vector<Vec3>> acceleration(g.running.size());
  cohesion.accelerations(g.running, 1.0 / 60, acceleration);
  for (const auto& strand : acceleration)
    for (const Vec3& a : strand) EXPECT_LT(a.norm(), 1e-9);
  const auto tip = static_cast<size_t>(g.running[5].model.hair_particle.back());
  g.running[5].state.position_m[tip] += Vec3(0.05, 0, 0);
  cohesion.accelerations(g.running, 1.0 / 60, acceleration);
  EXPECT_LT(acceleration[5][tip].x(), -0.5 * 1600 * 0.03);
  for (size_t m = 0; m < 5; ++m)
    for (const Vec3& a : acceleration[m]) EXPECT_LT(a.norm(), 1e-9);
}

TEST(BundleCohesion, StrayingOutwardIsDampedSwingingAsOneIsNot) {
  Guides g = make_guides(tail(0.05, 0.01));
  const double dt_s = 1.0 / 60;
  BundleCohesion undamped(g.guides, g.running, 1600, 0), damped(g.guides, g.running, 1600, 1);
  // Critical damping 2 sqrt(1600) = 80/s, held to 1/dt: 60/s at the default step, 80/s at
  // a quarter of it; none when undamped.
  EXPECT_DOUBLE_EQ(damped.damping_for_step(dt_s), 60);
  EXPECT_DOUBLE_EQ(damped.damping_for_step(dt_s / 4), 80);
  EXPECT_DOUBLE_EQ(undamped.damping_for_step(dt_s), 0);
  // Strand 0's tip 5 cm out along +x and moving on outwards at 1 m/s; the others still.
  const auto tip = static_cast<size_t>(g.running[0].model.hair_particle.back());
  g.running[0].state.position_m[tip] += Vec3(0.05, 0, 0);
  g.running[0].state.velocity_m_s[tip] = Vec3(1, 0, 0);
  std::vector<std::vector<Vec3>> spring(g.running.size()), with_damping(g.running.size());
  undamped.accelerations(g.running, dt_s, spring);
  damped.accelerations(g.running, dt_s, with_damping);
  // The centre line's tip moves at the members' mean, 0.2 m/s: the tip leaves it at about
  // 0.8 m/s, and is held back by 60/s times that more than by the spring alone.
  const double extra = spring[0][tip].x() - with_damping[0][tip].x();
  EXPECT_GT(extra, 0.9 * 60 * 0.8 * 0.9);
  EXPECT_LT(extra, 60 * 0.8 * 1.01);
  // Every hair of the tail moving alike (the tail swinging as one): no relative speed, no
  // damping; the spring alone.
  for (RunningStrand& strand : g.running)
    for (Vec3& v : strand.state.velocity_m_s) v = Vec3(1, 0, 0);
  damped.accelerations(g.running, dt_s, with_damping);
  undamped.accelerations(g.running, dt_s, spring);
  EXPECT_LT((with_damping[0][tip] - spring[0][tip]).norm(), 1e-9);
  // Coming back in fast, the damping may cancel the spring but never pushes outwards.
  g.running[0].state.velocity_m_s[tip] = Vec3(-50, 0, 0);
  damped.accelerations(g.running, dt_s, with_damping);
  EXPECT_LT(with_damping[0][tip].norm(), 1e-9);
  // Within its rest distance and moving outwards: left alone, as the spring leaves it.
  g.running[0].state.position_m[tip] -= Vec3(0.06, 0, 0);
  g.running[0].state.velocity_m_s[tip] = Vec3(-1, 0, 0);
  damped.accelerations(g.running, dt_s, with_damping);
  EXPECT_LT(with_damping[0][tip].norm(), 1e-9);
}

/// Guides `rest` over `frames` frames: the head yawed by 10 degrees a frame and the
/// guides turned with it, but guide 1's tip moved by `tip_move_m` (in the head's frame)
/// from frame 1 on. With `stub`, a third guide of the cluster, 1 cm long, 40 cm away.
SimulatedGuides turning_guides(int frames, double tip_move_m, bool stub = false) {
  SimulatedGuides guides;
  std::vector<std::vector<Vec3>> strands{{Vec3(0, 0, 0), Vec3(0, -0.1, 0), Vec3(0, -0.2, 0)},
                                         {Vec3(0.1, 0, 0), Vec3(0.1, -0.1, 0), Vec3(0.1, -0.2, 0)}};
  if (stub) strands.push_back({Vec3(0.5, 0, 0), Vec3(0.5, -0.005, 0), Vec3(0.5, -0.01, 0)});
  for (const auto& points : strands) {
    Points3f block(3, 3);
    for (int i = 0; i < 3; ++i) block.row(i) = points[static_cast<size_t>(i)].cast<float>().transpose();
    guides.rest.append_strand(block);
  }
  guides.rest.strand_attributes["cluster"] = std::vector<int32_t>(strands.size(), 0);
  guides.frame_count = frames;
  for (int f = 0; f < frames; ++f) {
    RigidTransform head;
    head.rotation = Eigen::AngleAxisd(f * 10 * std::numbers::pi / 180, Vec3::UnitY());
    guides.head.push_back(head);
    for (size_t s = 0; s < strands.size(); ++s)
      for (size_t i = 0; i < 3; ++i) {
        Vec3 p = strands[s][i];
        if (s == 1 && i == 2 && f > 0) p += Vec3(0, 0, tip_move_m);
        const Vec3 world = head.apply(p);
        for (int c = 0; c < 3; ++c) guides.guide_points_m.push_back(static_cast<float>(world[c]));
      }
  }
  return guides;
}

TEST(GuideMotionMeasures, DriftIsMeasuredInTheHeadsFrame) {
  const std::vector<GuideDrift> drift = guide_drift(turning_guides(5, 0.02));
  ASSERT_EQ(drift.size(), 2u);
  EXPECT_NEAR(drift[0].length_m, 0.2, 1e-6);
  EXPECT_LT(drift[0].largest_share, 1e-6);  // turned with the head: no drift
  EXPECT_NEAR(drift[1].final_share, 0.1, 1e-5);  // 2 cm of 20
  EXPECT_FALSE(drift[1].flipped);
  const DriftSummary summary = summarise_drift(drift);
  EXPECT_EQ(summary.guides, 2);
  EXPECT_NEAR(summary.mean, 0.05, 1e-5);
  EXPECT_NEAR(summary.largest, 0.1, 1e-5);
}

TEST(GuideMotionMeasures, ABundlesSpreadIsAgainstItsRest) {
  const BundleSpread spread = bundle_spread(turning_guides(4, 0.1), -1, 1.0);
  EXPECT_EQ(spread.cluster, 0);
  EXPECT_EQ(spread.guides, 2);
  EXPECT_NEAR(spread.rest_spread_m, 0.05, 1e-6);  // two tips 10 cm apart
  ASSERT_EQ(spread.ratio.size(), 4u);
  EXPECT_NEAR(spread.ratio[0], 1.0, 1e-6);
  EXPECT_NEAR(spread.ratio[1], std::hypot(0.1, 0.1) / 0.1, 1e-5);
  // A stub of the cluster, far from the tail: not one of its guides, the same spread.
  const BundleSpread with_stub = bundle_spread(turning_guides(4, 0.1, true), -1, 1.0);
  EXPECT_EQ(with_stub.guides, 2);
  EXPECT_NEAR(with_stub.rest_spread_m, 0.05, 1e-6);
  EXPECT_NEAR(with_stub.ratio[1], spread.ratio[1], 1e-9);
}

}  // namespace
}  // namespace hair
