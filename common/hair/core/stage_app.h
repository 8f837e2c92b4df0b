#pragma once

#include <CLI/CLI.hpp>
#include <chrono>
#include <functional>
#include <string>

#include "hair/core/params.h"

namespace hair {

/// The command-line shell shared by every stage's main.cpp (DESIGN.md, contracts 1 and 7).
///
/// It owns the CLI11 application, the stage's ParamSet and the common options:
///   -o,--output FILE     the output file (required)
///   --params FILE.toml   the stage's parameter file (optional; the command line wins)
///   --print-params       print the effective parameters as TOML to stdout and exit 0
///   --quiet, --verbose   warnings and errors only / debug messages
///   --reproducible       leave the date and the wall time out of provenance
///   --threads N          OpenMP threads, 0 = all
/// A stage adds its positional inputs through cli() and its parameters through params(),
/// then calls run() with the body of the stage.
/// The CPUs a Slurm job step was given (SLURM_CPUS_PER_TASK), or 0 outside one (or for a
/// value that is not a positive whole number). --threads 0 uses them.
int slurm_cpus_per_task();

class StageApp {
 public:
  StageApp(std::string stage_name, const std::string& description);
  StageApp(const StageApp&) = delete;
  StageApp& operator=(const StageApp&) = delete;

  CLI::App& cli() { return app_; }
  ParamSet& params() { return params_; }
  const ParamSet& params() const { return params_; }

  /// Parses the command line and the parameter file, checks the parameters, sets up
  /// logging and OpenMP, runs `body` and returns the exit status:
  ///   0  success, --help, --print-params
  ///   2  a command-line or parameter error, or hair::Error of kind bad_input / usage
  ///   1  hair::Error of kind runtime, std::bad_alloc, any other std::exception
  /// Every failure is reported on stderr as one line `stage: error: reason`.
  int run(int argc, const char* const* argv, const std::function<void()>& body);

  const std::string& stage_name() const { return stage_name_; }
  const std::string& output_path() const { return output_path_; }
  /// The parameter file given with --params, or "" if none.
  const std::string& params_path() const { return params_path_; }
  bool reproducible() const { return reproducible_; }
  /// Seconds since run() started.
  double elapsed_s() const;

 private:
  /// Parses argv; returns the exit status if the stage must not run, -1 if it must.
  int parse(int argc, const char* const* argv);
  /// Options that are not parameters may not be set from the parameter file.
  void forbid_non_parameters_in_file();
  void report_error(const std::string& reason) const;

  std::string stage_name_;
  CLI::App app_;
  ParamSet params_;
  CLI::Option* params_option_ = nullptr;

  std::string output_path_;
  std::string params_path_;
  bool print_params_ = false;
  bool quiet_ = false;
  bool verbose_ = false;
  bool reproducible_ = false;
  int threads_ = 0;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace hair
