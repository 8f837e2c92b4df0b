#include "hair/sim/strand_dynamics.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "hair/sim/banded_cholesky.h"
#include "hair/sim/strand_springs.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;

using strand_springs::BandSystem;
using strand_springs::for_each_spring;
using strand_springs::kBandwidth;
using strand_springs::LinearSpring;
using strand_springs::spring_energy;

/// Inertia, drag and the external forces of every free particle: M (1 + dt drag) on the
/// diagonal, M v + dt M a on the right. The uniform acceleration (gravity) acts on every
/// particle, ghosts too (the strand's mass is shared among them, so its weight is the
/// hair's); the per-particle one (hair-hair repulsion) on the hair particles.
void add_inertia(BandSystem& system, const AltitudeStrand& strand, const StrandMaterial& material,
                 const std::vector<Vec3>& acceleration_m_s2, const Vec3& uniform_acceleration_m_s2,
                 double dt_s, const std::vector<Vec3>& v, const Eigen::Matrix3d* support_rotation) {
  const bool supported = !strand.rest_support_n.empty();
  for (int32_t q = system.first_free(); q < strand.particle_count(); ++q) {
    auto k = static_cast<size_t>(q);
    double mass = strand.mass_kg[k];
    Vec3 acceleration = uniform_acceleration_m_s2;
    if (!strand.is_ghost[k] && !acceleration_m_s2.empty()) acceleration += acceleration_m_s2[k];
    system.add_diagonal(q, mass * (1 + dt_s * material.drag_per_s));
    Vec3 rhs = mass * v[k] + dt_s * mass * acceleration;
    if (supported)
      rhs += dt_s * (support_rotation ? Vec3(*support_rotation * strand.rest_support_n[k])
                                      : strand.rest_support_n[k]);
    system.add_rhs(q, rhs);
  }
}

/// One spring, implicit along its direction: dt (c + dt k) w_a w_b d d^T into the matrix,
/// -dt k (l - L) w_a d on the right, and, for a spring that reaches kinematic particles,
/// the rate of its length that their velocities (`known_velocity_sum`: sum of weight
/// times velocity over them) give.
void add_spring(BandSystem& system, const LinearSpring& spring, double dt_s,
                const Vec3* known_velocity_sum) {
  const int32_t first_free = system.first_free();
  double implicit = dt_s * (spring.damping + dt_s * spring.stiffness);
  double known_rate = known_velocity_sum ? spring.direction.dot(*known_velocity_sum) : 0.0;
  const Eigen::Matrix3d outer = spring.direction * spring.direction.transpose();
  for (int a = 0; a < spring.count; ++a) {
    int32_t qa = spring.particle[static_cast<size_t>(a)];
    double wa = spring.weight[static_cast<size_t>(a)];
    if (qa >= first_free) {
      system.add_rhs(qa, (-dt_s * spring.stiffness * (spring.length_m - spring.rest_length_m) * wa) *
                             spring.direction);
      if (known_rate != 0) system.add_rhs(qa, (-implicit * wa * known_rate) * spring.direction);
    }
    for (int b = a; b < spring.count; ++b) {
      int32_t qb = spring.particle[static_cast<size_t>(b)];
      if (qa < first_free || qb < first_free) continue;
      double coefficient = implicit * wa * spring.weight[static_cast<size_t>(b)];
      if (qa <= qb)
        system.add_outer(qa, qb, coefficient, outer);
      else
        system.add_outer(qb, qa, coefficient, outer);
    }
  }
}

