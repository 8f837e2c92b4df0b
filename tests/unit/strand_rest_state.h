#pragma once
// A strand's state at rest, and strands of human hair, for the strand dynamics tests.

#include <Eigen/Core>
#include <vector>

#include "hair/sim/altitude_strand.h"
#include "hair/sim/strand_dynamics.h"
#include "hair/sim/strand_stiffness.h"

namespace hair::testing {

/// Every particle of `strand` at its rest position, at rest.
inline StrandState rest_state(const AltitudeStrand& strand) {
  StrandState state;
  state.position_m = strand.rest_m;
  state.velocity_m_s.assign(strand.rest_m.size(), Eigen::Vector3d::Zero());
  return state;
}

/// The springs of a lock of human hair (the default fibre, fibres per strand, cohesion
/// and damping), once per test binary.
inline const StrandStiffness& human_hair() {
  static const StrandStiffness stiffness{StrandMaterial{}};
  return stiffness;
}

/// A strand of human hair through `points` (root first).
inline AltitudeStrand hair_strand(const std::vector<Eigen::Vector3d>& points) {
  return build_hair_strand(points, human_hair());
}

/// A lock of 600 hairs free to slide on one another (lock cohesion 0): it bends with 600
/// times one hair's E I, the hair's own physics; limp.
inline const StrandStiffness& free_hairs() {
  static const StrandStiffness stiffness = [] {
    StrandMaterial material;
    material.fibres_per_strand = 600;
    material.lock_cohesion = 0;
    return StrandStiffness(material);
  }();
  return stiffness;
}
inline AltitudeStrand free_hair_strand(const std::vector<Eigen::Vector3d>& points) {
  return build_hair_strand(points, free_hairs());
}

}  // namespace hair::testing
