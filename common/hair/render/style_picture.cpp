#include "hair/render/style_picture.h"

#include <opencv2/imgproc.hpp>

#include "hair/core/error.h"
#include "hair/extract/extract_io.h"
#include "hair/grow/grow_io.h"
#include "hair/h5/dataset.h"
#include "hair/h5/schema_validation.h"
#include "hair/style/style_io.h"

namespace hair {

cv::Vec3b style_colour(int8_t style) {
  switch (style) {
    case 0:
      return {40, 210, 240};  // normal: yellow
    case 1:
      return {30, 75, 140};  // fixed: brown
    case 2:
      return {60, 180, 60};  // short: green
    case 3:
      return {220, 110, 30};  // braided: blue
    default:
      return {150, 150, 150};
  }
}

int draw_style_legend(cv::Mat& image, cv::Point top_left, const std::array<int, 4>& count) {
  const char* names[] = {"normal", "fixed", "short", "braided"};
  int x = top_left.x;
  for (int8_t style : {1, 3, 2, 0}) {
    std::string text =
        std::string(names[style]) + " " + std::to_string(count[static_cast<size_t>(style)]);
    cv::Vec3b colour = style_colour(style);
    cv::rectangle(image, cv::Rect(x, top_left.y, 12, 12),
                  cv::Scalar(colour[0], colour[1], colour[2]), cv::FILLED);
    cv::putText(image, text, cv::Point(x + 16, top_left.y + 11), cv::FONT_HERSHEY_SIMPLEX, 0.45,
                cv::Scalar(40, 40, 40), 1, cv::LINE_AA);
    x += 30 + 9 * static_cast<int>(text.size());
  }
  return x;
}

cv::Mat styles_picture(const h5::File& styles, const h5::File& strands, const h5::File& extract,
                       const RenderOptions& options) {
  std::vector<int8_t> cluster_style = read_cluster_styles(styles);
  const StyleCertainty certainty = read_style_certainty(styles);
  GrownStrands grown = read_grown_strands(strands);
  const StrandSet& set = grown.strands;
  const auto& point_cluster = std::get<std::vector<int32_t>>(set.point_attributes.at("cluster"));
  PointColours colours;
  colours.reserve(point_cluster.size());
  for (int32_t cluster : point_cluster) {
    if (cluster < 0 || cluster >= static_cast<int32_t>(cluster_style.size()))
      throw Error::bad_input(styles.name(), "has " + std::to_string(cluster_style.size()) +
                                                " clusters, " + strands.name() +
                                                " a point of cluster " + std::to_string(cluster) +
                                                ": made from another model");
    cv::Vec3b colour = style_colour(cluster_style[static_cast<size_t>(cluster)]);
    if (certainty.unsure[static_cast<size_t>(cluster)])  // unsure: pale, half way to white
      for (int k = 0; k < 3; ++k) colour[k] = static_cast<uint8_t>((colour[k] + 255) / 2);
    colours.push_back(colour);
  }
  ExtractedBody body = read_extracted_body(extract);
  cv::Mat image = render_strands(set, colours, body.vertices, body.triangles, options);
  // Legend: the four styles in their colours, with how many clusters have each.
  std::array<int, 4> count{};
  for (int8_t style : cluster_style)
    if (style >= 0 && style < 4) ++count[static_cast<size_t>(style)];
  draw_style_legend(image, cv::Point(10, 34), count);
  // Below it, which clusters are unsure (drawn pale) and which the user pinned.
  std::string unsure, pinned;
  for (size_t c = 0; c < cluster_style.size(); ++c) {
    if (certainty.unsure[c])
      unsure += (unsure.empty() ? "" : ", ") + std::to_string(c) + " (" +
                cv::format("%.2f", certainty.confidence[c]) + ")";
    if (certainty.pinned[c]) pinned += (pinned.empty() ? "" : ", ") + std::to_string(c);
  }
  int y = 62;
  if (!unsure.empty()) {
    cv::putText(image, cv::format("pale: unsure, under %.2f of the votes: ", certainty.unsure_below) + unsure,
                cv::Point(10, y), cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(40, 40, 40), 1,
                cv::LINE_AA);
    y += 18;
  }
  if (!pinned.empty())
    cv::putText(image, "pinned by the user: " + pinned, cv::Point(10, y), cv::FONT_HERSHEY_SIMPLEX,
                0.45, cv::Scalar(40, 40, 40), 1, cv::LINE_AA);
  return image;
}

}  // namespace hair
