#pragma once

#include <string>

#include "hair/core/params.h"
#include "hair/sim/hair_simulation.h"

namespace hair {

/// The simulate stage's parameters: the simulation's and the head motion preset.
struct SimulateStageParams {
  SimulationParams simulation;
  std::string motion = "shake";  ///< a HeadMotion preset, unless --keyframes is given
};

/// Registers every parameter of the simulate stage in `params`, bound to `values`.
void declare_simulation_params(ParamSet& params, SimulateStageParams& values);

}  // namespace hair