/// Every spring of the strand at `x` (anchors excluded) into the system; returns their
/// elastic energy there, as strand_spring_energy() sums it.
double add_springs(BandSystem& system, const AltitudeStrand& strand, const StrandMaterial& material,
                   double dt_s, const std::vector<Vec3>& x, const std::vector<Vec3>& v) {
  const int32_t first_free = system.first_free();
  double energy_j = 0;
  for_each_spring(strand, material.stiffness_scale, x, [&](const LinearSpring& spring) {
    energy_j += spring_energy(spring);
    if (spring.count == 2 && spring.particle[0] >= first_free) {
      // Most springs: two free particles, weights -1 and 1 (add_spring, unrolled).
      const int32_t qa = spring.particle[0], qb = spring.particle[1];
      const double implicit = dt_s * (spring.damping + dt_s * spring.stiffness);
      const Vec3 force =
          (-dt_s * spring.stiffness * (spring.length_m - spring.rest_length_m)) * spring.direction;
      system.add_rhs(qa, -force);
      system.add_rhs(qb, force);
      const Eigen::Matrix3d outer = spring.direction * spring.direction.transpose();
      system.add_outer(qa, qa, implicit, outer);
      system.add_outer(qa, qb, -implicit, outer);
      system.add_outer(qb, qb, implicit, outer);
      return;
    }
    // Sum of weight * velocity over the spring's kinematic particles.
    Vec3 known = Vec3::Zero();
    bool any_known = false;
    for (int a = 0; a < spring.count; ++a) {
      int32_t qa = spring.particle[static_cast<size_t>(a)];
      if (qa < first_free) {
        known += spring.weight[static_cast<size_t>(a)] * v[static_cast<size_t>(qa)];
        any_known = true;
      }
    }
    add_spring(system, spring, dt_s, any_known ? &known : nullptr);
  });
  return energy_j;
}

/// The springs from a free first particle (a wisp centre's) to its anchors, whose ends
/// move as the anchors' velocities say.
void add_anchor_springs(BandSystem& system, const AltitudeStrand& strand,
                        const StrandMaterial& material, const std::vector<StrandAnchor>& anchors,
                        double dt_s, const std::vector<Vec3>& x) {
  double mass = strand.mass_kg[0];
  double stiffness = material.anchor_stiffness_per_kg * mass;
  double damping = 2 * material.damping_ratio * std::sqrt(material.anchor_stiffness_per_kg) * mass;
  LinearSpring linear;
  linear.count = 1;  // the anchor's end is known
  linear.particle[0] = 0;
  linear.weight[0] = 1;
  linear.stiffness = stiffness;
  linear.damping = damping;
  for (const StrandAnchor& anchor : anchors) {
    Vec3 span = x[0] - anchor.position_m;
    double length = span.norm();
    if (!(length > 1e-12)) continue;
    linear.direction = span / length;
    linear.length_m = length;
    linear.rest_length_m = anchor.rest_length_m;
    Vec3 known = -anchor.velocity_m_s;
    add_spring(system, linear, dt_s, &known);
  }
}

/// Brings hair segment i's tip side `tip_side` back within max_stretch of its rest length
/// from the segment's start, along the segment.
void limit_segment(const AltitudeStrand& strand, const StrandMaterial& material,
                   const std::vector<Vec3>& x, int32_t i, Vec3& tip_side) {
  Vec3 span = tip_side - x[static_cast<size_t>(strand.hair_particle[static_cast<size_t>(i)])];
  double length = span.norm();
  double rest = strand.hair_segment_m[static_cast<size_t>(i)];
  double limited =
      std::clamp(length, rest * (1 - material.max_stretch), rest * (1 + material.max_stretch));
  if (limited != length && length > 1e-12) tip_side += span * (limited / length - 1);
}

/// Moves the free ghosts within hair segment i by half its tip particle's move
/// `correction`.
void move_ghosts_within(const AltitudeStrand& strand, std::vector<Vec3>& x, int32_t i,
                        const Vec3& correction) {
  int32_t inner = strand.hair_particle[static_cast<size_t>(i)];
  int32_t outer = strand.hair_particle[static_cast<size_t>(i) + 1];
  for (int32_t q = std::max(inner + 1, strand.kinematic_count); q < outer; ++q)
    x[static_cast<size_t>(q)] += 0.5 * correction;
}

/// Strain limiting from the root out: a hair segment out of bounds is brought back by
/// moving everything beyond it, the ghosts within it by half as much.
void limit_strain(const AltitudeStrand& strand, const StrandMaterial& material,
                  std::vector<Vec3>& x) {
  Vec3 shift = Vec3::Zero();
  for (int32_t i = 0; i + 1 < strand.hair_count(); ++i) {
    int32_t inner = strand.hair_particle[static_cast<size_t>(i)];
    int32_t outer = strand.hair_particle[static_cast<size_t>(i) + 1];
    for (int32_t q = inner + 1; q <= outer; ++q) x[static_cast<size_t>(q)] += shift;
    if (outer < strand.kinematic_count) continue;
    Vec3& tip_side = x[static_cast<size_t>(outer)];
    const Vec3 before = tip_side;
    limit_segment(strand, material, x, i, tip_side);
    move_ghosts_within(strand, x, i, tip_side - before);
    shift += tip_side - before;
  }
}

