#pragma once
// Reading the classify stage's inputs and writing its output, styles.h5
// (schemas/styles.json).

#include "hair/h5/file.h"
#include "hair/style_features.h"

namespace hair {

/// Reads what style_features() needs from extract.h5 (body, scalp, H, the group count),
/// clusters.h5 (the final cluster and the middle cluster of every group) and strands.h5
/// (the grown strands with the cluster and group of every point), after checking each
/// file's schema and that the three come from the same model.
StyleFeatureInput read_style_feature_input(const h5::File& extract, const h5::File& clusters,
                                           const h5::File& strands);

}  // namespace hair
