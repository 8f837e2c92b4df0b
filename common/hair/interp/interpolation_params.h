#pragma once

#include "hair/core/params.h"
#include "hair/interp/strand_interpolation.h"

namespace hair {

/// Registers every interpolate parameter with its description and range, bound to `params`.
void declare_interpolation_params(ParamSet& p, InterpolationParams& params);

/// Holds `params` to the ranges declare_interpolation_params() gives them (check_params());
/// bind_strands() calls it. Throws hair::Error (usage).
void check_interpolation_params(const InterpolationParams& params);

}  // namespace hair
