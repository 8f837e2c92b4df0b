#include "hair/sim/strand_stiffness.h"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <string>

#include "hair/sim/banded_cholesky.h"
#include "hair/sim/strand_springs.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;
using strand_springs::BandSystem;
using strand_springs::for_each_spring;
using strand_springs::LinearSpring;

constexpr int kReferenceSegments = 48;
/// A hair segment's spring is at least this many times the bending springs' scale E I /
/// l^3: its chord then softens the chain's bending by under 1% (calibrated for anyway).
constexpr double kMinSegmentToBending = 1000;
/// Hair segments stiff enough against unit bending springs to stand for inextensible hair,
/// for the search of the torsion springs' share.
constexpr double kInextensible = 1e6;

/// A straight chain of unit hair segments along a direction no axis of the ghosts'
/// placement favours.
struct ReferenceChain {
  AltitudeStrand strand;
  Vec3 axis;
};

ReferenceChain reference_chain(double bend_group_n_m, double torsion_n_m,
                               double hair_segment_n_m, const AltitudeStrandOptions& options) {
  ReferenceChain chain;
  chain.axis = Vec3(0.3, -0.9, 0.2).normalized();
  std::vector<Vec3> points;
  for (int i = 0; i <= kReferenceSegments; ++i) points.push_back(i * chain.axis);
  chain.strand = build_altitude_strand(points, 1.0, options);
  for (TwoParticleSpring& spring : chain.strand.springs)
    spring.stiffness_n_m = spring.hair_segment                 ? hair_segment_n_m
                           : spring.kind == SpringKind::torsion ? torsion_n_m
                                                                : bend_group_n_m;
  for (ChainTetrahedron& tetrahedron : chain.strand.tetrahedra)
    tetrahedron.stiffness_n_m = bend_group_n_m;
  return chain;
}

/// Linear statics at rest: K u = f over the free particles (the root and its ghost
/// clamped), K = sum_s k_s J_s^T J_s (no spring is stretched at rest, so there is no
/// geometric stiffness).
std::vector<Vec3> static_displacement(const AltitudeStrand& strand, const std::vector<Vec3>& force) {
  const int32_t first_free = strand.kinematic_count, count = strand.particle_count();
  std::vector<double> band, rhs;
  BandSystem::reset(band, rhs, count, first_free);
  BandSystem system(band, rhs, first_free);
  for_each_spring(strand, 1.0, strand.rest_m,
                  [&](const LinearSpring& spring) { system.add_spring_outer(spring, spring.stiffness); });
  for (int32_t q = first_free; q < count; ++q) system.add_rhs(q, force[static_cast<size_t>(q)]);
  const int n = 3 * (count - first_free);
  if (int info = solve_banded_spd(band, rhs, n, strand_springs::kBandwidth); info != 0)
    throw std::runtime_error("chain rigidity: the reference chain's stiffness is singular (minor " +
                             std::to_string(info) + ")");
  std::vector<Vec3> displacement(static_cast<size_t>(count), Vec3::Zero());
  for (int32_t q = first_free; q < count; ++q)
    displacement[static_cast<size_t>(q)] = strand_springs::solved_particle(rhs, first_free, q);
  return displacement;
}

/// The middle half of the hair segments' or particles' indices.
bool in_middle(int i, int count) { return i >= count / 4 && i <= 3 * count / 4; }

/// Bending rigidity in the plane of the axis and `across`: a couple of unit forces on the
/// last hair segment (a moment of 1 N m, unit segments) bends the chain uniformly; the
/// curvature is the second difference of the hair particles' displacements.
double bending_rigidity(const ReferenceChain& chain, const Vec3& across) {
  const AltitudeStrand& strand = chain.strand;
  const int hairs = strand.hair_count();
  std::vector<Vec3> force(static_cast<size_t>(strand.particle_count()), Vec3::Zero());
  force[static_cast<size_t>(strand.hair_particle[static_cast<size_t>(hairs - 1)])] = across;
  force[static_cast<size_t>(strand.hair_particle[static_cast<size_t>(hairs - 2)])] = -across;
  const std::vector<Vec3> u = static_displacement(strand, force);
  auto w = [&](int i) {
    return u[static_cast<size_t>(strand.hair_particle[static_cast<size_t>(i)])].dot(across);
  };
  double curvature_sum = 0;
  int samples = 0;
  for (int i = 1; i + 1 < hairs; ++i) {
    if (!in_middle(i, hairs)) continue;
    curvature_sum += w(i + 1) - 2 * w(i) + w(i - 1);
    ++samples;
  }
  return std::abs(samples / curvature_sum);
}