/// Brings each free ghost's distances to its two hair neighbours (its edge springs)
/// within `max_stretch` of their rest lengths, keeping its angle about their segment.
/// The springs alone do not hold a ghost: linearised along their directions at the start
/// of the step, they let it move across them unopposed, and under a fast head (a violent
/// shake at the default step, any shake at a step of a tenth of a second) ghosts drift
/// metres off their strand while its hair stays within the strain limit.
void limit_ghosts(const AltitudeStrand& strand, const StrandMaterial& material,
                  std::vector<Vec3>& x) {
  const double low = 1 - material.max_stretch, high = 1 + material.max_stretch;
  for (int32_t q = std::max(strand.kinematic_count, 1); q + 1 < strand.particle_count(); ++q) {
    auto k = static_cast<size_t>(q);
    if (!strand.is_ghost[k]) continue;
    // A ghost always lies between two hair particles.
    const Vec3& a = x[k - 1];
    const Vec3& b = x[k + 1];
    // Squared lengths first: most ghosts are within bounds, and cost no square root.
    const double rest_a2 = (strand.rest_m[k] - strand.rest_m[k - 1]).squaredNorm();
    const double rest_b2 = (strand.rest_m[k + 1] - strand.rest_m[k]).squaredNorm();
    const double length_a2 = (x[k] - a).squaredNorm(), length_b2 = (b - x[k]).squaredNorm();
    if (length_a2 >= low * low * rest_a2 && length_a2 <= high * high * rest_a2 &&
        length_b2 >= low * low * rest_b2 && length_b2 <= high * high * rest_b2)
      continue;
    const double rest_a = std::sqrt(rest_a2), rest_b = std::sqrt(rest_b2);
    const double target_a = std::clamp(std::sqrt(length_a2), low * rest_a, high * rest_a);
    const double target_b = std::clamp(std::sqrt(length_b2), low * rest_b, high * rest_b);
    Vec3 axis = b - a;
    const double d = axis.norm();
    if (!(d > 1e-12)) continue;
    axis /= d;
    // The circle of points at target_a from a and target_b from b: its plane's distance t
    // from a along the axis and its radius.
    const double t = (target_a * target_a - target_b * target_b + d * d) / (2 * d);
    const double radius = std::sqrt(std::max(0.0, target_a * target_a - t * t));
    Vec3 across = (x[k] - a) - (x[k] - a).dot(axis) * axis;
    if (!(across.norm() > 1e-12 * d)) {  // on the axis: any direction across it
      Vec3 helper = std::abs(axis.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
      across = axis.cross(helper);
    }
    x[k] = a + t * axis + radius * across.normalized();
  }
}

}  // namespace

double strand_spring_energy(const AltitudeStrand& strand, const StrandMaterial& material,
                            const std::vector<Vec3>& position_m) {
  double energy = 0;
  for_each_spring(strand, material.stiffness_scale, position_m,
                  [&](const LinearSpring& spring) { energy += spring_energy(spring); });
  return energy;
}

double anchor_elastic_energy(const AltitudeStrand& strand, const StrandMaterial& material,
                             const std::vector<Vec3>& position_m,
                             const std::vector<StrandAnchor>& anchors) {
  double energy = 0;
  double anchor_stiffness = material.anchor_stiffness_per_kg * strand.mass_kg[0];
  for (const StrandAnchor& anchor : anchors) {
    double stretch = (position_m[0] - anchor.position_m).norm() - anchor.rest_length_m;
    energy += 0.5 * anchor_stiffness * stretch * stretch;
  }
  return energy;
}

double strand_elastic_energy(const AltitudeStrand& strand, const StrandMaterial& material,
                             const std::vector<Vec3>& position_m,
                             const std::vector<StrandAnchor>& anchors) {
  return strand_spring_energy(strand, material, position_m) +
         anchor_elastic_energy(strand, material, position_m, anchors);
}

