#pragma once

#include <array>
#include <opencv2/core.hpp>

#include "hair/h5/file.h"
#include "hair/render/strand_render.h"

namespace hair {

/// The paper's colours of the styles (Figure 9), BGR: fixed brown, braided blue, short
/// green, normal yellow; grey for a cluster without a style.
cv::Vec3b style_colour(int8_t style);

/// Draws the legend of the four styles into `image` from `top_left` rightwards: a swatch
/// in the style's colour, its name and `count[style]` (of clusters, guides, ...), fixed,
/// braided, short, normal. Returns the x where a further entry would start.
int draw_style_legend(cv::Mat& image, cv::Point top_left, const std::array<int, 4>& count);

/// Renders the grown strands of `strands` (strands.h5), every point in the paper's colour
/// of its cluster's style in `styles` (styles.h5), over the body of `extract`, with a
/// legend and the styles found; unsure clusters pale, and listed under the legend with
/// the clusters the user pinned. Errors (bad_input) name the file at fault, e.g. files of
/// different models.
cv::Mat styles_picture(const h5::File& styles, const h5::File& strands, const h5::File& extract,
                       const RenderOptions& options);

}  // namespace hair
