#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "hair/h5/file.h"
#include "hair/render/strand_render.h"

namespace hair {

/// What colours the strands of an extract picture.
enum class ExtractColouring {
  group,      ///< a hue per strand group (patch)
  direction,  ///< root (dark blue) to tip (yellow): shows the orientation
  rule,       ///< the rule that decided the orientation (with a legend)
  kind,       ///< the patch kind (with a legend)
  flow,       ///< along the painted flow of the nearest face (green), across it (red), or
              ///< no clear paint there (grey), with a legend and the share along
};

/// Parses "group", "direction", "rule", "kind" or "flow"; a usage error otherwise.
ExtractColouring parse_extract_colouring(const std::string& word);

/// Renders the input strands of an extract.h5 file over its body.
cv::Mat extract_picture(const h5::File& file, ExtractColouring colouring,
                        const RenderOptions& options);

/// Renders the input strands of `extract` coloured by the group types of `types`
/// (types.h5 made from it), with a legend: root_free blue, root_connected green,
/// middle orange, tip red.
cv::Mat types_picture(const h5::File& types, const h5::File& extract, const RenderOptions& options);

/// Renders the input strands of an extract.h5 file coloured by a style per group,
/// with a legend: normal yellow, fixed brown, short green, braided blue (the paper's
/// Fig. 9 and the synthetic gallery), grey for a group without a style.
///
/// @param group_style  #groups style codes (hair/style/style_labels.h), -1 for none
cv::Mat style_picture(const h5::File& extract, const std::vector<int8_t>& group_style,
                      const RenderOptions& options);

}  // namespace hair