double max_hair_strain(const AltitudeStrand& strand, const std::vector<Vec3>& position_m) {
  double worst = 0;
  for (int32_t i = 0; i + 1 < strand.hair_count(); ++i) {
    auto k = static_cast<size_t>(i);
    double length = (position_m[static_cast<size_t>(strand.hair_particle[k + 1])] -
                     position_m[static_cast<size_t>(strand.hair_particle[k])])
                        .norm();
    double strain = length / strand.hair_segment_m[k] - 1;
    if (std::abs(strain) > std::abs(worst)) worst = strain;
  }
  return worst;
}

void StrandStepper::step(const AltitudeStrand& strand, const StrandMaterial& material,
                         const std::vector<Vec3>& acceleration_m_s2,
                         const Vec3& uniform_acceleration_m_s2,
                         const std::vector<StrandAnchor>& anchors, double dt_s, StrandState& state,
                         const StrandCollider* collider, double friction,
                         const Eigen::Matrix3d* support_rotation) {
  const int32_t first_free = strand.kinematic_count;
  const int32_t count = strand.particle_count();
  std::vector<Vec3>& x = state.position_m;
  std::vector<Vec3>& v = state.velocity_m_s;
  profile_.particle_steps += count;
  if (count > first_free) {
    solve_velocities(strand, material, acceleration_m_s2, uniform_acceleration_m_s2, anchors, dt_s,
                     state, support_rotation);
  } else {
    PhaseTimer timer(phase(&SimulationProfile::springs_s));
    start_spring_energy_j_ = strand_spring_energy(strand, material, x);
  }

  // Positions, then two passes over the hair segments from the root out.
  //  1. Strain limiting: a segment out of bounds is brought back by moving everything
  //     beyond it (so the rest of the strand keeps its shape), the ghosts beside it by
  //     half as much. The velocities become (x' - x) / dt: inextensibility is motion.
  //  2. The body (collide_with_body): each hair particle is pushed out, its segment
  //     brought back to length and the two alternated (three rounds), with Coulomb
  //     friction on its displacement along the surface. These moves are geometry, not
  //     motion: they leave the velocities alone, but for the particles that touched, whose
  //     velocity relative to the surface loses its normal part. (Counted as motion, a push
  //     out of the body flings the rest of the strand, and hair on the shoulders never
  //     comes to rest.)
  {
    PhaseTimer timer(phase(&SimulationProfile::limits_s));
    start_.assign(x.begin(), x.end());
    for (int32_t q = 0; q < count; ++q) x[static_cast<size_t>(q)] += dt_s * v[static_cast<size_t>(q)];
    limit_strain(strand, material, x);
    limit_ghosts(strand, material, x);
    for (int32_t q = first_free; q < count; ++q) {
      auto k = static_cast<size_t>(q);
      v[k] = (x[k] - start_[k]) / dt_s;
    }
  }
  if (collider) {
    PhaseTimer timer(phase(&SimulationProfile::collisions_s));
    collide_with_body(strand, material, *collider, friction, dt_s, state);
  }
}

void StrandStepper::solve_velocities(const AltitudeStrand& strand, const StrandMaterial& material,
                                     const std::vector<Vec3>& acceleration_m_s2,
                                     const Vec3& uniform_acceleration_m_s2,
                                     const std::vector<StrandAnchor>& anchors, double dt_s,
                                     StrandState& state,
                                     const Eigen::Matrix3d* support_rotation) {
  const int32_t first_free = strand.kinematic_count;
  const int32_t count = strand.particle_count();
  const int n = 3 * (count - first_free);
  const std::vector<Vec3>& x = state.position_m;
  std::vector<Vec3>& v = state.velocity_m_s;
  {
    PhaseTimer timer(phase(&SimulationProfile::springs_s));
    BandSystem::reset(band_, rhs_, count, first_free);
    BandSystem system(band_, rhs_, first_free);
    add_inertia(system, strand, material, acceleration_m_s2, uniform_acceleration_m_s2, dt_s, v,
                support_rotation);
    start_spring_energy_j_ = add_springs(system, strand, material, dt_s, x, v);
    if (first_free == 0) add_anchor_springs(system, strand, material, anchors, dt_s, x);
  }
  PhaseTimer timer(phase(&SimulationProfile::solve_s));
  int info = solve_banded_spd(band_, rhs_, n, kBandwidth);
  if (info != 0)
    throw std::runtime_error("strand step: band matrix not positive definite (minor " +
                             std::to_string(info) + ")");
  for (int32_t q = first_free; q < count; ++q) {
    int row0 = 3 * (q - first_free);
    v[static_cast<size_t>(q)] =
        Vec3(rhs_[static_cast<size_t>(row0)], rhs_[static_cast<size_t>(row0 + 1)],
             rhs_[static_cast<size_t>(row0 + 2)]);
  }
}

