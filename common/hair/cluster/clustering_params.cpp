#include "hair/cluster/clustering_params.h"

#include <cmath>
#include <optional>
#include <string>

namespace hair {

void add_graph_clustering_params(ParamSet& params, GraphClusteringParams& values) {
  ConnectivityParams& c = values.connectivity;
  params.add("k1", c.k1, "coefficient of f1, the closeness of two groups at the connection",
             ParamRange::closed(0, 1));
  params.add("k2", c.k2, "coefficient of f2, the overlap of two groups", ParamRange::closed(0, 1));
  params.add("k3", c.k3, "coefficient of f3, the angle between the flows at the connection",
             ParamRange::closed(0, 1));
  params.add("k4", c.k4,
             "coefficient of f4, the continuation offset: how far each group's end lies off "
             "the line of the other's flow at the connection",
             ParamRange::closed(0, 1));
  params.add("f1_max", c.f1_max, "no edge when f1 (in H) reaches this bound", ParamRange::above(0));
  params.add("f2_max", c.f2_max, "no edge when the overlap f2 reaches this bound",
             ParamRange::above(0));
  params.add("f3_max", c.f3_max, "no edge when the flow angle f3 (in pi) reaches this bound",
             ParamRange::closed(0, 1));
  params.add("f4_max", c.f4_max,
             "no edge when the continuation offset f4 (in H) reaches this bound (f1_max or "
             "more: none, with closeness = ends)",
             ParamRange::above(0));
  params.add("closeness", values.closeness_word,
             "f1 as the closest approach of one group's distal half to the other's proximal "
             "half (halves, the paper's) or as the gap between the end and the start (ends)",
             {"halves", "ends"});
  params.add("flow_direction", values.flow_direction_word,
             "f3 between the flows from the farthest point off the chord (farthest_point, "
             "the paper's) or over the quarters at the connection (end_quarter)",
             {"farthest_point", "end_quarter"});
  params.add("halve_best_tip_side", values.halve_best_tip_side,
             "halve the weight from a group to its best-connected group on the tip side "
             "(the paper's local-similarity heuristic)");
  params.add("either_orientation", values.either_orientation,
             "connect two groups whichever way extract oriented them (the best weight over "
             "both directions of each)");
  params.add("continuations", values.continuations,
             "keep a connection only if it ranks among this many best at both group ends it "
             "joins (mutual nearest neighbours); 0 keeps every connection within the bounds",
             ParamRange::closed(0, 1000));
  params.add("affinity_scale", values.affinity_scale,
             "sigma of the affinity exp(-w^2 / (2 sigma^2)); 0 takes the median edge weight",
             ParamRange::at_least(0));
  SpectralParams& s = values.spectral;
  params.add("clusters", s.clusters,
             "number of clusters; 0 chooses it by the eigengap of each connected component",
             ParamRange::at_least(0));
  params.add("max_clusters_per_component", s.max_clusters_per_component,
             "the eigengap looks at most this many clusters in one connected component",
             ParamRange::closed(1, 1000));
  params.add("min_eigengap", s.min_eigengap,
             "a connected component is divided only if its eigengap exceeds this (and the "
             "gap stands out: mu_{k+1} >= 6 mu_k, docs/clustering.md)",
             ParamRange::closed(0, 1));
  params.add("dense_limit", s.dense_limit,
             "components of up to this many nodes use a dense eigensolver (Eigen), larger "
             "ones Spectra on the sparse matrix",
             ParamRange::at_least(0));
  params.add("kmeans_restarts", s.kmeans.restarts, "k-means++ restarts; the best is kept",
             ParamRange::closed(1, 1000));
  params.add("kmeans_iterations", s.kmeans.max_iterations, "iterations of one k-means run",
             ParamRange::closed(1, 100000));
  params.add_check([&values]() -> std::optional<std::string> {
    // The words were checked against their lists on parsing.
    values.connectivity.closeness = *closeness_from_name(values.closeness_word);
    values.connectivity.flow_direction = *flow_direction_from_name(values.flow_direction_word);
    return std::nullopt;
  });
  params.add_check([&c]() -> std::optional<std::string> {
    double sum = c.k1 + c.k2 + c.k3 + c.k4;
    if (std::abs(sum - 1) > 1e-6)
      return "k1 + k2 + k3 + k4 must be 1, found " + std::to_string(sum);
    return std::nullopt;
  });
}

void declare_cluster_middle_params(ParamSet& p, GraphClusteringParams& params) {
  add_graph_clustering_params(p, params);
}

void declare_cluster_all_params(ParamSet& p, HairClusteringParams& params) {
  add_graph_clustering_params(p, params.graph);
  p.add("similarity_distance_max_h", params.similarity.distance_max_h,
                   "no edge between free-root groups whose roots or tips are this far apart, "
                   "in H",
                   ParamRange::above(0));
  p.add("split_at_type_change", params.split_at_type_change,
                   "divide a cluster where its root-type groups meet its other groups");
  p.add(
      "split_continued_roots", params.split_continued_roots,
      "in that division, a root-type group whose start continues another group of "
      "its cluster (within the connectivity bounds) goes with the distal part, which does "
      "not start at the root (docs/clustering.md)");
  p.add("continued_root_min_scalp_distance_h",
                   params.continued_root_min_scalp_distance_h,
                   "...when its centre strand starts at least this far from the scalp, in H",
                   ParamRange::at_least(0));
}

void check_cluster_middle_params(const GraphClusteringParams& params) {
  check_params(params, declare_cluster_middle_params);
}

void check_cluster_all_params(const HairClusteringParams& params) {
  check_params(params, declare_cluster_all_params);
}

}  // namespace hair
