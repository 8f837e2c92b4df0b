// The altitude mass-spring strand and its time integration on hand-made strands with
// known answers: a hanging strand, a horizontal one released, a wavy one, a curl.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "hair/sim/altitude_strand.h"
#include "hair/sim/strand_dynamics.h"
#include "unit/strand_rest_state.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;

const Vec3 kGravity(0, -9.81, 0);

std::vector<Vec3> straight_strand(const Vec3& direction, int segments, double length_m) {
  std::vector<Vec3> points;
  for (int i = 0; i <= segments; ++i)
    points.push_back(direction.normalized() * length_m * i / segments);
  return points;
}

/// A wave in the x-y plane, hanging down -y with amplitude `amplitude_m` along x.
std::vector<Vec3> wavy_strand(int segments, double length_m, double amplitude_m, double waves) {
  std::vector<Vec3> points;
  for (int i = 0; i <= segments; ++i) {
    double s = static_cast<double>(i) / segments;
    points.emplace_back(amplitude_m * std::sin(2 * std::numbers::pi * waves * s), -length_m * s, 0);
  }
  return points;
}

using testing::hair_strand;
using testing::rest_state;

double hair_length(const AltitudeStrand& strand, const std::vector<Vec3>& position_m) {
  double length = 0;
  for (int32_t i = 0; i + 1 < strand.hair_count(); ++i)
    length += (position_m[static_cast<size_t>(strand.hair_particle[static_cast<size_t>(i) + 1])] -
               position_m[static_cast<size_t>(strand.hair_particle[static_cast<size_t>(i)])])
                  .norm();
  return length;
}

double kinetic_energy(const AltitudeStrand& strand, const StrandState& state) {
  double energy = 0;
  for (size_t k = 0; k < state.velocity_m_s.size(); ++k)
    energy += 0.5 * strand.mass_kg[k] * state.velocity_m_s[k].squaredNorm();
  return energy;
}

void run(const AltitudeStrand& strand, const StrandMaterial& material, StrandState& state,
         double seconds, double dt_s) {
  StrandStepper stepper;
  int steps = static_cast<int>(std::lround(seconds / dt_s));
  for (int i = 0; i < steps; ++i) stepper.step(strand, material, {}, kGravity, {}, dt_s, state);
}

TEST(AltitudeStrand, StraightStrandGetsGhostsAndCurlNeedsFew) {
  AltitudeStrand straight = build_altitude_strand(straight_strand(Vec3(0, -1, 0), 12, 0.3), 1e-3);
  EXPECT_EQ(straight.hair_count(), 13);
  // Every segment of a straight strand needs a ghost: no tetrahedron of hair alone has
  // volume; and one goes before the root, to clamp it.
  EXPECT_EQ(straight.ghost_count(), 13);
  EXPECT_EQ(straight.kinematic_count, 3);
  EXPECT_EQ(straight.hair_particle[0], 1);
  for (const ChainTetrahedron& tetrahedron : straight.tetrahedra) {
    EXPECT_GT(tetrahedron_quality(straight.rest_m[static_cast<size_t>(tetrahedron.particle[0])],
                                  straight.rest_m[static_cast<size_t>(tetrahedron.particle[1])],
                                  straight.rest_m[static_cast<size_t>(tetrahedron.particle[2])],
                                  straight.rest_m[static_cast<size_t>(tetrahedron.particle[3])]),
              0.15);
  }
  // A helix (a curl) makes its own tetrahedra: only the root's ghost.
  std::vector<Vec3> helix;
  for (int i = 0; i <= 24; ++i) {
    double angle = i * 2 * std::numbers::pi / 6;
    helix.emplace_back(0.02 * std::cos(angle), -0.01 * i, 0.02 * std::sin(angle));
  }
  AltitudeStrand curl = build_altitude_strand(helix, 1e-3);
  EXPECT_LT(curl.ghost_count(), curl.hair_count() / 2);
  // Masses: the strand weighs its length times its mass per length, ghosts included;
  // each ghost takes a third of its segment's.
  double mass = 0;
  for (double m : straight.mass_kg) mass += m;
  double held = straight.mass_kg[0];  // the leading ghost is held: its mass does not count
  EXPECT_NEAR(mass - held, 0.3e-3, 1e-12);
  EXPECT_NEAR(straight.mass_kg[4], 0.025e-3 / 3, 1e-15);  // the second segment's ghost
}

TEST(AltitudeStrand, AltitudesAreLinearFormsOfTheCorners) {
  std::array<Vec3, 4> corners{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0.2, 0.3, 0.5)};
  // Point 3 above the face (0, 1, 2) in the z = 0 plane: altitude 0.5.
  Altitude point_face = tetrahedron_altitude(corners, 3);
  EXPECT_NEAR(std::abs(point_face.length_m), 0.5, 1e-12);
  EXPECT_NEAR(point_face.robustness_m2, 1.0, 1e-12);
  double sum = 0;
  for (double w : point_face.weight) sum += w;
  EXPECT_NEAR(sum, 0, 1e-12);
  // Edge pair (01, 23): x axis and the segment from (0,1,0) to (0.2,0.3,0.5).
  Altitude edge_edge = tetrahedron_altitude(corners, 4);
  Vec3 normal = Vec3(1, 0, 0).cross(Vec3(0.2, -0.7, 0.5)).normalized();
  EXPECT_NEAR(std::abs(edge_edge.length_m), std::abs(normal.dot(Vec3(0, -1, 0))), 1e-12);
}

