#include "hair/core/stage_app.h"

#include <fmt/format.h>
#include <omp.h>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <cstdlib>
#include <new>
#include <string_view>
#include <utility>
#include <vector>

#include "hair/core/error.h"
#include "hair/core/log.h"

namespace hair {
namespace {

bool has_argument(int argc, const char* const* argv, std::string_view wanted) {
  for (int index = 1; index < argc; ++index) {
    if (argv[index] == wanted) return true;
  }
  return false;
}

/// The options of `app` and of its option groups.
std::vector<CLI::Option*> all_options(CLI::App& app) {
  std::vector<CLI::Option*> options = app.get_options();
  for (CLI::App* group :
       app.get_subcommands([](CLI::App* sub) { return sub->get_name().empty(); })) {
    for (CLI::Option* option : group->get_options()) options.push_back(option);
  }
  return options;
}

}  // namespace

StageApp::StageApp(std::string stage_name, const std::string& description)
    : stage_name_(std::move(stage_name)), app_(description, stage_name_), params_(app_) {
  app_.add_option("-o,--output", output_path_, "Output file")->required();
  params_option_ = app_.set_config("--params", "",
                                   "Parameter file of this stage (TOML); parameters given on "
                                   "the command line override it");
  params_option_->type_name("FILE.toml");
  app_.add_flag("--print-params", print_params_,
                "Print the effective parameters as TOML to stdout and exit without running "
                "(writes a default parameter file)");
  CLI::Option* quiet = app_.add_flag("--quiet", quiet_, "Warnings and errors only, no progress");
  CLI::Option* verbose = app_.add_flag("--verbose", verbose_, "Debug messages too");
  quiet->excludes(verbose);
  app_.add_flag("--reproducible", reproducible_,
                "Leave the date and the wall time out of provenance, so that reruns give "
                "identical files");
  app_.add_option("--threads", threads_, "OpenMP threads, 0 = all (inside a Slurm job: its SLURM_CPUS_PER_TASK)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
}

double StageApp::elapsed_s() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void StageApp::report_error(const std::string& reason) const {
  spdlog::error("{}", error_line("", "", reason));
}

void StageApp::forbid_non_parameters_in_file() {
  for (CLI::Option* option : all_options(app_)) {
    if (!params_.owns(option)) option->configurable(false);
  }
}

int StageApp::parse(int argc, const char* const* argv) {
  forbid_non_parameters_in_file();
  // --print-params only reads parameters: inputs and -o may be left out.
  if (has_argument(argc, argv, "--print-params")) {
    for (CLI::Option* option : all_options(app_)) option->required(false);
  }
  try {
    app_.parse(argc, argv);
  } catch (const CLI::Success& success) {
    return app_.exit(success);  // --help: usage on stdout, exit 0
  } catch (const CLI::ParseError& parse_error) {
    const auto& given = params_option_->results();
    report_error(parameter_file_error_line(parse_error, given.empty() ? "" : given.front()));
    return 2;
  } catch (const Error& error) {  // a parameter value the ParamSet refused
    report_error(error.what());
    return error.exit_code();
  }
  const auto& given = params_option_->results();
  params_path_ = given.empty() ? "" : given.front();
  try {
    params_.check();
  } catch (const Error& error) {
    report_error(error.what());
    return error.exit_code();
  }
  if (print_params_) {
    const std::string text = fmt::format(
        "# Parameters of stage {}: pass this file with --params; parameters on the "
        "command line override it.\n\n{}",
        stage_name_, params_.effective_toml());
    std::fwrite(text.data(), 1, text.size(), stdout);
    std::fflush(stdout);
    return 0;
  }
  return -1;
}

int slurm_cpus_per_task() {
  const char* text = std::getenv("SLURM_CPUS_PER_TASK");
  if (!text || !*text) return 0;
  char* end = nullptr;
  const long cpus = std::strtol(text, &end, 10);
  return end && *end == '\0' && cpus > 0 && cpus < 100000 ? static_cast<int>(cpus) : 0;
}

int StageApp::run(int argc, const char* const* argv, const std::function<void()>& body) {
  start_ = std::chrono::steady_clock::now();
  log::init(stage_name_, log::Verbosity::normal);  // parse errors are reported through it
  if (const int status = parse(argc, argv); status >= 0) return status;

  log::init(stage_name_, quiet_     ? log::Verbosity::quiet
                         : verbose_ ? log::Verbosity::verbose
                                    : log::Verbosity::normal);
  if (threads_ > 0) {
    omp_set_num_threads(threads_);
  } else if (const int slurm_cpus = slurm_cpus_per_task(); slurm_cpus > 0) {
    // "All cores" inside a Slurm job means the CPUs the job was given, not the node's.
    omp_set_num_threads(slurm_cpus);
  }
  spdlog::debug("parameters: {}", params_.effective_json().dump());
  spdlog::debug("OpenMP threads: {}", omp_get_max_threads());

  try {
    body();
  } catch (const Error& error) {
    report_error(error.what());
    return error.exit_code();
  } catch (const std::bad_alloc&) {
    report_error("out of memory");
    return 1;
  } catch (const std::exception& exception) {
    report_error(exception.what());
    return 1;
  }
  return 0;
}

}  // namespace hair
