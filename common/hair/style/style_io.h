#pragma once
// Reading the classify stage's inputs and writing its output, styles.h5
// (schemas/styles.json).

#include <string>

#include "hair/h5/enum_dataset.h"
#include "hair/h5/file.h"
#include "hair/style/cluster_styles.h"
#include "hair/style/style_features.h"

namespace hair {

/// Reads what style_features() needs from extract.h5 (body, scalp, H, the group count),
/// clusters.h5 (the final cluster and the middle cluster of every group) and strands.h5
/// (the grown strands with the cluster and group of every point), after checking each
/// file's schema and that the three come from the same model.
StyleFeatureInput read_style_feature_input(const h5::File& extract, const h5::File& clusters,
                                           const h5::File& strands);

/// Schema name of the classify stage's output (schemas/styles.json).
inline constexpr const char* kStylesSchema = "hairstyle.styles";

/// Members of the style enum datasets of styles.h5: none (-1), normal, fixed, short,
/// braided.
const h5::EnumMembers& style_members();

/// Writes styles.h5 (schemas/styles.json) but for provenance; a classified cluster whose
/// confidence is below `unsure_below` and that no pin settled is marked unsure.
void write_styles_file(h5::File& file, const ClusterStyles& styles, const StyleFeatures& features,
                       const std::string& model_file, const std::string& model_feature_set,
                       double head_height_m, double unsure_below);

/// Whether each classified cluster of `styles` is unsure: confidence below `unsure_below`,
/// not pinned.
std::vector<uint8_t> unsure_clusters(const ClusterStyles& styles, double unsure_below);

/// How sure styles.h5 is of every cluster (schema version 3).
struct StyleCertainty {
  std::vector<double> confidence;
  std::vector<uint8_t> unsure, pinned, ruled;
  double unsure_below = 0;
};
StyleCertainty read_style_certainty(const h5::File& file);

/// What the renderer and later stages read of styles.h5: the style of every cluster
/// (-1 none), after checking the schema.
std::vector<int8_t> read_cluster_styles(const h5::File& file);

}  // namespace hair
