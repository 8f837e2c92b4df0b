#include "hair/h5/tree.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hair/h5/attribute.h"
#include "hair/h5/dataset_blocks.h"
#include "hair/h5/enum_dataset.h"

namespace hair::h5 {

namespace {

NumericSummary numeric_summary(const File& file, const std::string& path) {
  NumericSummary summary;
  summary.min = std::numeric_limits<double>::infinity();
  summary.max = -std::numeric_limits<double>::infinity();
  for_each_block<double>(file, path, [&](int64_t, std::span<const double> values) {
    for (const double value : values) {
      if (!std::isfinite(value)) {
        ++summary.non_finite;
        continue;
      }
      ++summary.finite;
      summary.min = std::min(summary.min, value);
      summary.max = std::max(summary.max, value);
    }
    return true;
  });
  if (summary.finite == 0) summary.min = summary.max = 0;
  return summary;
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
      entry.summary = numeric_summary(file, path);
    }
  }
  entries.push_back(std::move(entry));
  if (entries.back().kind != ObjectKind::group) return;
  for (const std::string& name : file.member_names(path)) {
    list_object(file, child_path(path, name), with_summaries, entries);
  }
}

}  // namespace

std::vector<TreeEntry> list_tree(const File& file, bool with_summaries) {
  std::vector<TreeEntry> entries;
  list_object(file, "/", with_summaries, entries);
  return entries;
}

}  // namespace hair::h5