/// Twisting rigidity: the last ghost pushed about the axis by a unit force, its two hair
/// neighbours held back by half of it each (a pure torque of the ghost's offset in N m);
/// each ghost's turn about the axis against its segment, fitted linearly along the middle
/// half, is the twist per unit length.
double twisting_rigidity(const ReferenceChain& chain) {
  const AltitudeStrand& strand = chain.strand;
  const int32_t count = strand.particle_count();
  struct GhostFrame {
    int32_t ghost;
    Vec3 tangent;
    double offset_m, along_m;
  };
  std::vector<GhostFrame> ghosts;
  for (int32_t q = 1; q + 1 < count; ++q) {
    if (!strand.is_ghost[static_cast<size_t>(q)]) continue;
    const Vec3 middle =
        0.5 * (strand.rest_m[static_cast<size_t>(q - 1)] + strand.rest_m[static_cast<size_t>(q + 1)]);
    const Vec3 radial = strand.rest_m[static_cast<size_t>(q)] - middle;
    ghosts.push_back({q, chain.axis.cross(radial.normalized()), radial.norm(),
                      middle.dot(chain.axis)});
  }
  const GhostFrame& last = ghosts.back();
  std::vector<Vec3> force(static_cast<size_t>(count), Vec3::Zero());
  force[static_cast<size_t>(last.ghost)] = last.tangent;
  force[static_cast<size_t>(last.ghost - 1)] = -0.5 * last.tangent;
  force[static_cast<size_t>(last.ghost + 1)] = -0.5 * last.tangent;
  const double torque_n_m = last.offset_m;
  const std::vector<Vec3> u = static_displacement(strand, force);
  // Least-squares slope of the turn against the position along the axis.
  double sum_s = 0, sum_a = 0, sum_ss = 0, sum_sa = 0;
  int samples = 0;
  const auto ghost_count = static_cast<int>(ghosts.size());
  for (int j = 0; j < ghost_count; ++j) {
    if (!in_middle(j, ghost_count)) continue;
    const GhostFrame& g = ghosts[static_cast<size_t>(j)];
    const auto q = static_cast<size_t>(g.ghost);
    const double turn = (u[q] - 0.5 * (u[q - 1] + u[q + 1])).dot(g.tangent) / g.offset_m;
    sum_s += g.along_m;
    sum_a += turn;
    sum_ss += g.along_m * g.along_m;
    sum_sa += g.along_m * turn;
    ++samples;
  }
  const double slope = (samples * sum_sa - sum_s * sum_a) / (samples * sum_ss - sum_s * sum_s);
  return std::abs(torque_n_m / slope);
}

}  // namespace

