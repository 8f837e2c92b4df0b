// Strands of human hair (Young's modulus 3.89 GPa, shear modulus 0.89 GPa, radius 35 um,
// 1320 kg/m^3; 150 fibres per strand) against answers known from outside the code: the
// hanging chain's first mode, a cantilever's deflection under its own weight, and
// sag-free rest shapes (a helix, a groomed arc) that hold still under gravity.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "hair/sim/altitude_strand.h"
#include "hair/sim/sag_free_rest.h"
#include "hair/sim/strand_dynamics.h"
#include "hair/sim/strand_stiffness.h"
#include "unit/strand_rest_state.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;
using testing::hair_strand;
using testing::human_hair;
using testing::rest_state;

const Vec3 kGravity(0, -9.81, 0);

using testing::free_hair_strand;
using testing::free_hairs;

/// Steps `strand` for `seconds`; calls `each(time_s, state)` after every step.
template <typename Each>
void run(const AltitudeStrand& strand, const StrandMaterial& material, StrandState& state,
         double seconds, double dt_s, Each&& each) {
  StrandStepper stepper;
  const int steps = static_cast<int>(std::lround(seconds / dt_s));
  for (int i = 1; i <= steps; ++i) {
    stepper.step(strand, material, {}, kGravity, {}, dt_s, state);
    each(i * dt_s, state);
  }
}

Vec3 tip_of(const AltitudeStrand& strand, const StrandState& state) {
  return state.position_m[static_cast<size_t>(strand.hair_particle.back())];
}

TEST(ChainRigidity, TheCalibratedChainBendsAsTheLockAndTwistsAsNearAsItCan) {
  const HairFibre fibre;
  const double ratio = fibre.twisting_rigidity_n_m2() / fibre.bending_rigidity_n_m2();
  EXPECT_NEAR(ratio, 2 * 0.89 / 3.89, 1e-12);  // G J / E I = 2 G / E for a round fibre
  const ChainCalibration calibration = calibrate_chain(ratio);
  const ChainRigidity rigidity =
      measure_chain_rigidity(calibration.bend_group_n_m, calibration.torsion_n_m);
  // (to 1e-4: the measure's second differences under hair segments 1e6 times stiffer
  // than the bending springs carry rounding of a few parts in a million)
  EXPECT_NEAR(rigidity.bending_n_m2, 1.0, 1e-4);
  // The altitude chain cannot twist as readily as hair does (0.46 of its bending
  // rigidity): it comes to about 0.22, and the calibration reports what it reached.
  EXPECT_NEAR(calibration.achieved_twist_to_bend, rigidity.twisting_n_m2 / rigidity.bending_n_m2,
              1e-4);
  EXPECT_GT(calibration.achieved_twist_to_bend, 0.15);
  EXPECT_LT(calibration.achieved_twist_to_bend, ratio);
  EXPECT_GT(calibration.torsion_n_m, 0);
  // Across the chain it bends alike in two perpendicular planes, within 10%.
  EXPECT_LT(calibration.bending_anisotropy, 1.1);
  // The rigidity is linear in the springs: twice the springs (segments too), twice it.
  const ChainRigidity doubled =
      measure_chain_rigidity(2 * calibration.bend_group_n_m, 2 * calibration.torsion_n_m, 2e6);
  EXPECT_NEAR(doubled.bending_n_m2, 2.0, 1e-4);
  // Softer hair segments (finer particles against the radius) soften the chain: the
  // calibration for them is stiffer.
  EXPECT_GT(calibrate_chain(ratio, 400).bend_group_n_m, calibration.bend_group_n_m);
}

