#pragma once

#include <opencv2/core.hpp>
#include <string>

#include "hair/h5/file.h"
#include "hair/render/strand_render.h"

namespace hair {

/// Colour of the strands of groups that are not middle-type in a middle picture (BGR):
/// a light neutral grey, dim on the white background.
inline const cv::Vec3b kNonMiddleGrey{205, 205, 205};

/// Renders the input strands of `extract` (the extract.h5 the clustering was made from)
/// coloured by the middle clusters of `middle` (middle.h5): a hue per cluster from the
/// palette of colours_by_id(), the groups that are not middle-type in kNonMiddleGrey.
/// Under the title, a line with the number of middle clusters and how it was set
/// (cluster_count_source). Errors (bad_input) name the file at fault: a wrong schema,
/// or files made from different models.
cv::Mat middle_picture(const h5::File& middle, const h5::File& extract,
                       const RenderOptions& options);

/// Renders the input strands of `extract` coloured by the final clusters of `clusters`
/// (clusters.h5), or with `before_split` by the clusters spectral clustering found before
/// the division at type changes; same palette as middle_picture(). Under the title, a
/// line with the counts (clusters, before the split, split_count, how the count was set).
cv::Mat clusters_picture(const h5::File& clusters, const h5::File& extract,
                         const RenderOptions& options, bool before_split);

/// Parses hair-render's --color-by for clusters.h5: "cluster" (false) or "before_split"
/// (true); a usage error otherwise.
bool parse_cluster_colouring(const std::string& word);

}  // namespace hair