ChainRigidity measure_chain_rigidity(double bend_group_n_m, double torsion_n_m,
                                     double hair_segment_n_m,
                                     const AltitudeStrandOptions& options) {
  const ReferenceChain chain =
      reference_chain(bend_group_n_m, torsion_n_m, hair_segment_n_m, options);
  // Two directions across the axis.
  const Vec3 helper = std::abs(chain.axis.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 first = chain.axis.cross(helper).normalized();
  const Vec3 second = chain.axis.cross(first);
  const double a = bending_rigidity(chain, first), b = bending_rigidity(chain, second);
  ChainRigidity rigidity;
  rigidity.bending_n_m2 = 0.5 * (a + b);
  rigidity.bending_anisotropy = std::max(a, b) / std::min(a, b);
  rigidity.twisting_n_m2 = twisting_rigidity(chain);
  return rigidity;
}

ChainCalibration calibrate_chain(double twist_to_bend, double hair_segment_n_m,
                                 const AltitudeStrandOptions& options) {
  if (!(twist_to_bend > 0) || !std::isfinite(twist_to_bend))
    throw std::invalid_argument("calibrate_chain: the twist to bend ratio must be positive");
  auto ratio_at = [&](double log_torsion) {
    ChainRigidity r = measure_chain_rigidity(1.0, std::exp(log_torsion), kInextensible, options);
    return r.twisting_n_m2 / r.bending_n_m2;
  };
  // The ratio is not monotonic in the torsion springs (they stiffen bending more than
  // twist once strong), and the bend group alone gives the chain some twisting rigidity:
  // the nearest ratio on a grid of 161 torsion constants, 1e-2 to 1e2 of the bend group's.
  const double low = std::log(1e-2), high = std::log(1e2);
  constexpr int kGrid = 160;
  double log_torsion = low, best_miss = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= kGrid; ++i) {
    const double candidate = low + (high - low) * i / kGrid;
    const double miss = std::abs(std::log(ratio_at(candidate) / twist_to_bend));
    if (miss < best_miss) {
      best_miss = miss;
      log_torsion = candidate;
    }
  }
  // The scale of both that gives unit bending rigidity with hair segments of the given
  // stiffness: the rigidity is that of the bending springs in series with the hair
  // segments' (the chord on the axis), so scaling the springs scales it less than in
  // proportion where the segments are not far stiffer; a fixed-point iteration.
  const double torsion_share = std::exp(log_torsion);
  auto rigidity_at = [&](double scale) {
    return measure_chain_rigidity(scale, scale * torsion_share, hair_segment_n_m, options);
  };
  // Secant iterations on the bending rigidity against the scale, from the scale that
  // unit rigidity would need were it proportional.
  double previous_scale = 1, scale = 1;
  ChainRigidity previous = rigidity_at(previous_scale), rigidity = previous;
  scale = 1 / previous.bending_n_m2;
  for (int iteration = 0; iteration < 30; ++iteration) {
    rigidity = rigidity_at(scale);
    if (std::abs(rigidity.bending_n_m2 - 1) < 1e-10) break;
    const double slope =
        (rigidity.bending_n_m2 - previous.bending_n_m2) / (scale - previous_scale);
    previous_scale = scale;
    previous = rigidity;
    if (!(slope > 0)) {
      scale /= rigidity.bending_n_m2;
      continue;
    }
    scale += (1 - rigidity.bending_n_m2) / slope;
  }
  ChainCalibration calibration;
  calibration.bend_group_n_m = scale;
  calibration.torsion_n_m = scale * torsion_share;
  calibration.achieved_twist_to_bend = rigidity.twisting_n_m2 / rigidity.bending_n_m2;
  calibration.bending_anisotropy = rigidity.bending_anisotropy;
  return calibration;
}

StrandStiffness::StrandStiffness(const StrandMaterial& material,
                                 const AltitudeStrandOptions& options)
    : fibre_(material.fibre),
      fibres_(material.fibres_per_strand),
      cohesion_(material.lock_cohesion),
      damping_ratio_(material.damping_ratio),
      stretch_frequency_hz_(material.stretch_frequency_hz),
      options_(options) {
  const HairFibre& fibre = material.fibre;
  if (!(fibre.youngs_modulus_pa > 0 && fibre.shear_modulus_pa > 0 && fibre.radius_m > 0 &&
        fibre.density_kg_m3 > 0 && fibres_ >= 1 && stretch_frequency_hz_ > 0))
    throw std::invalid_argument(
        "hair material: moduli, radius, density and stretch frequency must be positive, "
        "fibres per strand at least 1");
  if (!(cohesion_ >= 0 && cohesion_ <= 1))
    throw std::invalid_argument("hair material: lock cohesion must be within 0 and 1");
}

double StrandStiffness::bending_rigidity_n_m2(double strand_count) const {
  // Each strand a lock; strands side by side (a wisp's) add their locks' rigidities, as
  // their masses add: the cohesion binds the hairs of a lock, not the locks of a braid.
  return strand_count * fibres_ * (1 + cohesion_ * (fibres_ - 1)) * fibre_.bending_rigidity_n_m2();
}

