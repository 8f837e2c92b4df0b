#include "hair/h5/tree_text.h"

#include <fmt/format.h>

#include <algorithm>

namespace hair::h5 {

namespace {

std::string storage_text(const DatasetInfo& info) {
  if (info.chunk_shape.empty()) return "contiguous";
  std::string text = "chunked " + format_shape(info.chunk_shape);
  for (const std::string& filter : info.filters) text += " " + filter;
  return text;
}

/// "[-1, 2]", or "[]" without finite values.
std::string range_text(const NumericSummary& summary) {
  if (summary.finite == 0) return "[]";
  return fmt::format("[{:.6g}, {:.6g}]", summary.min, summary.max);
}

std::string summary_text(const TreeEntry& entry) {
  std::string text;
  if (entry.summary) {
    if (entry.summary->finite > 0) text = fmt::format("range {}", range_text(*entry.summary));
    if (!entry.column_summaries.empty() && entry.summary->finite > 0) {
      text += "  by column";
      for (const NumericSummary& column : entry.column_summaries) {
        text += fmt::format(" {}", range_text(column));
      }
    }
    if (entry.summary->non_finite > 0) {
      text += fmt::format("{}{} non-finite", text.empty() ? "" : ", ", entry.summary->non_finite);
    }
    return text;
  }
  for (const auto& [name, count] : entry.enum_counts) {
    text += fmt::format("{}{} {}", text.empty() ? "" : ", ", name, count);
  }
  return text;
}

/// The value on one line, cut to kAttributeTextLimit characters.
std::string attribute_value_text(const std::string& text) {
  const size_t line_end = text.find('\n');
  if (line_end == std::string::npos && text.size() <= kAttributeTextLimit) return text;
  return text.substr(0, std::min(line_end, kAttributeTextLimit)) +
         fmt::format("... ({} characters)", text.size());
}

}  // namespace

std::string format_tree(const std::vector<TreeEntry>& entries) {
  size_t path_width = 0;
  for (const TreeEntry& entry : entries) path_width = std::max(path_width, entry.path.size());
  std::string text;
  for (const TreeEntry& entry : entries) {
    std::string description;
    if (entry.kind == ObjectKind::group) {
      description = "group";
    } else if (entry.kind == ObjectKind::dataset) {
      const DatasetInfo& info = entry.dataset;
      description = info.type_name + " " + format_shape(info.shape) + "  " + storage_text(info);
      const std::string summary = summary_text(entry);
      if (!summary.empty()) description += "  " + summary;
    } else {
      description = "other object";
    }
    text += fmt::format("{:<{}}  {}\n", entry.path, path_width, description);
    for (const AttributeEntry& attribute : entry.attributes) {
      text += fmt::format("    @{} ({}) = {}\n", attribute.name, attribute.type_name,
                          attribute_value_text(attribute.text));
    }
  }
  return text;
}

}  // namespace hair::h5
