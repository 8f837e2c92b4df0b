#include "hair/core/frame_range.h"

#include <charconv>

#include "hair/core/error.h"

namespace hair {
namespace {

/// A non-negative integer filling `text`, or -1.
int64_t parse_count(const std::string& text) {
  int64_t value = -1;
  auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < 0) return -1;
  return value;
}

}  // namespace

FrameRange parse_frame_range(const std::string& text, int64_t frame_count,
                             const std::string& option) {
  FrameRange range{0, frame_count};
  auto fail = [&](const std::string& why) {
    return Error::usage(option + " " + text + ": " + why + " (the input has " +
                        std::to_string(frame_count) + " frames, 0 to " +
                        std::to_string(frame_count - 1) + ")");
  };
  size_t colon = text.find(':');
  if (colon == std::string::npos) {
    if (!text.empty()) {
      range.first = parse_count(text);
      if (range.first < 0) throw fail("expected A:B, A:, :B or N");
      range.end = range.first + 1;
    }
  } else {
    std::string first = text.substr(0, colon), end = text.substr(colon + 1);
    if (!first.empty()) range.first = parse_count(first);
    if (!end.empty()) range.end = parse_count(end);
    if (range.first < 0 || range.end < 0) throw fail("expected A:B, A:, :B or N");
  }
  if (range.end > frame_count) throw fail("past the last frame");
  if (range.first >= range.end) throw fail("no frames");
  return range;
}

}  // namespace hair
