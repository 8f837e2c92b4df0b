#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "hair/h5/file.h"

namespace hair::h5 {

/// What hair-inspect reports about a file.
struct InspectReport {
  /// The tree with value ranges, the provenance if the file has any, and a last line
  /// "valid: hairstyle.extract v1" or "invalid: <first violation>" when validated.
  std::string text;
  /// The first violation of the file's schema; unset if valid or not validated.
  std::optional<std::string> violation;
};

/// Lists `file`, shows its provenance and, with `validate`, checks it against the schema
/// it names (or `schema_name`, which it must then name). An unknown `schema_name` is a
/// usage error.
InspectReport inspect_report(const File& file, bool validate, std::string_view schema_name = {});

}  // namespace hair::h5