TEST(AltitudeStrand, MostRobustAltitudeIsTheLargestOfTheSeven) {
  // Against the definition: the first of the seven altitudes of largest robustness, on
  // random tetrahedra, flat and needle-like ones among them, and a point (none).
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  for (int trial = 0; trial < 2000; ++trial) {
    std::array<Vec3, 4> corners;
    for (Vec3& corner : corners)
      corner = Vec3(coordinate(random), coordinate(random), coordinate(random));
    if (trial % 4 == 1) corners[3] = 0.3 * corners[0] + 0.7 * corners[1];  // a flat one
    if (trial % 4 == 2) corners[2] = corners[1] + 1e-6 * (corners[3] - corners[1]);
    int expected = -1;
    double largest = 0;
    for (int which = 0; which < 7; ++which) {
      double robustness = tetrahedron_altitude(corners, which).robustness_m2;
      if (robustness > largest * (1 + 1e-12)) {
        largest = robustness;
        expected = which;
      }
    }
    const int chosen = most_robust_altitude(corners);
    ASSERT_GE(chosen, 0) << "trial " << trial;
    EXPECT_NEAR(tetrahedron_altitude(corners, chosen).robustness_m2, largest, 1e-12 * largest)
        << "trial " << trial << ": chose " << chosen << ", expected " << expected;
  }
  const std::array<Vec3, 4> point{Vec3(1, 2, 3), Vec3(1, 2, 3), Vec3(1, 2, 3), Vec3(1, 2, 3)};
  EXPECT_EQ(most_robust_altitude(point), -1);
}

TEST(AltitudeStrand, TwoNearlyEqualAltitudesShareTheSpringSmoothly) {
  // Nothing for the second until it comes within the blend factor, half each at a tie,
  // continuous and rising in between.
  EXPECT_EQ(second_altitude_share(0.5), 0.0);
  EXPECT_EQ(second_altitude_share(1 / kAltitudeBlendFactor), 0.0);
  EXPECT_DOUBLE_EQ(second_altitude_share(1.0), 0.5);
  double previous = 0;
  for (int i = 1; i <= 100; ++i) {
    const double ratio = 1 / kAltitudeBlendFactor + (1 - 1 / kAltitudeBlendFactor) * i / 100.0;
    const double share = second_altitude_share(ratio);
    EXPECT_GE(share, previous);
    EXPECT_LT(share - previous, 0.006);  // no jump
    previous = share;
  }
  // A regular tetrahedron: its three pairs of opposite edges tie, the most robust.
  const std::array<Vec3, 4> corners{Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1),
                                    Vec3(-1, -1, 1)};
  const RobustAltitudes robust = robust_altitudes(corners);
  EXPECT_GE(robust.best, 4);
  EXPECT_GE(robust.second, 4);
  EXPECT_NEAR(robust.second_size, robust.best_size, 1e-12);
}

TEST(StrandDynamics, HangingStrandSettlesWithItsLength) {
  // A strand hanging straight down from its root: gravity pulls along it only.
  AltitudeStrand strand = hair_strand(straight_strand(Vec3(0, -1, 0), 15, 0.4));
  StrandMaterial material;
  StrandState state = rest_state(strand);
  run(strand, material, state, 3.0, 1.0 / 120);
  double length = hair_length(strand, state.position_m);
  EXPECT_NEAR(length / 0.4, 1.0, 0.01);
  EXPECT_LT(kinetic_energy(strand, state), 1e-8);  // of 8e-4 J it could have
  // Still hanging below the root.
  Vec3 tip = state.position_m[static_cast<size_t>(strand.hair_particle.back())];
  EXPECT_NEAR(tip.y(), -0.4, 0.004);
  EXPECT_NEAR(tip.x(), 0, 0.002);  // 0.5% of its length sideways
}

TEST(StrandDynamics, AStepReportsTheSpringEnergyOfWhereItStarted) {
  // A falling horizontal strand: every step starts somewhere new, its springs stretched.
  AltitudeStrand strand = hair_strand(straight_strand(Vec3(1, 0, 0), 15, 0.3));
  StrandMaterial material;
  StrandState state = rest_state(strand);
  StrandStepper stepper;
  double largest = 0;
  for (int i = 0; i < 60; ++i) {
    const std::vector<Vec3> start = state.position_m;
    stepper.step(strand, material, {}, kGravity, {}, 1.0 / 120, state);
    const double expected = strand_spring_energy(strand, material, start);
    ASSERT_EQ(stepper.start_spring_energy_j(), expected) << "step " << i;
    // The anchors' part is separate: with none, the two energies are one.
    ASSERT_EQ(strand_elastic_energy(strand, material, start, {}), expected);
    largest = std::max(largest, expected);
  }
  EXPECT_GT(largest, 0);  // the strand bent
}

