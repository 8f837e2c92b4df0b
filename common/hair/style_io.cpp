#include "hair/style_io.h"

#include <string>

#include "hair/clustering_io.h"
#include "hair/error.h"
#include "hair/extract_io.h"
#include "hair/grow_io.h"
#include "hair/h5/attribute.h"
#include "hair/h5/dataset.h"
#include "hair/h5/schema_validation.h"

namespace hair {

StyleFeatureInput read_style_feature_input(const h5::File& extract, const h5::File& clusters,
                                           const h5::File& strands) {
  StyleFeatureInput input;
  h5::require_schema(extract, kExtractSchema);
  input.body_vertices = h5::read_matrix<float, 3>(extract, "/body/vertices");
  input.body_triangles = h5::read_matrix<int32_t, 3>(extract, "/body/triangles");
  input.scalp_triangle = h5::read_vector<uint8_t>(extract, "/body/scalp_triangle");
  auto group_count = h5::read_vector<int32_t>(extract, "/groups/face_count").size();

  GroupClusters grouped = read_group_clusters(clusters);
  if (grouped.cluster.size() != group_count)
    throw Error::bad_dataset(clusters.name(), "/groups/cluster",
                             "has " + std::to_string(grouped.cluster.size()) + " groups, " +
                                 extract.name() + " " + std::to_string(group_count) +
                                 ": made from another model");
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
    throw Error::bad_dataset(strands.name(), "/clusters/strand_count",
                             "has " + std::to_string(grown_clusters) + " clusters, " +
                                 clusters.name() + " " + std::to_string(input.cluster_count) +
                                 ": made from another model");
  input.strands = std::move(grown.strands);
  input.head_height_m = grown.head_height_m;
  input.source = strands.name();
  return input;
}

}  // namespace hair
