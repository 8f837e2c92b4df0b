#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "hair/cluster/group_graph.h"
#include "hair/cluster/group_weights.h"
#include "hair/cluster/spectral_clustering.h"
#include "hair/cluster/typeify.h"
#include "hair/core/strand_set.h"

namespace hair {

/// How the number of clusters of a clustering was set.
enum class ClusterCountSource { eigengap, parameter, skipped };
const char* cluster_count_source_name(ClusterCountSource source);

/// Settings shared by both clustering levels.
struct GraphClusteringParams {
  ConnectivityParams connectivity;
  /// The words of connectivity.flow_direction and connectivity.closeness, as the
  /// parameter file gives them (add_graph_clustering_params() reads them into the enums).
  std::string flow_direction_word = flow_direction_name(connectivity.flow_direction);
  std::string closeness_word = closeness_name(connectivity.closeness);
  /// Halve w_ij when it is the smallest weight from group i to a group on its tip side
  /// (section 4.2, "a heuristic emphasizing the local similarity").
  bool halve_best_tip_side = true;
  /// Connect two groups whichever way extract oriented them: the weight is the best
  /// over both directions of each. Pieces read tip to root (extract gets about one in
  /// five braid pieces wrong) then still chain with their neighbours.
  bool either_orientation = true;
  /// Keep a connection only when it ranks among the `continuations` best at both group
  /// ends it joins (a mutual nearest-neighbour graph over group ends); 0 keeps every
  /// connection within the bounds (the paper's complete graph). Strand streams are
  /// chains: in a braid every piece also lies within the bounds of pieces of the other
  /// streams, and on the complete graph spectral clustering cuts the braid across
  /// instead of separating its streams.
  int continuations = 1;
  /// sigma of the affinity exp(-w^2 / (2 sigma^2)); 0: the median edge weight. 0.02 at
  /// the first level, where w is mostly 0.7 f4 + 0.2 f1 (an offset near the bound f4_max
  /// with a gap of 0.03 H gives about 0.02; 0.03 H is 7 mm on MakeHuman), so that a weak
  /// false link between two chains of pieces is still cut by the eigengap
  /// (docs/clustering.md: the synthetic braids score alike for any sigma from 0.016 to
  /// 0.04); the median at the second level.
  double affinity_scale = 0.02;
  SpectralParams spectral;
};

/// Result of the first level: clusters of middle-type groups (section 4.2).
struct MiddleClustering {
  std::vector<int32_t> middle_cluster;  ///< per group; -1 for groups not middle-type
  int32_t cluster_count = 0;
  ClusterCountSource count_source = ClusterCountSource::skipped;
  GroupGraph graph;                 ///< over group ids
  std::vector<double> eigenvalues;  ///< leading, descending
};

/// Spectral clustering of the middle-type groups over a graph weighted by
/// connectivity (equations 1-3). No middle groups: an empty result, `skipped`.
///
/// @param centres  centre strand of every group (types.h5 /centre_strands), root first
MiddleClustering cluster_middle_groups(const StrandSet& centres,
                                       const std::vector<GroupType>& types, double head_height_m,
                                       const GraphClusteringParams& params);

/// Settings of the second level. Its graph keeps every connection within the bounds
/// (continuations = 0, the paper's complete graph): at this level clusters are regions
/// of hair (a braid with its streams, a ponytail's tail), not single streams.
struct HairClusteringParams {
  HairClusteringParams() {
    graph.continuations = 0;
    graph.affinity_scale = 0;
    // The paper's three criteria, f1 first, and no continuation offset: between regions
    // of hair the end gap is what counts.
    ConnectivityParams& c = graph.connectivity;
    c.k1 = 0.9;
    c.k2 = 0.05;
    c.k3 = 0.05;
    c.k4 = 0;
    c.f4_max = 1;
  }
  GraphClusteringParams graph;
  SimilarityParams similarity;
  /// Divide a cluster where the type changes from root to another type (section 4.3).
  bool split_at_type_change = true;
  /// In that division, a root-type group of S2 whose first point continues another group
  /// of its cluster (a connection within the connectivity bounds joins that group's end to
  /// this group's start) goes with the distal part: typeify found nothing within its reach
  /// (0.08 H) before it, but at this level's reach (f1_max) it continues a chain, so it does
  /// not start at the root. A braid whose strips start well below the cap groups that run
  /// into it (braid01's) is typed root_connected and would stay with the cap without
  /// this. grow roots no strand at such a group (its cluster does not start at the root)
  /// and reaches it across the gap (GrowParams::continued_root_radius_h).
  bool split_continued_roots = true;
  /// ...but only a group whose centre strand starts at least this far from the scalp
  /// (types.h5 /groups/start_scalp_distance_m), in H: groups that start on the scalp
  /// beside one another (a crown, the two sides of a parting) line up as well as a
  /// continuation does. A braid's continued strips start farther from the scalp than its
  /// cap groups, and hair-synth's true first pieces typed root nearly all start within
  /// 0.04 H (docs/clustering.md).
  double continued_root_min_scalp_distance_h = 0.05;
};

/// Result of the second level: every group in a hair cluster (section 4.3).
struct HairClustering {
  std::vector<int32_t> node_of_group;           ///< per group
  std::vector<int32_t> cluster_before_split;    ///< per group
  std::vector<int32_t> cluster;                 ///< per group, final
  std::vector<uint8_t> node_in_s1;              ///< per node: a free-root group
  std::vector<int32_t> node_middle_cluster;     ///< per node: its middle cluster or -1
  std::vector<int32_t> cluster_origin;          ///< per final cluster: its cluster before split
  std::vector<uint8_t> cluster_starts_at_root;  ///< per final cluster
  std::vector<int32_t> cluster_group_count;     ///< per final cluster
  /// per group: a root-type group that continues another group of its cluster, counted
  /// with the distal part (split_continued_roots)
  std::vector<uint8_t> continues_group;
  int32_t clusters_before_split = 0;
  int32_t split_count = 0;
  ClusterCountSource count_source = ClusterCountSource::skipped;
  GroupGraph graph;  ///< over nodes
  std::vector<double> eigenvalues;
};

/// Algorithm 2's second level. Nodes: each free-root group (S1), each other root or
/// tip group, and each middle cluster (S2). S1-S1 edges by similarity (equations 4-5),
/// S2-S2 edges by connectivity (1-3; between nodes of several groups the smallest
/// weight of their groups' pairs), no S1-S2 edges. Then spectral clustering and the
/// division of clusters at the change from root-type groups to the others (a root-type
/// group of S2 that continues another group of its cluster counts as one of the others:
/// HairClusteringParams::split_continued_roots).
///
/// @param middle_cluster  per group, from cluster_middle_groups(); every middle group
///                        must have one (each_middle_group_alone() for one level only)
/// @param start_scalp_distance_m  per group, from start_scalp_distances(); empty when not
///                        known, and then any root-type group may continue another
HairClustering cluster_hair(const StrandSet& centres, const std::vector<GroupType>& types,
                            const std::vector<int32_t>& middle_cluster, double head_height_m,
                            const HairClusteringParams& params,
                            const std::vector<double>& start_scalp_distance_m = {});

/// A middle clustering that puts every middle group in a cluster of its own: with it,
/// cluster_hair() is one-level spectral clustering over all groups (the baseline the
/// paper says fails on braids).
std::vector<int32_t> each_middle_group_alone(const std::vector<GroupType>& types);

}  // namespace hair
