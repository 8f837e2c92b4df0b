#include "hair/core/progress.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <iostream>
#include <utility>

namespace hair {
namespace {

using Clock = ProgressOutput::Clock;

/// Work shorter than this prints nothing.
constexpr std::chrono::nanoseconds kSilentDuration = std::chrono::seconds(1);
/// At most 5 redraws a second.
constexpr std::chrono::nanoseconds kRedrawInterval = std::chrono::milliseconds(200);

double seconds(Clock::duration duration) { return std::chrono::duration<double>(duration).count(); }

}  // namespace

ProgressOutput ProgressOutput::standard_error() {
  ProgressOutput output;
  output.stream = &std::cerr;
  output.is_terminal = isatty(fileno(stderr)) != 0;
  const auto logger = spdlog::default_logger();
  output.enabled = logger->should_log(spdlog::level::info);
  if (!logger->name().empty()) output.line_prefix = logger->name() + ": ";
  return output;
}

Progress::Progress(std::string label, int64_t total_units, ProgressOutput output)
    : label_(std::move(label)),
      total_units_(total_units),
      output_(std::move(output)),
      start_(output_.now()),
      next_draw_ns_(kSilentDuration.count()) {}

Progress::~Progress() {
  if (std::uncaught_exceptions() == 0) {
    finish();
    return;
  }
  std::lock_guard lock(draw_mutex_);
  if (drawn_line_length_ > 0) *output_.stream << "\n" << std::flush;
}

void Progress::advance(int64_t units) {
  const int64_t done_units = done_units_.fetch_add(units, std::memory_order_relaxed) + units;
  if (!output_.enabled) return;
  const Clock::duration elapsed = output_.now() - start_;
  const int64_t elapsed_ns = std::chrono::nanoseconds(elapsed).count();
  if (elapsed_ns < next_draw_ns_.load(std::memory_order_relaxed)) return;
  std::unique_lock lock(draw_mutex_, std::try_to_lock);
  if (!lock.owns_lock() || finished_) return;  // another thread is drawing
  if (elapsed_ns < next_draw_ns_.load(std::memory_order_relaxed)) return;
  next_draw_ns_.store(elapsed_ns + kRedrawInterval.count(), std::memory_order_relaxed);
  draw(done_units, elapsed, false);
}

void Progress::finish() {
  std::lock_guard lock(draw_mutex_);
  if (finished_) return;
  finished_ = true;
  if (!output_.enabled) return;
  const Clock::duration elapsed = output_.now() - start_;
  if (printed_ || elapsed >= kSilentDuration) {
    draw(done_units_.load(std::memory_order_relaxed), elapsed, true);
  }
}

std::string Progress::report_line(int64_t done_units) const {
  const int64_t percent =
      total_units_ > 0 ? std::clamp<int64_t>(done_units * 100 / total_units_, 0, 100) : 100;
  return fmt::format("{}{}: {}% ({}/{})", output_.line_prefix, label_, percent, done_units,
                     total_units_);
}

void Progress::draw(int64_t done_units, Clock::duration elapsed, bool final) {
  std::string line = report_line(done_units);
  if (final) line += fmt::format(" in {:.1f} s", seconds(elapsed));
  if (output_.is_terminal) {
    // Pad with spaces to wipe the rest of a longer line drawn before.
    const size_t padding = drawn_line_length_ > line.size() ? drawn_line_length_ - line.size() : 0;
    *output_.stream << "\r" << line << std::string(padding, ' ') << (final ? "\n" : "")
                    << std::flush;
    drawn_line_length_ = final ? 0 : line.size();
    printed_ = true;
    return;
  }
  const int tenth =
      total_units_ > 0
          ? static_cast<int>(std::clamp<int64_t>(done_units * 10 / total_units_, 0, 10))
          : 10;
  if (final || tenth > last_tenth_printed_) {
    *output_.stream << line << "\n" << std::flush;
    last_tenth_printed_ = tenth;
    printed_ = true;
  }
}

}  // namespace hair
