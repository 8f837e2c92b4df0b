#pragma once
// The --frames option of interpolate and the exporters: a range of frames.

#include <cstdint>
#include <string>

namespace hair {

/// Frames first .. end - 1.
struct FrameRange {
  int64_t first = 0;
  int64_t end = 0;
  int64_t count() const { return end - first; }
};

/// Parses `text` against `frame_count` frames: "A:B" is frames A to B - 1 (as Python
/// slices), "A:" from A to the last, ":B" from 0, "N" frame N alone, "" or ":" all.
/// Throws Error::usage naming `option` for text that is not such a range, or a range
/// that is empty or past the last frame.
FrameRange parse_frame_range(const std::string& text, int64_t frame_count,
                             const std::string& option = "--frames");

}  // namespace hair