TEST(StrandStiffness, ALockBendsBetweenFreeAndBondedFibres) {
  const HairFibre fibre;
  const double single = fibre.bending_rigidity_n_m2();
  EXPECT_NEAR(single, 3.89e9 * std::numbers::pi * std::pow(35e-6, 4) / 4, 1e-20);
  auto lock = [](double fibres, double cohesion) {
    StrandMaterial material;
    material.fibres_per_strand = fibres;
    material.lock_cohesion = cohesion;
    return StrandStiffness(material);
  };
  EXPECT_NEAR(lock(600, 0).bending_rigidity_n_m2(), 600 * single, 1e-15);
  EXPECT_NEAR(lock(600, 1).bending_rigidity_n_m2(), 600 * 600 * single, 1e-12);
  EXPECT_NEAR(lock(600, 0.3).bending_rigidity_n_m2(), 600 * (1 + 0.3 * 599) * single, 1e-12);
  EXPECT_THROW(lock(600, 1.5), std::invalid_argument);
  EXPECT_THROW(lock(0.5, 0.3), std::invalid_argument);
  // A hair segment's spring vibrates at the stretch frequency with its particles' mass,
  // unless that is under 1000 times the bending springs' scale E I / l^3 (a stiff lock,
  // short segments), or over the hair's own E A / L.
  const double omega = 2 * std::numbers::pi * StrandMaterial{}.stretch_frequency_hz;
  for (double cohesion : {0.0, 0.3}) {
    const StrandStiffness hair = lock(600, cohesion);
    std::vector<Vec3> points{Vec3(0, 0, 0), Vec3(0, -0.04, 0), Vec3(0, -0.08, 0)};
    const AltitudeStrand strand = build_hair_strand(points, hair);
    const double floor = 1000 * hair.bending_rigidity_n_m2() / std::pow(0.04, 3);
    const double own = 600 * 3.89e9 * fibre.area_m2() / 0.04;
    for (const TwoParticleSpring& spring : strand.springs) {
      if (!spring.hair_segment) continue;
      const double mass = 0.5 * (strand.mass_kg[static_cast<size_t>(spring.a)] +
                                 strand.mass_kg[static_cast<size_t>(spring.b)]);
      const double expected = std::min(std::max(mass * omega * omega, floor), own);
      EXPECT_NEAR(spring.stiffness_n_m, expected, 1e-9 * expected) << cohesion;
    }
  }
  const StrandStiffness hair = lock(600, 0.3);
  const AltitudeStrand strand =
      build_hair_strand({Vec3(0, 0, 0), Vec3(0, -0.02, 0), Vec3(0, -0.04, 0)}, hair);
  double mass = 0;
  for (size_t q = 1; q < strand.mass_kg.size(); ++q) mass += strand.mass_kg[q];  // 0: held ghost
  EXPECT_NEAR(mass, 600 * 1320 * fibre.area_m2() * 0.04, 1e-12);
}

