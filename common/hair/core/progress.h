#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <mutex>
#include <string>

namespace hair {

/// Where and how a Progress reports (DESIGN.md, contract 7).
struct ProgressOutput {
  using Clock = std::chrono::steady_clock;

  std::ostream* stream = nullptr;  ///< where lines go
  bool is_terminal = false;        ///< redraw one line with '\r' instead of printing lines
  bool enabled = true;             ///< false with --quiet
  std::string line_prefix;         ///< e.g. "extract: ", so parallel stages can be told apart
  std::function<Clock::time_point()> now = Clock::now;  ///< tests inject their own clock

  /// stderr; a terminal if stderr is one; enabled if spdlog's default logger logs info;
  /// prefixed with that logger's name (the stage name after hair::log::init).
  static ProgressOutput standard_error();
};

/// Progress of a long loop on stderr: `extract: growing strands: 45% (450/1000)`.
///
/// Nothing is printed for work that ends within a second. After that, on a terminal the
/// line is redrawn in place at most 5 times a second; elsewhere (logs, make -j) a line is
/// printed each time another tenth of the work is done. finish() prints the final line
/// with the elapsed time if anything was, or the work lasted over a second.
///
/// advance() is thread-safe and cheap (an atomic add and a clock read), so it can be called
/// from inside an OpenMP loop once per item.
class Progress {
 public:
  Progress(std::string label, int64_t total_units,
           ProgressOutput output = ProgressOutput::standard_error());
  /// Finishes if finish() was not called, unless an exception is unwinding the stack
  /// (then only ends a half-drawn terminal line).
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// Records `units` more units of work done.
  void advance(int64_t units = 1);

  /// Ends the report; later calls do nothing.
  void finish();

 private:
  /// Writes the report of `done_units` after `elapsed`; the caller holds draw_mutex_.
  void draw(int64_t done_units, ProgressOutput::Clock::duration elapsed, bool final);
  std::string report_line(int64_t done_units) const;

  std::string label_;
  int64_t total_units_;
  ProgressOutput output_;
  ProgressOutput::Clock::time_point start_;

  std::atomic<int64_t> done_units_{0};
  std::atomic<int64_t> next_draw_ns_;  ///< since start_; no drawing before it

  std::mutex draw_mutex_;
  int last_tenth_printed_ = 0;    ///< lines mode: tenths of the work already reported
  size_t drawn_line_length_ = 0;  ///< terminal mode: length of the line on screen, 0 if none
  bool printed_ = false;
  bool finished_ = false;
};

}  // namespace hair