TEST(StrandDynamics, HorizontalStrandFallsSwingsAndDampsOut) {
  // Released horizontal: it swings down; with damping its energy decays. A lock of hairs
  // free to slide on one another, 30 cm long, is limp: it swings.
  AltitudeStrand strand = testing::free_hair_strand(straight_strand(Vec3(1, 0, 0), 15, 0.3));
  StrandMaterial material;
  StrandState state = rest_state(strand);
  StrandStepper stepper;
  const double dt_s = 1.0 / 120;
  std::vector<double> energy;  // kinetic + potential, per quarter second
  double lowest_tip_y = 0;
  for (int i = 1; i <= 8 * 120; ++i) {
    stepper.step(strand, material, {}, kGravity, {}, dt_s, state);
    lowest_tip_y = std::min(lowest_tip_y, state.position_m.back().y());
    for (double stretch : {max_hair_strain(strand, state.position_m)}) {
      ASSERT_LE(std::abs(stretch), material.max_stretch + 1e-9);
    }
    if (i % 30 == 0) {
      double total = kinetic_energy(strand, state) +
                     strand_elastic_energy(strand, material, state.position_m, {});
      for (size_t q = 0; q < strand.mass_kg.size(); ++q)  // gravity acts on every particle
        total += strand.mass_kg[q] * 9.81 * state.position_m[q].y();
      energy.push_back(total);
    }
  }
  EXPECT_LT(lowest_tip_y, -0.2);  // it fell
  // Energy decays: every second lower than the one before, or, come to rest, within 2% of
  // what the fall released (the altitude springs' switches are not quite conservative);
  // and it ends near rest.
  const double released = energy.front() - *std::min_element(energy.begin(), energy.end());
  for (size_t k = 4; k + 4 <= energy.size(); k += 4)
    EXPECT_LT(energy[k + 3], energy[k - 1] + 0.02 * released);
  EXPECT_LT(kinetic_energy(strand, state), 4e-6);  // 1% of the energy it fell by
  Vec3 tip = state.position_m.back();
  EXPECT_GT(-tip.y(), 0.25);  // hangs nearly straight down at the end
}

TEST(StrandDynamics, WavyStrandKeepsItsWavesUnderGravity) {
  // Two waves of 2 cm amplitude on a 30 cm strand: after settling under gravity the waves
  // are still there (amplitude within 25%).
  std::vector<Vec3> wave = wavy_strand(32, 0.3, 0.02, 2);
  AltitudeStrand strand = hair_strand(wave);
  auto amplitude = [&](const StrandState& state) {
    double low = 1e9, high = -1e9;
    for (int32_t q : strand.hair_particle) {
      low = std::min(low, state.position_m[static_cast<size_t>(q)].x());
      high = std::max(high, state.position_m[static_cast<size_t>(q)].x());
    }
    return 0.5 * (high - low);
  };
  StrandState stiff = rest_state(strand);
  run(strand, StrandMaterial{}, stiff, 3.0, 1.0 / 120);
  EXPECT_NEAR(amplitude(stiff) / 0.02, 1.0, 0.25);

  // The waves do not sag out of the strand: its tip stays within 8% of where it was.
  EXPECT_GT(stiff.position_m.back().y(), -0.3 * 1.08);
}

TEST(StrandDynamics, LargeTimeStepsStayFiniteAndBounded) {
  // One step per frame at 30 fps and 1000 times the stiffness: stable, no NaN.
  AltitudeStrand strand = hair_strand(straight_strand(Vec3(1, -0.2, 0.3), 20, 0.4));
  StrandMaterial material;
  material.stiffness_scale = 1000;
  StrandState state = rest_state(strand);
  StrandStepper stepper;
  for (int i = 0; i < 300; ++i) {
    stepper.step(strand, material, {}, kGravity, {}, 1.0 / 30, state);
    for (const Vec3& p : state.position_m) ASSERT_TRUE(p.allFinite());
    ASSERT_LE(std::abs(max_hair_strain(strand, state.position_m)), material.max_stretch + 1e-9);
  }
}

TEST(StrandDynamics, TwoRunsAgreeBitForBit) {
  AltitudeStrand strand = hair_strand(wavy_strand(20, 0.3, 0.03, 1.5));
  StrandState a = rest_state(strand), b = rest_state(strand);
  run(strand, StrandMaterial{}, a, 1.0, 1.0 / 120);
  run(strand, StrandMaterial{}, b, 1.0, 1.0 / 120);
  for (size_t k = 0; k < a.position_m.size(); ++k) EXPECT_EQ(a.position_m[k], b.position_m[k]);
}

}  // namespace
}  // namespace hair
