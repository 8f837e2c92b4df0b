#pragma once

#include <string_view>
#include <vector>

namespace hair::h5 {

/// One schema file of schemas/, compiled into the binary.
struct EmbeddedSchema {
  std::string_view file_name;  ///< e.g. "extract.json"
  std::string_view json_text;  ///< the file's contents
};

/// Every schema of schemas/ at build time, in directory order.
const std::vector<EmbeddedSchema>& embedded_schemas();

}  // namespace hair::h5
