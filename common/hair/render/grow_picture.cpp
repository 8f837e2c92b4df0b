#include "hair/render/grow_picture.h"

#include <opencv2/imgproc.hpp>

#include "hair/core/error.h"
#include "hair/extract/extract_io.h"
#include "hair/grow/grow_io.h"
#include "hair/h5/dataset.h"
#include "hair/h5/enum_dataset.h"
#include "hair/h5/schema_validation.h"

namespace hair {
namespace {

/// Colours of the grow rules (BGR): field blue, input strand orange, bridge magenta.
const std::vector<cv::Vec3b>& rule_colours() {
  static const std::vector<cv::Vec3b> colours = {
      {90, 90, 90}, {200, 120, 30}, {20, 140, 240}, {200, 40, 200}};
  return colours;
}

}  // namespace

GrownColouring parse_grown_colouring(const std::string& word) {
  if (word == "cluster") return GrownColouring::cluster;
  if (word == "root_cluster") return GrownColouring::root_cluster;
  if (word == "rule") return GrownColouring::rule;
  if (word == "direction") return GrownColouring::direction;
  throw Error::usage("--color-by for strands.h5 is cluster, root_cluster, rule or direction, not '" +
                     word + "'");
}

cv::Mat grown_picture(const h5::File& strands, const h5::File& extract,
                      const RenderOptions& options, GrownColouring colouring) {
  GrownStrands grown = read_grown_strands(strands);
  ExtractedBody body = read_extracted_body(extract);
  const StrandSet& set = grown.strands;
  PointColours colours;
  switch (colouring) {
    case GrownColouring::cluster:
      colours =
          colours_by_point_id(std::get<std::vector<int32_t>>(set.point_attributes.at("cluster")));
      break;
    case GrownColouring::root_cluster:
      colours = colours_by_id(set, std::get<std::vector<int32_t>>(set.strand_attributes.at("cluster")));
      break;
    case GrownColouring::direction:
      colours = colours_root_to_tip(set);
      break;
    case GrownColouring::rule: {
      std::vector<int8_t> rule =
          h5::read_enum_dataset(strands, "/strands/point_rule", grow_rule_members());
      if (static_cast<int64_t>(rule.size()) != set.point_count())
        throw Error::bad_dataset(strands.name(), "/strands/point_rule",
                                 "does not have one value per point");
      colours.reserve(rule.size());
      for (int8_t value : rule) colours.push_back(rule_colours()[static_cast<size_t>(value)]);
      break;
    }
  }
  cv::Mat image = render_strands(set, colours, body.vertices, body.triangles, options);
  std::string line = std::to_string(set.strand_count()) + " strands, " +
                     std::to_string(set.point_count()) + " points";
  if (colouring == GrownColouring::rule)
    line += "   blue: field   orange: input strand   magenta: bridge";
  cv::putText(image, line, cv::Point(10, 44), cv::FONT_HERSHEY_SIMPLEX, 0.45,
              cv::Scalar(40, 40, 40), 1, cv::LINE_AA);
  return image;
}

}  // namespace hair
