#pragma once

#include <string>

#include "hair/h5/schema.h"

namespace hair::h5 {

/// A schema as readable text: name and version, description, history, dimensions, root
/// attributes and datasets with their dtype, shape, unit, constraints and description.
std::string format_schema(const Schema& schema);

}  // namespace hair::h5
