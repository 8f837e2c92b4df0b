#include "hair/style/style_io.h"

#include <string>

#include "hair/cluster/clustering_io.h"
#include "hair/core/error.h"
#include "hair/extract/extract_io.h"
#include "hair/grow/grow_io.h"
#include "hair/h5/attribute.h"
#include "hair/h5/dataset.h"
#include "hair/h5/enum_dataset.h"
#include "hair/h5/schema.h"
#include "hair/h5/schema_validation.h"
#include "hair/style/style_model_io.h"

namespace hair {

StyleFeatureInput read_style_feature_input(const h5::File& extract, const h5::File& clusters,
                                           const h5::File& strands) {
  StyleFeatureInput input;
  ExtractedBody body = read_extracted_body(extract);
  input.body_vertices = std::move(body.vertices);
  input.body_triangles = std::move(body.triangles);
  input.scalp_triangle = std::move(body.scalp_triangle);
  auto group_count = h5::read_vector<int32_t>(extract, "/groups/face_count").size();

  GroupClusters grouped = read_group_clusters(clusters);
  if (grouped.cluster.size() != group_count)
    throw Error::other_model(clusters.name(), "/groups/cluster", grouped.cluster.size(), "groups",
                             extract.name(), group_count);
  input.cluster_count = static_cast<int32_t>(grouped.starts_at_root.size());
  input.group_cluster = std::move(grouped.cluster);
  std::vector<int32_t> node = h5::read_vector<int32_t>(clusters, "/groups/node");
  std::vector<int32_t> middle_cluster = h5::read_vector<int32_t>(clusters, "/nodes/middle_cluster");
  input.group_middle_node.reserve(node.size());
  for (int32_t n : node)
    input.group_middle_node.push_back(n >= 0 && n < static_cast<int32_t>(middle_cluster.size())
                                          ? middle_cluster[static_cast<size_t>(n)]
                                          : -1);

  GrownStrands grown = read_grown_strands(strands);
  auto grown_clusters = h5::read_vector<int64_t>(strands, "/clusters/strand_count").size();
  if (grown_clusters != static_cast<size_t>(input.cluster_count))
    throw Error::other_model(strands.name(), "/clusters/strand_count", grown_clusters, "clusters",
                             clusters.name(), static_cast<size_t>(input.cluster_count));
  input.strands = std::move(grown.strands);
  input.head_height_m = grown.head_height_m;
  input.source = strands.name();
  return input;
}

const h5::EnumMembers& style_members() {
  static const h5::EnumMembers members = {
      {"none", -1}, {"normal", 0}, {"fixed", 1}, {"short", 2}, {"braided", 3}};
  return members;
}

std::vector<uint8_t> unsure_clusters(const ClusterStyles& styles, double unsure_below) {
  std::vector<uint8_t> unsure(styles.style.size(), 0);
  for (size_t c = 0; c < unsure.size(); ++c)
    unsure[c] = styles.style[c] >= 0 && (c >= styles.pinned.size() || !styles.pinned[c]) &&
                        (c >= styles.ruled.size() || !styles.ruled[c]) &&
                        c < styles.confidence.size() && styles.confidence[c] < unsure_below
                    ? 1
                    : 0;
  return unsure;
}

void write_styles_file(h5::File& file, const ClusterStyles& styles, const StyleFeatures& features,
                       const std::string& model_file, const std::string& model_feature_set,
                       double head_height_m, double unsure_below) {
  using RowMajorD = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  using RowMajorI = Eigen::Matrix<int32_t, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  h5::write_schema_attributes(file, h5::Schema::find(kStylesSchema));
  h5::write_string_attribute(file, "/", "unit", "m");
  h5::write_double_attribute(file, "/", "head_height_m", head_height_m);
  h5::write_string_attribute(file, "/", "classifier", style_classifier_name(styles.classifier));
  h5::write_string_attribute(file, "/", "model_file", model_file);
  h5::write_int64_attribute(file, "/", "model_version", kStyleModelVersion);
  h5::write_string_attribute(file, "/", "model_feature_set", model_feature_set);
  h5::write_double_attribute(file, "/", "unsure_below", unsure_below);
  h5::write_enum_dataset(file, "/clusters/style", styles.style, style_members());
  h5::write_enum_dataset(file, "/clusters/svm_style", styles.svm_style, style_members());
  h5::write_enum_dataset(file, "/clusters/forest_style", styles.forest_style, style_members());
  std::vector<double> confidence = styles.confidence;
  confidence.resize(styles.style.size(), 0.0);
  std::vector<uint8_t> pinned = styles.pinned;
  pinned.resize(styles.style.size(), 0);
  h5::write_vector(file, "/clusters/confidence", confidence);
  h5::write_vector(file, "/clusters/unsure", unsure_clusters(styles, unsure_below));
  h5::write_vector(file, "/clusters/pinned", pinned);
  std::vector<uint8_t> ruled = styles.ruled;
  ruled.resize(styles.style.size(), 0);
  h5::write_vector(file, "/clusters/ruled", ruled);
  std::vector<uint8_t> fixed_ruled_out = styles.fixed_ruled_out;
  fixed_ruled_out.resize(styles.style.size(), 0);
  h5::write_vector(file, "/clusters/fixed_ruled_out", fixed_ruled_out);
  h5::write_vector(file, "/clusters/strand_count", features.strand_count);
  h5::write_vector(file, "/clusters/point_count", features.point_count);
  h5::write_matrix<double, Eigen::Dynamic>(file, "/clusters/svm_decision_values",
                                           RowMajorD(styles.svm_decision_values));
  h5::write_matrix<int32_t, Eigen::Dynamic>(file, "/clusters/svm_votes",
                                            RowMajorI(styles.svm_votes));
  h5::write_matrix<double, Eigen::Dynamic>(file, "/clusters/forest_vote_fraction",
                                           RowMajorD(styles.forest_vote_fraction));
  std::vector<int8_t> classes(styles.classes.begin(), styles.classes.end());
  h5::write_enum_dataset(file, "/classes/style", classes, style_members());
  const std::vector<std::string>& names = extended_feature_names();
  for (size_t f = 0; f < names.size(); ++f) {
    std::vector<double> column(static_cast<size_t>(features.extended_rows.rows()));
    for (size_t c = 0; c < column.size(); ++c)
      column[c] =
          features.extended_rows(static_cast<Eigen::Index>(c), static_cast<Eigen::Index>(f));
    h5::write_vector(file, "/features/" + names[f], column);
  }
}

std::vector<int8_t> read_cluster_styles(const h5::File& file) {
  h5::require_schema(file, kStylesSchema);
  return h5::read_enum_dataset(file, "/clusters/style", style_members());
}

StyleCertainty read_style_certainty(const h5::File& file) {
  h5::require_schema(file, kStylesSchema);
  StyleCertainty certainty;
  certainty.confidence = h5::read_vector<double>(file, "/clusters/confidence");
  certainty.unsure = h5::read_vector<uint8_t>(file, "/clusters/unsure");
  certainty.pinned = h5::read_vector<uint8_t>(file, "/clusters/pinned");
  certainty.ruled = h5::read_vector<uint8_t>(file, "/clusters/ruled");
  certainty.unsure_below = h5::read_double_attribute(file, "/", "unsure_below");
  return certainty;
}

}  // namespace hair
