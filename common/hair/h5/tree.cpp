#include "hair/h5/tree.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hair/h5/attribute.h"
#include "hair/h5/dataset_blocks.h"
#include "hair/h5/enum_dataset.h"

namespace hair::h5 {

namespace {

/// Fills the summary of a numeric dataset of extents `shape`, and its column summaries
/// if it is a narrow 2-D dataset.
void summarise_numbers(const File& file, const std::string& path, const Shape& shape,
                       TreeEntry& entry) {
  NumericSummary summary;
  const bool by_column = shape.size() == 2 && shape[1] > 0 && shape[1] <= kMaxSummaryColumns;
  std::vector<NumericSummary> columns(by_column ? static_cast<size_t>(shape[1]) : 0);
  for_each_block<double>(file, path, [&](int64_t first, std::span<const double> values) {
    for (size_t offset = 0; offset < values.size(); ++offset) {
      summary.add(values[offset]);
      if (by_column) columns[(first + offset) % columns.size()].add(values[offset]);
    }
    return true;
  });
  entry.summary = summary;
  entry.column_summaries = std::move(columns);
}

std::vector<std::pair<std::string, int64_t>> enum_counts(const File& file,
                                                         const std::string& path) {
  std::vector<std::pair<std::string, int64_t>> counts;
  const EnumMembers members = read_enum_members(file, path);
  for (const EnumMember& member : members) counts.emplace_back(member.name, 0);
  for (const int8_t value : read_enum_values(file, path)) {
    for (size_t index = 0; index < members.size(); ++index) {
      if (members[index].value == value) ++counts[index].second;
    }
  }
  return counts;
}

void list_object(const File& file, const std::string& path, bool with_summaries,
                 std::vector<TreeEntry>& entries) {
  TreeEntry entry;
  entry.path = path;
  entry.kind = file.kind_of(path);
  if (entry.kind == ObjectKind::missing) return;  // a dangling soft or external link
  for (const std::string& name : attribute_names(file, path)) {
    entry.attributes.push_back(
        {name, attribute_type_name(file, path, name), attribute_text(file, path, name)});
  }
  if (entry.kind == ObjectKind::dataset) {
    entry.dataset = dataset_info(file, path);
    if (with_summaries && entry.dataset.type_name == "enum int8") {
      entry.enum_counts = enum_counts(file, path);
    } else if (with_summaries && (entry.dataset.type_name.starts_with("int") ||
                                  entry.dataset.type_name.starts_with("uint") ||
                                  entry.dataset.type_name.starts_with("float"))) {
      summarise_numbers(file, path, entry.dataset.shape, entry);
    }
  }
  entries.push_back(std::move(entry));
  if (entries.back().kind != ObjectKind::group) return;
  for (const std::string& name : file.member_names(path)) {
    list_object(file, child_path(path, name), with_summaries, entries);
  }
}

}  // namespace

void NumericSummary::add(double value) {
  if (!std::isfinite(value)) {
    ++non_finite;
    return;
  }
  ++finite;
  min = std::min(min, value);
  max = std::max(max, value);
}

std::vector<TreeEntry> list_tree(const File& file, bool with_summaries) {
  std::vector<TreeEntry> entries;
  list_object(file, "/", with_summaries, entries);
  return entries;
}

}  // namespace hair::h5
