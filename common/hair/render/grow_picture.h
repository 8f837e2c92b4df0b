#pragma once

#include <opencv2/core.hpp>
#include <string>

#include "hair/h5/file.h"
#include "hair/render/strand_render.h"

namespace hair {

/// How a picture of strands.h5 colours the grown strands.
enum class GrownColouring {
  cluster,   ///< by cluster, the palette of clusters_picture() (the same cluster, the same hue)
  root_cluster,  ///< each whole strand by its root's cluster: where each cluster's hair goes
  rule,      ///< by how each segment was grown: field, input strand, bridge
  direction  ///< root (dark blue) to tip (yellow)
};
GrownColouring parse_grown_colouring(const std::string& word);

/// Renders the grown strands of `strands` (strands.h5) over the body of `extract` (the
/// extract.h5 they were grown from). Under the title, a line with the strand and point
/// counts, and for `rule` the legend. Errors (bad_input) name the file at fault.
cv::Mat grown_picture(const h5::File& strands, const h5::File& extract,
                      const RenderOptions& options, GrownColouring colouring);

}  // namespace hair
