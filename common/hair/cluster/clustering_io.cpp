#include "hair/cluster/clustering_io.h"

#include "hair/cluster/typeify_io.h"
#include "hair/core/error.h"
#include "hair/h5/attribute.h"
#include "hair/h5/dataset.h"
#include "hair/h5/enum_dataset.h"
#include "hair/h5/schema.h"
#include "hair/h5/schema_validation.h"
#include "hair/h5/strand_set_io.h"

namespace hair {
namespace {

/// The graph datasets both files share: edges, weights, affinities, eigenvalues.
void write_graph(h5::File& file, const GroupGraph& graph, const std::vector<double>& eigenvalues) {
  std::vector<int32_t> edges;
  edges.reserve(2 * graph.edges.size());
  for (const auto& edge : graph.edges) edges.insert(edges.end(), edge.begin(), edge.end());
  h5::write_dataset(file, "/graph/edges", edges, {static_cast<int64_t>(graph.edges.size()), 2});
  h5::write_vector(file, "/graph/weight",
                   std::vector<float>(graph.weight.begin(), graph.weight.end()));
  h5::write_vector(file, "/graph/affinity",
                   std::vector<float>(graph.affinity.begin(), graph.affinity.end()));
  h5::write_vector(file, "/spectrum/eigenvalues", eigenvalues);
}

void write_common_attributes(h5::File& file, const char* schema, double head_height_m,
                             int64_t cluster_count, ClusterCountSource source,
                             double affinity_scale) {
  h5::write_schema_attributes(file, h5::Schema::find(schema));
  h5::write_string_attribute(file, "/", "unit", "m");
  h5::write_double_attribute(file, "/", "head_height_m", head_height_m);
  h5::write_int64_attribute(file, "/", "cluster_count", cluster_count);
  h5::write_string_attribute(file, "/", "cluster_count_source", cluster_count_source_name(source));
  h5::write_double_attribute(file, "/", "affinity_scale", affinity_scale);
}

}  // namespace

TypedGroups read_typed_groups(const h5::File& file) {
  h5::require_schema(file, kTypesSchema);
  TypedGroups groups;
  StrandSet centres;
  centres.points = h5::read_matrix<float, 3>(file, "/centre_strands/points");
  centres.offsets = h5::read_vector<int64_t>(file, "/centre_strands/offsets");
  groups.centre_strands = std::move(centres);
  for (int8_t value : h5::read_enum_dataset(file, "/groups/type", group_type_members()))
    groups.type.push_back(static_cast<GroupType>(value));
  groups.head_height_m = h5::read_double_attribute(file, "/", "head_height_m");
  groups.start_scalp_distance_m = h5::read_vector<double>(file, "/groups/start_scalp_distance_m");
  return groups;
}

std::vector<int32_t> read_middle_clusters(const h5::File& file, size_t group_count) {
  h5::require_schema(file, kMiddleSchema);
  std::vector<int32_t> middle_cluster = h5::read_vector<int32_t>(file, "/groups/middle_cluster");
  if (middle_cluster.size() != group_count)
    throw Error::other_model(file.name(), "/groups/middle_cluster", middle_cluster.size(), "groups",
                             "the types file", group_count);
  return middle_cluster;
}

GroupClusters read_group_clusters(const h5::File& file) {
  h5::require_schema(file, kClustersSchema);
  GroupClusters clusters;
  clusters.cluster = h5::read_vector<int32_t>(file, "/groups/cluster");
  clusters.cluster_before_split = h5::read_vector<int32_t>(file, "/groups/cluster_before_split");
  clusters.starts_at_root = h5::read_vector<uint8_t>(file, "/clusters/starts_at_root");
  return clusters;
}

void write_middle_file(h5::File& file, const MiddleClustering& clustering, double head_height_m) {
  write_common_attributes(file, kMiddleSchema, head_height_m, clustering.cluster_count,
                          clustering.count_source, clustering.graph.affinity_scale);
  h5::write_vector(file, "/groups/middle_cluster", clustering.middle_cluster);
  std::vector<int32_t> group_count(static_cast<size_t>(clustering.cluster_count), 0);
  for (int32_t cluster : clustering.middle_cluster)
    if (cluster >= 0) ++group_count[static_cast<size_t>(cluster)];
  h5::write_vector(file, "/clusters/group_count", group_count);
  std::vector<float> features;
  for (const auto& f : clustering.graph.features)
    features.insert(features.end(), f.begin(), f.end());
  h5::write_dataset(file, "/graph/f", features,
                    {static_cast<int64_t>(clustering.graph.features.size()), 4});
  write_graph(file, clustering.graph, clustering.eigenvalues);
}

void write_clusters_file(h5::File& file, const HairClustering& clustering, double head_height_m) {
  write_common_attributes(file, kClustersSchema, head_height_m, clustering.clusters_before_split,
                          clustering.count_source, clustering.graph.affinity_scale);
  h5::write_int64_attribute(file, "/", "split_count", clustering.split_count);
  h5::write_vector(file, "/groups/cluster", clustering.cluster);
  h5::write_vector(file, "/groups/node", clustering.node_of_group);
  h5::write_vector(file, "/groups/cluster_before_split", clustering.cluster_before_split);
  const h5::Schema& schema = h5::Schema::find(kClustersSchema);
  std::vector<int8_t> sets;
  for (uint8_t in_s1 : clustering.node_in_s1) sets.push_back(in_s1 ? 0 : 1);
  h5::write_enum_dataset(file, "/nodes/set", sets, schema.dataset("/nodes/set").enum_members);
  h5::write_vector(file, "/nodes/middle_cluster", clustering.node_middle_cluster);
  h5::write_vector(file, "/clusters/group_count", clustering.cluster_group_count);
  h5::write_vector(file, "/clusters/starts_at_root", clustering.cluster_starts_at_root);
  h5::write_vector(file, "/clusters/before_split", clustering.cluster_origin);
  std::vector<int32_t> before_split_count(static_cast<size_t>(clustering.clusters_before_split), 0);
  for (int32_t cluster : clustering.cluster_before_split)
    ++before_split_count[static_cast<size_t>(cluster)];
  h5::write_vector(file, "/clusters_before_split/group_count", before_split_count);
  h5::write_enum_dataset(file, "/graph/kind", h5::enum_values(clustering.graph.kind),
                         schema.dataset("/graph/kind").enum_members);
  write_graph(file, clustering.graph, clustering.eigenvalues);
}

}  // namespace hair
