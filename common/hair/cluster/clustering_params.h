#pragma once

#include "hair/cluster/hair_clustering.h"
#include "hair/core/params.h"

namespace hair {

/// Registers the parameters both clustering stages share (the connectivity weight,
/// its bounds, the heuristic, the affinity scale and spectral clustering) with their
/// ranges, and the check that k1 + k2 + k3 + k4 = 1.
void add_graph_clustering_params(ParamSet& params, GraphClusteringParams& values);

}  // namespace hair
