#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hair/h5/file.h"

namespace hair {

/// One input file of a stage run.
struct ProvenanceInput {
  std::string role;    ///< what the stage uses it for, e.g. "hair_mesh"
  std::string path;    ///< as given on the command line
  std::string sha256;  ///< content digest, 64 lowercase hex digits
  bool operator==(const ProvenanceInput&) const = default;
};

/// How an output came about (DESIGN.md, contract 3), stored as root attributes:
///   stage, project_version, parameters (JSON text), inputs (JSON text: a list of
///   {"role", "path", "sha256"}), and unless the run was reproducible wall_time_s and
///   created_utc (ISO 8601, e.g. "2024-05-01T12:00:00Z").
struct Provenance {
  std::string stage;
  std::string project_version;
  std::string parameters;  ///< the effective parameters as JSON text
  std::vector<ProvenanceInput> inputs;
  std::optional<double> wall_time_s;       ///< absent in reproducible runs
  std::optional<std::string> created_utc;  ///< absent in reproducible runs
  bool operator==(const Provenance&) const = default;
};

/// The provenance of a run of `stage` in this build: each input (role, path) digested,
/// and with `reproducible` false the wall time and the current UTC time; with it true
/// both are left out so that reruns give identical attributes.
Provenance stage_provenance(
    std::string stage, std::string parameters_json,
    const std::vector<std::pair<std::string, std::filesystem::path>>& inputs, double wall_time_s,
    bool reproducible);

/// Writes the provenance attributes on the root group. Parameters that are not JSON
/// text are a runtime error.
void write_provenance(h5::File& file, const Provenance& provenance);

/// Reads the provenance attributes of the root group; bad_input naming the attribute if
/// one is missing, mistyped or (parameters, inputs) not the JSON expected.
Provenance read_provenance(const h5::File& file);

/// Provenance as indented text for people, parameters pretty-printed.
std::string format_provenance(const Provenance& provenance);

/// The current time in UTC as ISO 8601 to the second: "2024-05-01T12:00:00Z".
std::string utc_timestamp_now();

}  // namespace hair
