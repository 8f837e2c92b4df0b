#include "hair/cluster/hair_clustering.h"

#include <algorithm>
#include <limits>
#include <map>
#include <utility>

#include "hair/cluster/clustering_params.h"
#include "hair/core/error.h"

namespace hair {
namespace {

bool is_root_type(GroupType type) {
  return type == GroupType::root_free || type == GroupType::root_connected;
}

/// Axis-aligned bounds of every centre strand, for a quick rejection of far pairs.
struct Bounds {
  Eigen::Vector3f low, high;
};

std::vector<Bounds> centre_bounds(const StrandSet& centres) {
  std::vector<Bounds> bounds(static_cast<size_t>(centres.strand_count()));
  for (int64_t g = 0; g < centres.strand_count(); ++g) {
    auto strand = centres.strand(g);
    bounds[static_cast<size_t>(g)] = {strand.colwise().minCoeff().transpose(),
                                      strand.colwise().maxCoeff().transpose()};
  }
  return bounds;
}

float bounds_gap(const Bounds& a, const Bounds& b) {
  Eigen::Vector3f gap = (a.low - b.high).cwiseMax(b.low - a.high).cwiseMax(0.0f);
  return gap.norm();
}

/// The best connection between two groups: which end of each it joins (0 the first
/// centre point, 1 the last), its features and weight.
struct GroupConnection {
  int32_t root_group = -1, tip_group = -1;  ///< c^r and c^t
  int root_end = 1, tip_end = 0;            ///< the end of c^r and of c^t that meet
  double weight = 0;
  ConnectionFeatures features;
};

/// The connection of groups g and h of least weight over the directions allowed (each
/// group as extract oriented it, or also reversed), or nullopt when none is in bounds.
std::optional<GroupConnection> best_connection(const StrandSet& centres, const StrandSet& reversed,
                                               int32_t g, int32_t h, double head_height_m,
                                               const GraphClusteringParams& params) {
  std::optional<GroupConnection> best;
  int directions = params.either_orientation ? 2 : 1;
  for (int g_reversed = 0; g_reversed < directions; ++g_reversed)
    for (int h_reversed = 0; h_reversed < directions; ++h_reversed) {
      ConnectionFeatures features = connection_features(
          (g_reversed ? reversed : centres).strand(g), (h_reversed ? reversed : centres).strand(h),
          head_height_m, params.connectivity.flow_direction, params.connectivity.closeness);
      std::optional<double> weight = connectivity_weight(features, params.connectivity);
      if (!weight || (best && *weight >= best->weight)) continue;
      // As oriented, c^r meets c^t with its last point and c^t with its first.
      bool g_is_root = features.first_is_root_side;
      int g_end = (g_is_root ? 1 : 0) ^ g_reversed, h_end = (g_is_root ? 0 : 1) ^ h_reversed;
      best =
          GroupConnection{g_is_root ? g : h,         g_is_root ? h : g, g_is_root ? g_end : h_end,
                          g_is_root ? h_end : g_end, *weight,           features};
    }
  return best;
}

/// Connectivity edges between the nodes that `node_of_group` gives (-1: a group not in
/// the graph, which still ranks connections). Every pair of groups gets its best connection; a
/// connection is kept when it ranks among the `continuations` best at both group ends it joins (all
/// are kept for 0), and halved when it is the best at the end of its root-side group (the
/// local-similarity heuristic). Between nodes of several groups the edge is their
/// groups' connection of least weight. Pairs inside one node rank, but make no edge.
void add_connectivity_edges(GroupGraph& graph, const StrandSet& centres,
                            const std::vector<int32_t>& node_of_group, double head_height_m,
                            const GraphClusteringParams& params) {
  // Every group takes part in the ranking, also those that are no node: a middle
  // piece's best continuation may be a cap or a tip, and then it is not also joined
  // to another stream's piece.
  std::vector<int32_t> members(node_of_group.size());
  for (size_t g = 0; g < members.size(); ++g) members[g] = static_cast<int32_t>(g);
  std::vector<Bounds> bounds = centre_bounds(centres);
  StrandSet reversed = centres;
  for (int64_t g = 0; g < reversed.strand_count(); ++g)
    reversed.strand(g) = centres.strand(g).colwise().reverse().eval();
  auto reach_m = static_cast<float>(params.connectivity.f1_max * head_height_m);

  std::vector<GroupConnection> connections;
  for (size_t i = 0; i < members.size(); ++i)
    for (size_t j = i + 1; j < members.size(); ++j) {
      int32_t g = members[i], h = members[j];
      if (bounds_gap(bounds[static_cast<size_t>(g)], bounds[static_cast<size_t>(h)]) >= reach_m)
        continue;
      if (auto connection = best_connection(centres, reversed, g, h, head_height_m, params))
        connections.push_back(*connection);
    }

  // Rank of each connection among those at each of the two group ends it joins.
  std::map<std::pair<int32_t, int>, std::vector<std::pair<double, size_t>>> at_end;
  for (size_t c = 0; c < connections.size(); ++c) {
    const GroupConnection& connection = connections[c];
    at_end[{connection.root_group, connection.root_end}].push_back({connection.weight, c});
    at_end[{connection.tip_group, connection.tip_end}].push_back({connection.weight, c});
  }
  std::vector<std::array<size_t, 2>> rank(connections.size());  // {at c^r's end, at c^t's}
  for (auto& [end, list] : at_end) {
    std::sort(list.begin(), list.end());
    for (size_t r = 0; r < list.size(); ++r) {
      const GroupConnection& connection = connections[list[r].second];
      bool root_side = connection.root_group == end.first && connection.root_end == end.second;
      rank[list[r].second][root_side ? 0 : 1] = r;
    }
  }

  // Node pairs: the kept connection of least weight between their groups.
  std::map<std::pair<int32_t, int32_t>, std::pair<double, size_t>> best;
  auto kept = static_cast<size_t>(params.continuations);
  for (size_t c = 0; c < connections.size(); ++c) {
    const GroupConnection& connection = connections[c];
    if (kept > 0 && (rank[c][0] >= kept || rank[c][1] >= kept)) continue;
    int32_t root_node = node_of_group[static_cast<size_t>(connection.root_group)];
    int32_t tip_node = node_of_group[static_cast<size_t>(connection.tip_group)];
    if (root_node < 0 || tip_node < 0 || root_node == tip_node) continue;
    double weight = connection.weight;
    if (params.halve_best_tip_side && rank[c][0] == 0) weight /= 2;
    auto key = std::make_pair(std::min(root_node, tip_node), std::max(root_node, tip_node));
    auto [it, inserted] = best.try_emplace(key, weight, c);
    if (!inserted && weight < it->second.first) it->second = {weight, c};
  }
  for (const auto& [key, weighted] : best) {
    const ConnectionFeatures& features = connections[weighted.second].features;
    graph.add_edge(key.first, key.second, weighted.first, EdgeKind::connectivity,
                   {static_cast<float>(features.f1), static_cast<float>(features.f2),
                    static_cast<float>(features.f3), static_cast<float>(features.f4)});
  }
}

/// Per group: 1 for a root-type group of S2 (`s2_node_of_group` >= 0) whose first point
/// continues another S2 group of its cluster: some group h of the same cluster, in either
/// orientation when params.either_orientation, is c^r of a connection within the bounds
/// whose c^t is this group as extract oriented it (its first point, the root typeify
/// judged, meets h's end).
std::vector<uint8_t> continuing_roots(const StrandSet& centres, const std::vector<GroupType>& types,
                                      const std::vector<int32_t>& s2_node_of_group,
                                      const std::vector<int32_t>& cluster, double head_height_m,
                                      const GraphClusteringParams& params,
                                      const std::vector<double>& start_scalp_distance_m,
                                      double min_scalp_distance_m) {
  std::vector<uint8_t> continues(types.size(), 0);
  std::vector<Bounds> bounds = centre_bounds(centres);
  auto reach_m = static_cast<float>(params.connectivity.f1_max * head_height_m);
  int directions = params.either_orientation ? 2 : 1;
  for (size_t g = 0; g < types.size(); ++g) {
    if (!is_root_type(types[g]) || s2_node_of_group[g] < 0) continue;
    if (!start_scalp_distance_m.empty() && start_scalp_distance_m[g] < min_scalp_distance_m)
      continue;
    auto root_group = centres.strand(static_cast<int64_t>(g));
    for (size_t h = 0; h < types.size() && !continues[g]; ++h) {
      if (h == g || s2_node_of_group[h] < 0 || cluster[h] != cluster[g] ||
          bounds_gap(bounds[g], bounds[h]) >= reach_m)
        continue;
      // A root-type group read backwards ends at the scalp: a group that starts there
      // lies beside its root (the other side of a parting, or a crown), not after it.
      int h_directions = is_root_type(types[h]) ? 1 : directions;
      for (int h_reversed = 0; h_reversed < h_directions && !continues[g]; ++h_reversed) {
        Points3f before = centres.strand(static_cast<int64_t>(h));
        if (h_reversed) before = before.colwise().reverse().eval();
        ConnectionFeatures features =
            connection_features(before, root_group, head_height_m,
                                params.connectivity.flow_direction, params.connectivity.closeness);
        continues[g] = features.first_is_root_side &&
                       connectivity_weight(features, params.connectivity).has_value();
      }
    }
  }
  return continues;
}

ClusterCountSource source_of(const SpectralParams& params) {
  return params.clusters > 0 ? ClusterCountSource::parameter : ClusterCountSource::eigengap;
}

void check_inputs(const StrandSet& centres, const std::vector<GroupType>& types,
                  double head_height_m) {
  if (static_cast<int64_t>(types.size()) != centres.strand_count())
    throw Error::bad_input("", "types and centre strands differ in group count");
  if (!(head_height_m > 0)) throw Error::bad_input("", "the head height must be positive");
  for (int64_t g = 0; g < centres.strand_count(); ++g)
    if (centres.strand_size(g) < 2)
      throw Error::bad_input("", "centre strand " + std::to_string(g) + " has fewer than 2 points");
}

}  // namespace

const char* cluster_count_source_name(ClusterCountSource source) {
  switch (source) {
    case ClusterCountSource::eigengap:
      return "eigengap";
    case ClusterCountSource::parameter:
      return "parameter";
    case ClusterCountSource::skipped:
      return "skipped";
  }
  return "skipped";
}

MiddleClustering cluster_middle_groups(const StrandSet& centres,
                                       const std::vector<GroupType>& types, double head_height_m,
                                       const GraphClusteringParams& params) {
  check_cluster_middle_params(params);
  check_inputs(centres, types, head_height_m);
  MiddleClustering result;
  result.middle_cluster.assign(types.size(), -1);
  std::vector<int32_t> node_of_group(types.size(), -1);
  for (size_t g = 0; g < types.size(); ++g)
    if (types[g] == GroupType::middle) node_of_group[g] = static_cast<int32_t>(g);
  int32_t middle_count =
      static_cast<int32_t>(std::count(types.begin(), types.end(), GroupType::middle));
  result.graph.node_count = static_cast<int32_t>(types.size());
  if (middle_count == 0) return result;

  add_connectivity_edges(result.graph, centres, node_of_group, head_height_m, params);
  result.graph.set_affinities(params.affinity_scale);

  // Spectral clustering over the middle groups only.
  std::vector<int32_t> middle_groups, index_of_group(types.size(), -1);
  for (size_t g = 0; g < types.size(); ++g)
    if (node_of_group[g] >= 0) {
      index_of_group[g] = static_cast<int32_t>(middle_groups.size());
      middle_groups.push_back(static_cast<int32_t>(g));
    }
  std::vector<Eigen::Triplet<double>> triplets;
  for (size_t e = 0; e < result.graph.edges.size(); ++e) {
    int32_t a = index_of_group[static_cast<size_t>(result.graph.edges[e][0])];
    int32_t b = index_of_group[static_cast<size_t>(result.graph.edges[e][1])];
    triplets.emplace_back(a, b, result.graph.affinity[e]);
    triplets.emplace_back(b, a, result.graph.affinity[e]);
  }
  Eigen::SparseMatrix<double> affinity(middle_count, middle_count);
  affinity.setFromTriplets(triplets.begin(), triplets.end());
  SpectralResult spectral = spectral_clustering(affinity, params.spectral);
  for (size_t i = 0; i < middle_groups.size(); ++i)
    result.middle_cluster[static_cast<size_t>(middle_groups[i])] = spectral.label[i];
  result.cluster_count = spectral.cluster_count;
  result.count_source = source_of(params.spectral);
  result.eigenvalues = std::move(spectral.eigenvalues);
  return result;
}

std::vector<int32_t> each_middle_group_alone(const std::vector<GroupType>& types) {
  std::vector<int32_t> middle_cluster(types.size(), -1);
  int32_t next = 0;
  for (size_t g = 0; g < types.size(); ++g)
    if (types[g] == GroupType::middle) middle_cluster[g] = next++;
  return middle_cluster;
}

HairClustering cluster_hair(const StrandSet& centres, const std::vector<GroupType>& types,
                            const std::vector<int32_t>& middle_cluster, double head_height_m,
                            const HairClusteringParams& params,
                            const std::vector<double>& start_scalp_distance_m) {
  check_cluster_all_params(params);
  check_inputs(centres, types, head_height_m);
  if (!start_scalp_distance_m.empty() && start_scalp_distance_m.size() != types.size())
    throw Error::bad_input("", "scalp distances and types differ in group count");
  if (middle_cluster.size() != types.size())
    throw Error::bad_input("", "middle clusters and types differ in group count");
  HairClustering result;
  auto group_count = types.size();

  // Nodes: groups in order, the groups of a middle cluster sharing the node made at
  // the first of them.
  result.node_of_group.assign(group_count, -1);
  std::map<int32_t, int32_t> node_of_middle_cluster;
  for (size_t g = 0; g < group_count; ++g) {
    if (types[g] == GroupType::middle) {
      if (middle_cluster[g] < 0)
        throw Error::bad_input("", "middle group " + std::to_string(g) + " has no middle cluster");
      auto [it, inserted] = node_of_middle_cluster.try_emplace(
          middle_cluster[g], static_cast<int32_t>(result.node_in_s1.size()));
      if (inserted) {
        result.node_in_s1.push_back(0);
        result.node_middle_cluster.push_back(middle_cluster[g]);
      }
      result.node_of_group[g] = it->second;
    } else {
      result.node_of_group[g] = static_cast<int32_t>(result.node_in_s1.size());
      result.node_in_s1.push_back(types[g] == GroupType::root_free ? 1 : 0);
      result.node_middle_cluster.push_back(-1);
    }
  }
  auto node_count = static_cast<int32_t>(result.node_in_s1.size());
  result.graph.node_count = node_count;

  // S2-S2: connectivity; S1-S1: similarity; S1-S2: none.
  std::vector<int32_t> s2_node_of_group(group_count, -1);
  std::vector<int32_t> s1_groups;
  for (size_t g = 0; g < group_count; ++g) {
    if (types[g] == GroupType::root_free)
      s1_groups.push_back(static_cast<int32_t>(g));
    else
      s2_node_of_group[g] = result.node_of_group[g];
  }
  add_connectivity_edges(result.graph, centres, s2_node_of_group, head_height_m, params.graph);
  for (size_t i = 0; i < s1_groups.size(); ++i)
    for (size_t j = i + 1; j < s1_groups.size(); ++j) {
      int32_t g = s1_groups[i], h = s1_groups[j];
      std::optional<double> weight =
          similarity_weight(centres.strand(g), centres.strand(h), head_height_m, params.similarity);
      if (weight)
        result.graph.add_edge(result.node_of_group[static_cast<size_t>(g)],
                              result.node_of_group[static_cast<size_t>(h)], *weight,
                              EdgeKind::similarity);
    }
  result.graph.set_affinities(params.graph.affinity_scale);

  SpectralResult spectral =
      node_count > 0 ? spectral_clustering(result.graph.affinity_matrix(), params.graph.spectral)
                     : SpectralResult{};
  result.clusters_before_split = spectral.cluster_count;
  result.count_source =
      node_count > 0 ? source_of(params.graph.spectral) : ClusterCountSource::skipped;
  result.eigenvalues = std::move(spectral.eigenvalues);
  result.cluster_before_split.resize(group_count);
  for (size_t g = 0; g < group_count; ++g)
    result.cluster_before_split[g] = spectral.label[static_cast<size_t>(result.node_of_group[g])];

  // The division: the root-type groups of a cluster apart from its other groups, where
  // a root-type group that continues another group of its cluster is one of the others.
  result.continues_group.assign(group_count, 0);
  if (params.split_at_type_change && params.split_continued_roots)
    result.continues_group = continuing_roots(
        centres, types, s2_node_of_group, result.cluster_before_split, head_height_m, params.graph,
        start_scalp_distance_m, params.continued_root_min_scalp_distance_h * head_height_m);
  auto side_of = [&](size_t g) {
    return is_root_type(types[g]) && !result.continues_group[g] ? 0 : 1;
  };
  std::map<std::pair<int32_t, int>, int32_t> final_cluster;  // (cluster, 0 root / 1 rest)
  std::vector<std::array<bool, 2>> parts(static_cast<size_t>(spectral.cluster_count),
                                         {false, false});
  for (size_t g = 0; g < group_count; ++g)
    parts[static_cast<size_t>(result.cluster_before_split[g])][static_cast<size_t>(side_of(g))] =
        true;
  for (int32_t c = 0; c < spectral.cluster_count; ++c) {
    const auto& part = parts[static_cast<size_t>(c)];
    bool divide = params.split_at_type_change && part[0] && part[1];
    result.split_count += divide ? 1 : 0;
    for (int side : {0, 1}) {
      if (!part[static_cast<size_t>(side)]) continue;
      if (!divide && side == 1 && part[0]) continue;  // kept whole: one cluster
      final_cluster[{c, side}] = static_cast<int32_t>(result.cluster_origin.size());
      result.cluster_origin.push_back(c);
      result.cluster_starts_at_root.push_back(side == 0 ? 1 : 0);
      result.cluster_group_count.push_back(0);
    }
  }
  result.cluster.resize(group_count);
  for (size_t g = 0; g < group_count; ++g) {
    int32_t c = result.cluster_before_split[g];
    const auto& part = parts[static_cast<size_t>(c)];
    bool divided = params.split_at_type_change && part[0] && part[1];
    int side = divided ? side_of(g) : (part[0] ? 0 : 1);
    result.cluster[g] = final_cluster.at({c, side});
    ++result.cluster_group_count[static_cast<size_t>(result.cluster[g])];
  }
  return result;
}

}  // namespace hair
