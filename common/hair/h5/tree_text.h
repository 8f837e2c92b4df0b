#pragma once

#include <string>
#include <vector>

#include "hair/h5/tree.h"

namespace hair::h5 {

/// Longest attribute value shown whole by format_tree(); longer ones are cut.
inline constexpr size_t kAttributeTextLimit = 72;

/// A file's tree as text, one line per group or dataset (path, dtype, shape, storage,
/// summary) followed by its attributes indented, e.g.
///   /strands/points  float32 [5000, 3]  chunked [10922, 3] shuffle deflate(4)  range
///   [-0.2, 1.8]  by column [-0.2, 0.2] [1.4, 1.8] [-0.1, 0.2]
///       @scale (float64) = 0.1
std::string format_tree(const std::vector<TreeEntry>& entries);

}  // namespace hair::h5