void StrandStepper::collide_with_body(const AltitudeStrand& strand, const StrandMaterial& material,
                                      const StrandCollider& collider, double friction, double dt_s,
                                      StrandState& state) {
  const int32_t first_free = strand.kinematic_count;
  const int32_t count = strand.particle_count();
  std::vector<Vec3>& x = state.position_m;
  std::vector<Vec3>& v = state.velocity_m_s;
  const std::vector<Vec3>& start = start_;
  after_limits_.assign(x.begin(), x.end());
  contacts_.clear();
  Vec3 shift = Vec3::Zero();
  for (int32_t i = 0; i + 1 < strand.hair_count(); ++i) {
    int32_t inner = strand.hair_particle[static_cast<size_t>(i)];
    int32_t outer = strand.hair_particle[static_cast<size_t>(i) + 1];
    for (int32_t q = inner + 1; q <= outer; ++q) x[static_cast<size_t>(q)] += shift;
    if (outer < first_free) continue;
    Vec3& tip_side = x[static_cast<size_t>(outer)];
    const Vec3 before = tip_side;
    Contact contact{outer, Vec3::Zero(), Vec3::Zero(), 0};
    bool touched = false;
    for (int round = 0; round < 3; ++round) {
      if (round > 0) limit_segment(strand, material, x, i, tip_side);
      Vec3 moved = tip_side;
      if (!collider.collide(moved, start[static_cast<size_t>(outer)], contact.normal,
                            contact.surface_velocity_m_s))
        break;
      contact.moved_m += (moved - tip_side).norm();
      tip_side = moved;
      touched = true;
    }
    if (touched) {
      // Friction on the step's displacement along the surface, relative to the body:
      // held where it was under friction times the push, slowed by that otherwise.
      Vec3 slide =
          tip_side - start[static_cast<size_t>(outer)] - dt_s * contact.surface_velocity_m_s;
      slide -= slide.dot(contact.normal) * contact.normal;
      double length = slide.norm(), grip = friction * contact.moved_m;
      tip_side -= length <= grip ? slide : Vec3(slide * (grip / length));
      // Where the body and the length still disagree (a body part sweeping through the
      // hair faster than a step resolves), the length wins: a particle left inside for
      // a step is hidden by the body, a stretched strand is not.
      limit_segment(strand, material, x, i, tip_side);
      contacts_.push_back(contact);
    }
    move_ghosts_within(strand, x, i, tip_side - before);
    shift += tip_side - before;
  }
  if (!contacts_.empty()) limit_ghosts(strand, material, x);  // else nothing moved
  // A particle the body's moves held back (it, or the strand before it, touched) loses
  // the part of its velocity they opposed: it is stopped, not thrown back.
  for (int32_t q = first_free; q < count; ++q) {
    auto k = static_cast<size_t>(q);
    Vec3 held = x[k] - after_limits_[k];
    double norm = held.norm();
    if (!(norm > 1e-12)) continue;
    Vec3 direction = held / norm;
    double against = v[k].dot(direction);
    if (against < 0) v[k] -= against * direction;
  }
  for (const Contact& contact : contacts_) {
    auto k = static_cast<size_t>(contact.particle);
    Vec3 relative = (x[k] - start[k]) / dt_s - contact.surface_velocity_m_s;
    relative -= relative.dot(contact.normal) * contact.normal;
    v[k] = contact.surface_velocity_m_s + relative;
  }
}

}  // namespace hair