double StrandStiffness::mass_per_length_kg_m(double strand_count) const {
  return fibres_ * strand_count * fibre_.mass_per_length_kg_m();
}

ChainCalibration StrandStiffness::calibration(double segment_stiffness) const {
  // Bins of 1/64 of a decade in the hair segments' stiffness (in units of the bending
  // rigidity over l^3), 3.7% apart; each bin calibrated once, at its centre.
  const double bin = std::round(64 * std::log10(segment_stiffness));
  std::lock_guard<std::mutex> lock(cache_mutex_);
  auto found = cache_.find(bin);
  if (found != cache_.end()) return found->second;
  const ChainCalibration calibration =
      calibrate_chain(fibre_.twisting_rigidity_n_m2() / fibre_.bending_rigidity_n_m2(),
                      std::pow(10.0, bin / 64), options_);
  cache_.emplace(bin, calibration);
  return calibration;
}

void StrandStiffness::assign(AltitudeStrand& strand, double strand_count) const {
  double segment_sum_m = 0;
  for (double length : strand.hair_segment_m) segment_sum_m += length;
  const double segment_m = segment_sum_m / static_cast<double>(strand.hair_segment_m.size());
  const double bending_n_m2 = bending_rigidity_n_m2(strand_count);
  const double per_cube = bending_n_m2 / (segment_m * segment_m * segment_m);
  const double stretch_omega = 2 * std::numbers::pi * stretch_frequency_hz_;
  const double fibres_area_m2 = fibres_ * strand_count * fibre_.area_m2();
  auto mass = [&](int32_t q) { return strand.mass_kg[static_cast<size_t>(q)]; };
  // A hair segment's spring: at the stretch frequency, but at least kMinSegmentToBending
  // times the bending springs' scale (so the chain bends as a beam, its segments a chord
  // that does not give) and at most the hair's own E A / L.
  auto segment_stiffness = [&](const TwoParticleSpring& spring) {
    const double numerical = 0.5 * (mass(spring.a) + mass(spring.b)) * stretch_omega * stretch_omega;
    const double own = fibre_.youngs_modulus_pa * fibres_area_m2 / spring.rest_length_m;
    return std::min(std::max(numerical, kMinSegmentToBending * per_cube), own);
  };
  double segment_sum = 0;
  int segments = 0;
  for (const TwoParticleSpring& spring : strand.springs) {
    if (!spring.hair_segment) continue;
    segment_sum += segment_stiffness(spring);
    ++segments;
  }
  const ChainCalibration chain =
      calibration(segments > 0 ? segment_sum / segments / per_cube : kMinSegmentToBending);
  const double bend_group = chain.bend_group_n_m * per_cube;
  const double torsion = chain.torsion_n_m * per_cube;
  auto damping = [&](double stiffness, double mean_mass) {
    return 2 * damping_ratio_ * std::sqrt(stiffness * mean_mass);
  };
  for (TwoParticleSpring& spring : strand.springs) {
    spring.stiffness_n_m = spring.hair_segment                 ? segment_stiffness(spring)
                           : spring.kind == SpringKind::torsion ? torsion
                                                                : bend_group;
    spring.damping_n_s_m = damping(spring.stiffness_n_m, 0.5 * (mass(spring.a) + mass(spring.b)));
  }
  for (ChainTetrahedron& tetrahedron : strand.tetrahedra) {
    tetrahedron.stiffness_n_m = bend_group;
    double mean = 0;
    for (int32_t q : tetrahedron.particle) mean += 0.25 * mass(q);
    tetrahedron.damping_n_s_m = damping(bend_group, mean);
  }
}

AltitudeStrand build_hair_strand(const std::vector<Vec3>& hair_points_m,
                                 const StrandStiffness& stiffness, double strand_count,
                                 const AltitudeStrandOptions& options) {
  AltitudeStrand strand =
      build_altitude_strand(hair_points_m, stiffness.mass_per_length_kg_m(strand_count), options);
  stiffness.assign(strand, strand_count);
  return strand;
}

}  // namespace hair
