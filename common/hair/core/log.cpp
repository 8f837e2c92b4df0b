#include "hair/core/log.h"

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <memory>

namespace hair::log {

void init(const std::string& stage_name, Verbosity verbosity) {
  // Not created through the registry's factory, so that init may be called again
  // with the same name; set_default_logger replaces the previous one.
  auto logger = std::make_shared<spdlog::logger>(
      stage_name, std::make_shared<spdlog::sinks::stderr_color_sink_mt>());
  // %n: logger (stage) name, %l: level, %^...%$: coloured range on a terminal.
  logger->set_pattern("%n: %^%l%$: %v");
  switch (verbosity) {
    case Verbosity::quiet:
      logger->set_level(spdlog::level::warn);
      break;
    case Verbosity::normal:
      logger->set_level(spdlog::level::info);
      break;
    case Verbosity::verbose:
      logger->set_level(spdlog::level::debug);
      break;
  }
  spdlog::set_default_logger(std::move(logger));
}

}  // namespace hair::log
