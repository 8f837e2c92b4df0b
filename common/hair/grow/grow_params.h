#pragma once

#include "hair/core/params.h"
#include "hair/grow/strand_growing.h"

namespace hair {

/// Registers every grow parameter with its description and range, bound to `params`.
void declare_grow_params(ParamSet& p, GrowParams& params);

/// Holds `params` to the ranges declare_grow_params() gives them (check_params());
/// grow_strands() calls it. Throws hair::Error (usage) naming the first bad value.
void check_grow_params(const GrowParams& params);

}  // namespace hair
