#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "hair/core/error.h"
#include "hair/h5/file.h"
#include "hair/h5/schema.h"

namespace hair::h5 {

// Checking files against their schema (schemas/README.md, "Validation"). Readers call
// require_schema() when they open an input (DESIGN.md, contract 2); writers stamp their
// output with write_schema_attributes() and call require_valid_output() on the
// temporary file before the atomic rename.

/// The first violation of `schema` by `file`, as a bad_input Error naming the file and
/// the dataset or attribute ("extract.h5:/strands/points: expected float32, found
/// float64"), or nothing if the file conforms. Checks, in this order: the `schema` and
/// `schema_version` attributes, the root attributes, every dataset's presence, dtype and
/// shape (binding dimensions on first use), then every dataset's values.
std::optional<Error> first_violation(const File& file, const Schema& schema);

/// Validates `file` against the compiled-in schema named by its `schema` attribute (or
/// `expected_schema` if given, which the file must then name). Returns the first
/// violation as one line, or nothing if the file conforms; a missing or unknown schema,
/// or another schema version, is a violation too.
std::optional<std::string> validate_file(const File& file, std::string_view expected_schema = {});

/// Throws the first violation (bad_input, exit 2) unless `file` conforms to the
/// compiled-in schema `expected_schema`. Stages call this on every input they open.
void require_schema(const File& file, std::string_view expected_schema);

/// Writes the root attributes `schema` (the name) and `schema_version`.
void write_schema_attributes(File& file, const Schema& schema);

/// Throws a runtime error (exit 1: the writer has a bug) carrying the first violation
/// unless `file` conforms to the compiled-in schema `schema_name`.
void require_valid_output(const File& file, std::string_view schema_name);

}  // namespace hair::h5
