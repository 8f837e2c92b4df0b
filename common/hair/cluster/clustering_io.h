#pragma once

#include <string>
#include <vector>

#include "hair/cluster/hair_clustering.h"
#include "hair/h5/file.h"

namespace hair {

/// Schema names of the clustering stages' outputs (schemas/middle.json, clusters.json).
inline constexpr const char* kMiddleSchema = "hairstyle.middle";
inline constexpr const char* kClustersSchema = "hairstyle.clusters";

/// What the clustering stages read of types.h5.
struct TypedGroups {
  StrandSet centre_strands;                    ///< /centre_strands, one per group, root first
  std::vector<GroupType> type;                 ///< /groups/type
  double head_height_m = 0;                    ///< @head_height_m
  std::vector<double> start_scalp_distance_m;  ///< /groups/start_scalp_distance_m
};

/// Reads the types, centre strands and H of a types.h5 file, after checking its schema.
TypedGroups read_typed_groups(const h5::File& file);

/// Reads /groups/middle_cluster of a middle.h5 file, after checking its schema and that
/// it has `group_count` groups (else bad_input: the files come from different models).
std::vector<int32_t> read_middle_clusters(const h5::File& file, size_t group_count);

/// What later stages and the renderer read of clusters.h5.
struct GroupClusters {
  std::vector<int32_t> cluster;               ///< per group, final
  std::vector<int32_t> cluster_before_split;  ///< per group
  std::vector<uint8_t> starts_at_root;        ///< per cluster
};
GroupClusters read_group_clusters(const h5::File& file);

/// Write middle.h5 / clusters.h5 but for provenance.
void write_middle_file(h5::File& file, const MiddleClustering& clustering, double head_height_m);
void write_clusters_file(h5::File& file, const HairClustering& clustering, double head_height_m);

}  // namespace hair
