#include "hair/style/style_labels.h"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <map>
#include <utility>

#include "hair/core/error.h"

namespace hair {
namespace {

constexpr std::string_view kHeader = "model\tfirst_face\tstyle";

/// The tab-separated fields of a line.
std::vector<std::string_view> split_tabs(std::string_view line) {
  std::vector<std::string_view> fields;
  size_t start = 0;
  for (size_t tab = line.find('\t'); tab != std::string_view::npos; tab = line.find('\t', start)) {
    fields.push_back(line.substr(start, tab - start));
    start = tab + 1;
  }
  fields.push_back(line.substr(start));
  return fields;
}

/// A non-negative decimal integer filling the whole field; none otherwise.
std::optional<int64_t> parse_face(std::string_view field) {
  int64_t value = 0;
  auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (error != std::errc() || end != field.data() + field.size() || value < 0) return std::nullopt;
  return value;
}

}  // namespace

std::optional<int8_t> style_code(std::string_view word) {
  for (size_t code = 0; code < kStyleWords.size(); ++code)
    if (kStyleWords[code] == word) return static_cast<int8_t>(code);
  return std::nullopt;
}

std::vector<PatchStyleLabel> read_patch_style_labels(const std::filesystem::path& tsv) {
  const std::string file = tsv.string();
  std::ifstream in(tsv);
  if (!in) throw Error::bad_input(file, "cannot open the style label table");
  auto fail = [&](int64_t line, const std::string& reason) {
    return Error::bad_dataset(file, "line " + std::to_string(line), reason);
  };

  std::vector<PatchStyleLabel> labels;
  std::map<std::pair<std::string, int64_t>, int64_t> line_of_patch;
  bool header_seen = false;
  int64_t line_number = 0;
  std::string text;
  while (std::getline(in, text)) {
    ++line_number;
    std::string_view line = text;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.empty() || line.front() == '#') continue;
    if (!header_seen) {
      if (line != kHeader)
        throw fail(line_number, "expected the header 'model<TAB>first_face<TAB>style', found '" +
                                    std::string(line) + "'");
      header_seen = true;
      continue;
    }
    std::vector<std::string_view> fields = split_tabs(line);
    if (fields.size() != 3)
      throw fail(line_number, "expected 3 tab-separated fields (model, first_face, style), found " +
                                  std::to_string(fields.size()));
    PatchStyleLabel label;
    label.line = line_number;
    label.model = fields[0];
    if (label.model.empty()) throw fail(line_number, "empty model name");
    std::optional<int64_t> face = parse_face(fields[1]);
    if (!face)
      throw fail(line_number,
                 "first_face '" + std::string(fields[1]) + "' is not a non-negative integer");
    label.first_face = *face;
    std::optional<int8_t> style = style_code(fields[2]);
    if (!style)
      throw fail(line_number, "style '" + std::string(fields[2]) +
                                  "' is not one of normal, fixed, short, braided");
    label.style = *style;
    auto [previous, inserted] =
        line_of_patch.emplace(std::pair{label.model, label.first_face}, line_number);
    if (!inserted)
      throw fail(line_number, label.model + " first face " + std::to_string(label.first_face) +
                                  " is labelled again (first on line " +
                                  std::to_string(previous->second) + ")");
    labels.push_back(std::move(label));
  }
  if (in.bad()) throw Error::runtime(file, "read error");
  if (!header_seen) throw Error::bad_input(file, "no header 'model<TAB>first_face<TAB>style'");
  return labels;
}

std::vector<int8_t> group_styles_from_patch_labels(const std::vector<int32_t>& face_group,
                                                   int32_t group_count,
                                                   const std::vector<PatchStyleLabel>& labels,
                                                   std::string_view model) {
  const std::string name(model);
  // The smallest face of every group, -1 for a group without faces.
  std::vector<int64_t> first_face(static_cast<size_t>(std::max(group_count, 0)), -1);
  for (size_t face = 0; face < face_group.size(); ++face) {
    int32_t group = face_group[face];
    if (group < 0 || group >= group_count)
      throw Error::bad_input(name, "face " + std::to_string(face) + " is in group " +
                                       std::to_string(group) + ", outside [0, " +
                                       std::to_string(group_count) + ")");
    if (first_face[group] < 0) first_face[group] = static_cast<int64_t>(face);
  }
  std::map<int64_t, int32_t> group_of_first_face;
  for (int32_t group = 0; group < group_count; ++group)
    if (first_face[group] >= 0) group_of_first_face.emplace(first_face[group], group);

  std::vector<int8_t> styles(first_face.size(), -1);
  for (const PatchStyleLabel& label : labels) {
    if (label.model != model) continue;
    auto found = group_of_first_face.find(label.first_face);
    if (found == group_of_first_face.end())
      throw Error::bad_input(name, "the style label on line " + std::to_string(label.line) +
                                       " names first face " + std::to_string(label.first_face) +
                                       ", which is not the first face of any patch (has the "
                                       "mesh changed?)");
    styles[found->second] = label.style;
  }
  return styles;
}

}  // namespace hair
