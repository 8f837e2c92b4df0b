#pragma once
// Sag-free rest: a strand's groomed shape made its equilibrium under gravity with the
// head still, as Hsu, Wang, Wu and Yuksel ("Sag-Free Initialization for Strand-Based
// Hybrid Hair Simulation", 2023) ask of a groom. The strand carries along itself what it
// can (the tension of its hair segments, their rest lengths shortened by it); the rest of
// its weight at rest, what a groom leans on the scalp, the hair about it and its styling
// for, is a support force fixed in the head's frame, as their hybrid takes it from its
// grid. The derivation, and why the springs' rest shapes are not bent instead, are in
// docs/simulate.md, "Sag-free rest".

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "hair/sim/altitude_strand.h"
#include "hair/sim/strand_dynamics.h"

namespace hair {

/// What make_sag_free() found.
struct SagFreeReport {
  double weight_n = 0;   ///< of the strand's free particles
  double support_n = 0;  ///< how much of it the support forces hold up (against gravity)
  double largest_tension_strain = 0;  ///< of a hair segment: tension / (its stiffness x length)
};

/// Makes the groom strand.rest_m an equilibrium under `gravity_m_s2` with the kinematic
/// particles held. Walking from the tip to the root, each hair segment takes the tension
/// t = max(0, L . d) of the load L on its outer hair particle (that particle's weight plus
/// the pull of the segment beyond), d the segment's direction: a hanging strand carries
/// its weight along itself. What a hair particle's load leaves over (its part across the
/// strand, and along it where the strand would be pressed together: hair standing up),
/// and every ghost's weight, is its support force, stored in strand.rest_support_n. Each
/// hair segment spring's rest length becomes its groomed length less t / k; every other
/// spring rests in the groom. Then at the groom every free particle's weight, springs and
/// support sum to zero, and the springs hold no stress across the strand (what would
/// make it buckle). Deterministic.
SagFreeReport make_sag_free(AltitudeStrand& strand, const StrandMaterial& material,
                            const Eigen::Vector3d& gravity_m_s2);

/// The net force on each free particle of `strand` at `position_m` from its springs, its
/// support (as stored, unrotated) and `gravity_m_s2` (zero for kinematic particles),
/// newtons.
std::vector<Eigen::Vector3d> strand_static_force(const AltitudeStrand& strand,
                                                 const StrandMaterial& material,
                                                 const std::vector<Eigen::Vector3d>& position_m,
                                                 const Eigen::Vector3d& gravity_m_s2);

}  // namespace hair
