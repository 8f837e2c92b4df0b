#pragma once

#include <string>

namespace hair::log {

/// How much a stage says on stderr.
enum class Verbosity {
  quiet,    ///< warnings and errors only (--quiet); no progress
  normal,   ///< info and above
  verbose,  ///< debug and above (--verbose)
};

/// Makes spdlog's default logger write to stderr as `stage: level: message`
/// (e.g. `extract: info: 12 groups`), coloured only on a terminal, at the level that
/// `verbosity` selects. Elsewhere, log with spdlog::info, spdlog::debug, ... directly.
/// May be called again to change the stage name or the verbosity.
void init(const std::string& stage_name, Verbosity verbosity);

}  // namespace hair::log
