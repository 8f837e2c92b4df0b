#include "hair/render/extract_picture.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "hair/cluster/typeify_io.h"
#include "hair/core/error.h"
#include "hair/extract/extract_io.h"
#include "hair/h5/attribute.h"
#include "hair/h5/dataset.h"
#include "hair/h5/schema_validation.h"
#include "hair/h5/strand_set_io.h"
#include "hair/render/style_picture.h"
#include "hair/style/style_labels.h"

namespace hair {
namespace {

/// Distinct colours (BGR) for categories, in the order of their enum values.
const std::vector<cv::Vec3b>& category_colours() {
  static const std::vector<cv::Vec3b> colours = {{180, 119, 31}, {14, 127, 255},  {44, 160, 44},
                                                 {40, 39, 214},  {189, 103, 148}, {75, 86, 140},
                                                 {194, 119, 227}};
  return colours;
}

void draw_legend(cv::Mat& image, const h5::EnumMembers& members,
                 const std::vector<cv::Vec3b>& colours = category_colours()) {
  int y = 44;
  for (const h5::EnumMember& member : members) {
    cv::Vec3b c = colours[static_cast<size_t>(member.value) % colours.size()];
    cv::rectangle(image, cv::Rect(10, y - 10, 14, 10), cv::Scalar(c[0], c[1], c[2]), cv::FILLED);
    cv::putText(image, member.name, cv::Point(30, y), cv::FONT_HERSHEY_SIMPLEX, 0.45,
                cv::Scalar(40, 40, 40), 1, cv::LINE_AA);
    y += 18;
  }
}

/// Spreads a per-group enum to the strands.
std::vector<int32_t> per_strand(const std::vector<int8_t>& per_group,
                                const std::vector<int32_t>& strand_group) {
  std::vector<int32_t> values;
  values.reserve(strand_group.size());
  for (int32_t group : strand_group) values.push_back(per_group[group]);
  return values;
}

/// The input strands coloured by how they run against the painted flow, with a legend
/// that gives the share of judged segments along it.
cv::Mat flow_picture(const h5::File& file, const StrandSet& strands, const ExtractedBody& body,
                     const RenderOptions& options) {
  ExtractedPaint paint = read_extracted_paint(file);
  const double head_height_m = h5::read_double_attribute(file, "/", "head_height_m");
  std::vector<int8_t> along =
      segments_along_painted_flow(paint.mesh, paint.flow, strands, kClearFlowCoherence,
                                  kFlowAgreementAngleDeg, 0.1 * head_height_m);
  // BGR: across red, along green, not judged grey.
  static const std::vector<cv::Vec3b> flow_colours = {{50, 50, 215}, {60, 170, 40}, {170, 170, 170}};
  PointColours colours;
  colours.reserve(along.size());
  int64_t judged = 0, agreeing = 0;
  for (int8_t value : along) {
    colours.push_back(flow_colours[static_cast<size_t>(value < 0 ? 2 : value)]);
    judged += value >= 0;
    agreeing += value == 1;
  }
  cv::Mat image = render_strands(strands, colours, body.vertices, body.triangles, options);
  const std::string share =
      judged ? std::to_string(static_cast<int>(std::lround(100.0 * static_cast<double>(agreeing) /
                                                           static_cast<double>(judged)))) + "%"
             : "-";
  h5::EnumMembers legend = {{"across the paint", 0},
                            {"along the paint (" + share + " of points judged)", 1},
                            {"no clear paint", 2}};
  draw_legend(image, legend, flow_colours);
  return image;
}

}  // namespace

ExtractColouring parse_extract_colouring(const std::string& word) {
  if (word == "group") return ExtractColouring::group;
  if (word == "direction") return ExtractColouring::direction;
  if (word == "rule") return ExtractColouring::rule;
  if (word == "kind") return ExtractColouring::kind;
  if (word == "flow") return ExtractColouring::flow;
  throw Error::usage("colouring '" + word + "' is not one of: group, direction, rule, kind, flow");
}

cv::Mat extract_picture(const h5::File& file, ExtractColouring colouring,
                        const RenderOptions& options) {
  h5::require_schema(file, kExtractSchema);
  StrandSet strands = h5::read_strand_set(file, "/strands");
  const auto& strand_group = std::get<std::vector<int32_t>>(strands.strand_attributes.at("group"));
  ExtractedBody body = read_extracted_body(file);

  PointColours colours;
  const h5::EnumMembers* legend = nullptr;
  switch (colouring) {
    case ExtractColouring::group:
      colours = colours_by_id(strands, strand_group);
      break;
    case ExtractColouring::direction:
      colours = colours_root_to_tip(strands);
      break;
    case ExtractColouring::rule:
      legend = &orientation_rule_members();
      colours = colours_by_table(
          strands,
          per_strand(h5::read_enum_dataset(file, "/groups/orientation_rule", *legend),
                     strand_group),
          category_colours());
      break;
    case ExtractColouring::kind:
      legend = &patch_kind_members();
      colours = colours_by_table(
          strands,
          per_strand(h5::read_enum_dataset(file, "/groups/patch_kind", *legend), strand_group),
          category_colours());
      break;
    case ExtractColouring::flow:
      return flow_picture(file, strands, body, options);
  }
  cv::Mat image = render_strands(strands, colours, body.vertices, body.triangles, options);
  if (legend) draw_legend(image, *legend);
  return image;
}

cv::Mat types_picture(const h5::File& types, const h5::File& extract,
                      const RenderOptions& options) {
  h5::require_schema(types, kTypesSchema);
  h5::require_schema(extract, kExtractSchema);
  StrandSet strands = h5::read_strand_set(extract, "/strands");
  const auto& strand_group = std::get<std::vector<int32_t>>(strands.strand_attributes.at("group"));
  std::vector<int8_t> type = h5::read_enum_dataset(types, "/groups/type", group_type_members());
  auto group_count = static_cast<int32_t>(type.size());
  for (int32_t group : strand_group)
    if (group >= group_count)
      throw Error::bad_input(types.name(), "has " + std::to_string(group_count) + " groups; " +
                                               extract.name() + " has more");
  // BGR: root_free blue, root_connected green, middle orange, tip red.
  static const std::vector<cv::Vec3b> type_colours = {
      {200, 110, 30}, {60, 170, 40}, {20, 140, 250}, {40, 40, 210}};
  PointColours colours = colours_by_table(strands, per_strand(type, strand_group), type_colours);
  ExtractedBody body = read_extracted_body(extract);
  cv::Mat image = render_strands(strands, colours, body.vertices, body.triangles, options);
  draw_legend(image, group_type_members(), type_colours);
  return image;
}

cv::Mat style_picture(const h5::File& extract, const std::vector<int8_t>& group_style,
                      const RenderOptions& options) {
  h5::require_schema(extract, kExtractSchema);
  StrandSet strands = h5::read_strand_set(extract, "/strands");
  const auto& strand_group = std::get<std::vector<int32_t>>(strands.strand_attributes.at("group"));
  // Indexed by style code; the last entry: no style.
  static const std::vector<cv::Vec3b> style_colours = {
      style_colour(0), style_colour(1), style_colour(2), style_colour(3), style_colour(-1)};
  const auto none = static_cast<int32_t>(kStyleWords.size());
  std::vector<int32_t> strand_style;
  strand_style.reserve(strand_group.size());
  for (int32_t group : strand_group) {
    if (group < 0 || static_cast<size_t>(group) >= group_style.size())
      throw Error::bad_input(extract.name(), "group " + std::to_string(group) + " has no style (" +
                                                 std::to_string(group_style.size()) + " given)");
    int8_t style = group_style[group];
    strand_style.push_back(style >= 0 && style < none ? style : none);
  }
  ExtractedBody body = read_extracted_body(extract);
  cv::Mat image = render_strands(strands, colours_by_table(strands, strand_style, style_colours),
                                 body.vertices, body.triangles, options);
  h5::EnumMembers legend;
  for (size_t code = 0; code < kStyleWords.size(); ++code)
    legend.push_back({std::string(kStyleWords[code]), static_cast<int8_t>(code)});
  if (std::count(strand_style.begin(), strand_style.end(), none) > 0)
    legend.push_back({"no label", static_cast<int8_t>(none)});
  draw_legend(image, legend, style_colours);
  return image;
}

}  // namespace hair
