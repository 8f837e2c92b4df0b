#pragma once
// Time integration of one altitude mass-spring strand (Selle, Lentine and Fedkiw 2008):
// backward Euler with every spring linearised along its direction at the start of the
// step, which makes the step one banded SPD solve per strand (banded_cholesky.h), then
// strain limiting of the hair segments and of the ghosts' edges. The solve is stable
// whatever the stiffness and the time step as a linear system; the strain limiting keeps
// what its linearisation misses (motion across the springs) bounded
// (tests/unit/sim/test_simulation_stress.cpp).

#include <Eigen/Core>
#include <vector>

#include "hair/sim/altitude_strand.h"
#include "hair/sim/hair_fibre.h"
#include "hair/sim/simulation_profile.h"

namespace hair {

/// What a simulated strand is made of and how it moves besides its springs. The
/// springs' constants follow from the fibre and the fibres per strand
/// (StrandStiffness, strand_stiffness.h) and are stored in the AltitudeStrand.
struct StrandMaterial {
  HairFibre fibre;
  /// Hairs a guide strand stands for (a lock): a scalp has about 100,000 (Robbins 2012),
  /// 600 per guide of the paper's 169; 600 hairs of 35 um weigh 3.0 g per metre.
  double fibres_per_strand = 600;
  /// How much a lock's hairs hold together in bending and twist, from 0 (free to slide on
  /// one another: the lock bends with N E I) to 1 (bonded into one bundle: N^2 E I); see
  /// StrandStiffness and docs/simulate.md.
  double lock_cohesion = 0.3;
  /// The hair segments' springs vibrate at this (a numerical stiffness: the strain limit
  /// keeps the hair's length; see StrandStiffness::assign()). 318 Hz: 4e6 / s^2.
  double stretch_frequency_hz = 318.3;
  /// Expert override: every spring constant times this (damping kept at its fraction of
  /// critical); 1 is the hair's own. For stress tests.
  double stiffness_scale = 1;
  double anchor_stiffness_per_kg = 4e5;  ///< 1/s^2, springs from a wisp to its anchors
  double damping_ratio = 0.3;            ///< of each spring, a fraction of critical
  double drag_per_s = 2.0;               ///< air drag, velocity lost per second
  double max_stretch = 0.01;             ///< hair segments kept within this strain
};

/// Positions and velocities of a strand's particles (its whole sequence, ghosts too).
struct StrandState {
  std::vector<Eigen::Vector3d> position_m;
  std::vector<Eigen::Vector3d> velocity_m_s;
};

/// A spring from a point moved by the head (the end of a hair that leads into a braid)
/// to particle 0 of a wisp's centre strand.
struct StrandAnchor {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();    ///< at the start of the step
  Eigen::Vector3d velocity_m_s = Eigen::Vector3d::Zero();  ///< over the step
  double rest_length_m = 0;
};

/// The elastic energy of the strand's springs at `position_m`: sum of k (l - L)^2 / 2
/// over two-particle springs, the altitude of each tetrahedron (the most robust one)
/// and the anchors, joules: strand_spring_energy() + anchor_elastic_energy().
double strand_elastic_energy(const AltitudeStrand& strand, const StrandMaterial& material,
                             const std::vector<Eigen::Vector3d>& position_m,
                             const std::vector<StrandAnchor>& anchors);

/// The part of strand_elastic_energy() in the strand's own springs (anchors excluded),
/// joules; what StrandStepper::start_spring_energy_j() reports of a step's start.
double strand_spring_energy(const AltitudeStrand& strand, const StrandMaterial& material,
                            const std::vector<Eigen::Vector3d>& position_m);

/// The part of strand_elastic_energy() in the springs to the anchors, joules.
double anchor_elastic_energy(const AltitudeStrand& strand, const StrandMaterial& material,
                             const std::vector<Eigen::Vector3d>& position_m,
                             const std::vector<StrandAnchor>& anchors);

/// Keeps particles out of a body: called for each hair particle, root to tip, as the
/// strand's segments are brought back to length, so that the rest of the strand follows
/// a particle that a collision moved.
class StrandCollider {
 public:
  virtual ~StrandCollider() = default;
  /// Moves `position_m` out of the body if it is inside (or nearer than a clearance);
  /// returns whether it did, with the outward unit normal and the velocity of the body's
  /// surface there. `start_m` is where the particle was at the start of the step (outside),
  /// for a particle that went too deep to find its way out.
  virtual bool collide(Eigen::Vector3d& position_m, const Eigen::Vector3d& start_m,
                       Eigen::Vector3d& normal, Eigen::Vector3d& surface_velocity_m_s) const = 0;
};

/// Advances strands by one time step. Holds the band matrix between calls, so one per
/// thread, reused, allocates nothing once warm.
class StrandStepper {
 public:
  /// One step of dt_s. On entry `state` holds the positions at the start of the step and
  /// the velocities; the kinematic particles' velocities must already be those that take
  /// them where the head puts them at the end of the step. `acceleration_m_s2` is added to
  /// every particle's (gravity, hair-hair repulsion; size particle_count(), or empty for
  /// `uniform_acceleration_m_s2` alone). The strand's rest support forces
  /// (strand.rest_support_n, if any) act on their particles turned by `support_rotation`
  /// (the head's rotation; none: as they are). Each step:
  ///   (M + dt sum_s (c_s + dt k_s) J_s^T J_s) v' = M v + dt f_ext - dt sum_s k_s (l_s - L_s) J_s^T
  ///   x' = x + dt v'
  /// where J_s is spring s's length as a linear form of the positions along its current
  /// direction (two-particle springs, the altitude of each tetrahedron with the most
  /// robust normal, the anchors) and c_s its damping. Then hair segments longer or
  /// shorter than max_stretch allows are brought back, from the root out, moving the
  /// particle farther from the root and everything beyond it; each free ghost is brought
  /// to within max_stretch of its rest distances from its two hair neighbours, keeping
  /// its angle about their segment (the linearised springs alone let ghosts slide across
  /// them, and under fast head motion drift far off the strand); and the velocities
  /// become (x' - x) / dt. Then, with `collider`, each hair particle is pushed out of the body,
  /// alternating with its segment's length limit, and keeps its step's displacement along
  /// the surface (relative to the body) only beyond `friction` times the push, less that
  /// (Coulomb friction on positions, so hair lying on the body comes to rest); the rest
  /// of the strand follows, and the ghosts are limited again. These moves add no velocity: a
  /// particle they moved loses the part of its velocity against the move, and one that touched the
  /// body the normal part of its velocity relative to the surface. Throws std::runtime_error if the
  /// band matrix is not positive definite (it always is for positive masses and time step).
  void step(const AltitudeStrand& strand, const StrandMaterial& material,
            const std::vector<Eigen::Vector3d>& acceleration_m_s2,
            const Eigen::Vector3d& uniform_acceleration_m_s2,
            const std::vector<StrandAnchor>& anchors, double dt_s, StrandState& state,
            const StrandCollider* collider = nullptr, double friction = 0,
            const Eigen::Matrix3d* support_rotation = nullptr);

