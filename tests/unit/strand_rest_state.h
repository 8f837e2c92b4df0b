#pragma once
// A strand's state at rest, for the strand dynamics tests.

#include <Eigen/Core>

#include "hair/sim/altitude_strand.h"
#include "hair/sim/strand_dynamics.h"

namespace hair::testing {

/// Every particle of `strand` at its rest position, at rest.
inline StrandState rest_state(const AltitudeStrand& strand) {
  StrandState state;
  state.position_m = strand.rest_m;
  state.velocity_m_s.assign(strand.rest_m.size(), Eigen::Vector3d::Zero());
  return state;
}

}  // namespace hair::testing
