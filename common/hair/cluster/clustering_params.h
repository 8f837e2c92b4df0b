#pragma once

#include "hair/cluster/hair_clustering.h"
#include "hair/core/params.h"

namespace hair {

/// Registers the parameters both clustering stages share (the connectivity weight,
/// its bounds, the heuristic, the affinity scale and spectral clustering) with their
/// ranges, and the check that k1 + k2 + k3 + k4 = 1.
void add_graph_clustering_params(ParamSet& params, GraphClusteringParams& values);

/// Registers every cluster-middle parameter (add_graph_clustering_params()).
void declare_cluster_middle_params(ParamSet& p, GraphClusteringParams& params);

/// Registers every cluster-all parameter: the shared ones and the similarity bound, the
/// division at type changes and where continued roots go.
void declare_cluster_all_params(ParamSet& p, HairClusteringParams& params);

/// Hold `params` to the ranges the declarations give them (check_params()); the clustering
/// entry points call them. Throw hair::Error (usage).
void check_cluster_middle_params(const GraphClusteringParams& params);
void check_cluster_all_params(const HairClusteringParams& params);

}  // namespace hair