TEST(HairPhysics, HangingStrandSwingsAtTheFirstModeOfAHangingChain) {
  // A 50 cm lock of free hairs hanging from a still root, released from the first mode's
  // shape, the Bessel function J0(2.4048 sqrt(z / L)) (z up from the free end): it swings
  // at omega = 1.2024 sqrt(g / L) (Bernoulli's hanging chain; its bending length, 1.4 cm
  // under the tension at its root, is small against its length). No air drag.
  const double length_m = 0.5;
  const int segments = 40;
  std::vector<Vec3> points;
  for (int i = 0; i <= segments; ++i) points.emplace_back(0, -length_m * i / segments, 0);
  const AltitudeStrand strand = free_hair_strand(points);
  StrandMaterial material;
  material.drag_per_s = 0;
  StrandState state = rest_state(strand);
  const double amplitude_m = 0.01;
  for (size_t q = static_cast<size_t>(strand.kinematic_count); q < strand.rest_m.size(); ++q) {
    const double z = length_m + strand.rest_m[q].y();  // up from the free end
    state.position_m[q].x() += amplitude_m * std::cyl_bessel_j(0.0, 2.4048 * std::sqrt(std::max(z, 0.0) / length_m));
  }
  const double expected_omega = 1.2024 * std::sqrt(9.81 / length_m);
  // Upward zero crossings of the tip's x, interpolated.
  std::vector<double> crossings;
  double previous_x = tip_of(strand, state).x(), previous_t = 0;
  run(strand, material, state, 6.0, 1.0 / 600, [&](double t, const StrandState& s) {
    const double x = tip_of(strand, s).x();
    if (previous_x < 0 && x >= 0) crossings.push_back(previous_t + (t - previous_t) * -previous_x / (x - previous_x));
    previous_x = x;
    previous_t = t;
  });
  ASSERT_GE(crossings.size(), 3u);
  const double period_s = (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  const double omega = 2 * std::numbers::pi / period_s;
  RecordProperty("omega_rad_s", std::to_string(omega));
  EXPECT_NEAR(omega / expected_omega, 1.0, 0.05) << omega << " rad/s against " << expected_omega;
}

TEST(HairPhysics, ShortHorizontalStrandsDeflectAsCantilevers) {
  // A 3 cm lock of free hairs held horizontally at its root bends under its own weight w
  // per metre by delta = w L^4 / (8 E I) at its tip (Euler-Bernoulli; delta / L = 0.037),
  // E I the lock's. In eight directions about the vertical (its ghosts sit differently
  // about each): each within 10% of the answer, and the mean.
  const double length_m = 0.03;
  const int segments = 20;
  const StrandMaterial material;
  const double w = 600 * material.fibre.mass_per_length_kg_m() * 9.81;
  const double expected_m = w * std::pow(length_m, 4) / (8 * free_hairs().bending_rigidity_n_m2());
  ASSERT_LT(expected_m / length_m, 0.1);
  double sum = 0;
  for (int direction = 0; direction < 8; ++direction) {
    const double angle = direction * std::numbers::pi / 4;
    const Vec3 along(std::cos(angle), 0, std::sin(angle));
    std::vector<Vec3> points;
    for (int i = 0; i <= segments; ++i) points.push_back(length_m * i / segments * along);
    const AltitudeStrand strand = free_hair_strand(points);
    StrandState state = rest_state(strand);
    run(strand, material, state, 3.0, 1.0 / 2000, [](double, const StrandState&) {});
    const double ratio = -tip_of(strand, state).y() / expected_m;
    RecordProperty("deflection_ratio_" + std::to_string(direction), std::to_string(ratio));
    EXPECT_NEAR(ratio, 1.0, 0.10) << "direction " << direction;
    sum += ratio;
    double fastest = 0;  // its hair at rest by then
    for (int32_t q : strand.hair_particle)
      fastest = std::max(fastest, state.velocity_m_s[static_cast<size_t>(q)].norm());
    EXPECT_LT(fastest, 0.01 * length_m);
  }
  RecordProperty("deflection_ratio_mean", std::to_string(sum / 8));
  EXPECT_NEAR(sum / 8, 1.0, 0.10);
}

/// A helix hanging down -y: `turns` turns of radius `radius_m` and pitch `pitch_m`,
/// `per_turn` hair particles per turn.
std::vector<Vec3> helix(double radius_m, double pitch_m, int turns, int per_turn) {
  std::vector<Vec3> points;
  for (int i = 0; i <= turns * per_turn; ++i) {
    const double angle = 2 * std::numbers::pi * i / per_turn;
    points.emplace_back(radius_m * std::cos(angle), -pitch_m * i / per_turn, radius_m * std::sin(angle));
  }
  return points;
}

/// Radius (mean distance of the hair particles from the y axis through the helix's mean)
/// and pitch (the hair's drop over its turns) of a hanging helix.
std::pair<double, double> radius_and_pitch(const AltitudeStrand& strand,
                                           const std::vector<Vec3>& position_m, int turns) {
  Vec3 mean = Vec3::Zero();
  for (int32_t q : strand.hair_particle) mean += position_m[static_cast<size_t>(q)];
  mean /= strand.hair_count();
  double radius = 0;
  for (int32_t q : strand.hair_particle) {
    const Vec3 d = position_m[static_cast<size_t>(q)] - mean;
    radius += std::hypot(d.x(), d.z());
  }
  radius /= strand.hair_count();
  const double drop = position_m[static_cast<size_t>(strand.hair_particle.front())].y() -
                      position_m[static_cast<size_t>(strand.hair_particle.back())].y();
  return {radius, drop / turns};
}

TEST(HairPhysics, ASagFreeHelixKeepsItsRadiusAndPitch) {
  // A curl of 8 turns, 1 cm radius, 2 cm pitch. With its springs at rest in the groom,
  // gravity stretches it out; sag-free, it keeps its shape within 5% (the groom is its
  // shape at rest), and at the groom every free particle's forces sum to zero.
  const int turns = 8;
  const std::vector<Vec3> points = helix(0.01, 0.02, turns, 8);
  const StrandMaterial material;
  AltitudeStrand sagging = free_hair_strand(points);
  AltitudeStrand sag_free = sagging;
  const SagFreeReport report = make_sag_free(sag_free, material, kGravity);
  EXPECT_GT(report.support_n, 0);
  double largest_force = 0, weight = 0;
  for (const Vec3& f : strand_static_force(sag_free, material, sag_free.rest_m, kGravity))
    largest_force = std::max(largest_force, f.norm());
  for (double m : sag_free.mass_kg) weight = std::max(weight, m * 9.81);
  EXPECT_LT(largest_force, 1e-6 * weight);

  for (bool solved : {false, true}) {
    const AltitudeStrand& strand = solved ? sag_free : sagging;
    StrandState state = rest_state(strand);
    run(strand, material, state, 3.0, 1.0 / 120, [](double, const StrandState&) {});
    auto [radius, pitch] = radius_and_pitch(strand, state.position_m, turns);
    auto [rest_radius, rest_pitch] = radius_and_pitch(strand, strand.rest_m, turns);
    RecordProperty(solved ? "sag_free_pitch_ratio" : "sagging_pitch_ratio",
                   std::to_string(pitch / rest_pitch));
    if (solved) {
      EXPECT_NEAR(radius / rest_radius, 1.0, 0.05);
      EXPECT_NEAR(pitch / rest_pitch, 1.0, 0.05);
    } else {
      EXPECT_GT(pitch / rest_pitch, 1.05);  // without: the curl pulls out under its weight
    }
  }
}

TEST(HairPhysics, ASagFreeGroomHoldsStillForTenSeconds) {
  // A strand leaving its root sideways, arching down over 3 cm and hanging 20 cm (hair
  // out of a band): sag-free, no tip moves more than 1% of its length in 10 s of a still
  // root; with its springs at rest in the groom it sags far more.
  std::vector<Vec3> points;
  const double radius_m = 0.03;
  for (int i = 0; i <= 4; ++i) {
    const double angle = 0.5 * std::numbers::pi * i / 4;
    points.emplace_back(radius_m * std::sin(angle), radius_m * (std::cos(angle) - 1), 0);
  }
  for (int i = 1; i <= 8; ++i) points.emplace_back(radius_m, -radius_m - 0.025 * i, 0.002 * i);
  const StrandMaterial material;
  AltitudeStrand sagging = free_hair_strand(points);
  AltitudeStrand sag_free = sagging;
  make_sag_free(sag_free, material, kGravity);
  double length_m = 0;
  for (double l : sag_free.hair_segment_m) length_m += l;
  for (bool solved : {true, false}) {
    const AltitudeStrand& strand = solved ? sag_free : sagging;
    StrandState state = rest_state(strand);
    double farthest = 0;
    const Vec3 start = tip_of(strand, state);
    run(strand, material, state, 10.0, 1.0 / 60, [&](double, const StrandState& s) {
      farthest = std::max(farthest, (tip_of(strand, s) - start).norm());
    });
    RecordProperty(solved ? "sag_free_tip_drift" : "sagging_tip_drift",
                   std::to_string(farthest / length_m));
    if (solved)
      EXPECT_LT(farthest / length_m, 0.01);
    else
      EXPECT_GT(farthest / length_m, 0.1);
  }
}

TEST(SagFreeRest, AHangingStrandCarriesItsWeightAndALevelOneIsHeld) {
  // Hanging straight down, the hair carries its own weight by tension: only the ghosts
  // are held up. Held out level, it carries none of its weight along itself: all of it
  // is held up. The tension at the root is the weight below it.
  const StrandMaterial material;
  std::vector<Vec3> down, level;
  for (int i = 0; i <= 10; ++i) {
    down.emplace_back(0, -0.02 * i, 0);
    level.emplace_back(0.02 * i, 0, 0);
  }
  AltitudeStrand hanging = hair_strand(down), held = hair_strand(level);
  const SagFreeReport hanging_report = make_sag_free(hanging, material, kGravity);
  const SagFreeReport held_report = make_sag_free(held, material, kGravity);
  double ghosts_n = 0;
  for (size_t q = static_cast<size_t>(hanging.kinematic_count); q < hanging.mass_kg.size(); ++q)
    if (hanging.is_ghost[q]) ghosts_n += hanging.mass_kg[q] * 9.81;
  EXPECT_NEAR(hanging_report.support_n, ghosts_n, 1e-9 * ghosts_n);
  for (int32_t q : hanging.hair_particle)
    EXPECT_LT(hanging.rest_support_n[static_cast<size_t>(q)].norm(), 1e-12);
  EXPECT_NEAR(held_report.support_n, held_report.weight_n, 1e-9 * held_report.weight_n);
  // The root segment's spring is shortened by the weight below it over its stiffness.
  double below_n = 0;
  for (size_t q = static_cast<size_t>(hanging.kinematic_count); q < hanging.mass_kg.size(); ++q)
    if (!hanging.is_ghost[q]) below_n += hanging.mass_kg[q] * 9.81;
  for (const TwoParticleSpring& spring : hanging.springs) {
    if (!spring.hair_segment || spring.a != hanging.hair_particle[0]) continue;
    const double groomed = (hanging.rest_m[static_cast<size_t>(spring.b)] -
                            hanging.rest_m[static_cast<size_t>(spring.a)]).norm();
    EXPECT_NEAR(groomed - spring.rest_length_m, below_n / spring.stiffness_n_m, 1e-15);
  }
}

TEST(SagFreeRest, TheSupportTurnsWithTheHead) {
  // A lock held level at rest by its support. Turned with the head upside down, the
  // support points down with gravity, and it falls; left as it was, it stays.
  const StrandMaterial material;
  std::vector<Vec3> level;
  for (int i = 0; i <= 8; ++i) level.emplace_back(0.02 * i, 0, 0);
  AltitudeStrand strand = free_hair_strand(level);
  make_sag_free(strand, material, kGravity);
  StrandState still = rest_state(strand), turned = rest_state(strand);
  StrandStepper stepper;
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d flipped = Eigen::AngleAxisd(std::numbers::pi, Vec3::UnitX()).toRotationMatrix();
  for (int i = 0; i < 60; ++i) {
    stepper.step(strand, material, {}, kGravity, {}, 1.0 / 60, still, nullptr, 0, &identity);
    stepper.step(strand, material, {}, kGravity, {}, 1.0 / 60, turned, nullptr, 0, &flipped);
  }
  EXPECT_LT((tip_of(strand, still) - strand.rest_m.back()).norm(), 1e-6);
  EXPECT_LT(tip_of(strand, turned).y(), -0.05);
}

}  // namespace
}  // namespace hair