  /// strand_spring_energy() at the positions the last step() started from, bit for bit:
  /// the step evaluates every spring there, so the energy costs it one multiply-add per
  /// spring (a simulation reads a frame's end state's energy off the next frame's first
  /// step instead of evaluating the springs again).
  double start_spring_energy_j() const { return start_spring_energy_j_; }

  /// Time this stepper's steps spent in each of their phases, and the particle-steps
  /// (springs_s, solve_s, limits_s, collisions_s, particle_steps; the rest is the caller's).
  SimulationProfile& profile() { return profile_; }
  /// Whether the steps time their phases (else they count particle-steps only).
  void time_phases(bool on) { timed_ = on ? &profile_ : nullptr; }
  /// `seconds` of this stepper's profile where the phases are timed, else none.
  double* phase(double SimulationProfile::*seconds) {
    return timed_ ? &(timed_->*seconds) : nullptr;
  }

 private:
  /// The implicit system of the step over the free particles, solved: their velocities.
  void solve_velocities(const AltitudeStrand& strand, const StrandMaterial& material,
                        const std::vector<Eigen::Vector3d>& acceleration_m_s2,
                        const Eigen::Vector3d& uniform_acceleration_m_s2,
                        const std::vector<StrandAnchor>& anchors, double dt_s,
                        StrandState& state, const Eigen::Matrix3d* support_rotation);
  /// The body's pass over the hair segments after the strain limiting (see step()).
  void collide_with_body(const AltitudeStrand& strand, const StrandMaterial& material,
                         const StrandCollider& collider, double friction, double dt_s,
                         StrandState& state);

  double start_spring_energy_j_ = 0;
  SimulationProfile profile_;
  SimulationProfile* timed_ = nullptr;  ///< &profile_ where the phases are timed
  std::vector<double> band_;  ///< LAPACK upper band storage, column-major
  std::vector<double> rhs_;
  std::vector<Eigen::Vector3d> start_;         ///< positions at the start of the step
  std::vector<Eigen::Vector3d> after_limits_;  ///< positions after the strain limiting
  /// Contacts of this step: particle, normal, surface velocity, distance moved.
  struct Contact {
    int32_t particle;
    Eigen::Vector3d normal, surface_velocity_m_s;
    double moved_m;
  };
  std::vector<Contact> contacts_;
};

/// Spring (the hair segment from hair particle i to i + 1) strain: |x_i+1 - x_i| / L_i - 1,
/// the largest over the strand's hair segments in absolute value, signed.
double max_hair_strain(const AltitudeStrand& strand,
                       const std::vector<Eigen::Vector3d>& position_m);

}  // namespace hair
