#pragma once

#include "hair/cluster/typeify.h"
#include "hair/core/params.h"

namespace hair {

/// Registers every typeify parameter with its description and range, and the check that
/// the threshold's bounds are in order, bound to `params`.
void declare_typeify_params(ParamSet& p, TypeifyParams& params);

/// Holds `params` to the ranges declare_typeify_params() gives them (check_params());
/// group_types_from_centres() calls it. Throws hair::Error (usage).
void check_typeify_params(const TypeifyParams& params);

}  // namespace hair
