#include "hair/cluster/group_graph.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace hair {

void GroupGraph::add_edge(int32_t a, int32_t b, double edge_weight, EdgeKind edge_kind,
                          std::array<float, 4> edge_features) {
  edges.push_back({std::min(a, b), std::max(a, b)});
  weight.push_back(edge_weight);
  kind.push_back(edge_kind);
  features.push_back(edge_features);
}

void GroupGraph::set_affinities(double scale) {
  if (scale <= 0) {
    std::vector<double> sorted = weight;
    if (sorted.empty()) {
      scale = 1;
    } else {
      auto middle = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2);
      std::nth_element(sorted.begin(), middle, sorted.end());
      scale = std::max(*middle, 1e-6);
    }
  }
  affinity_scale = scale;
  affinity.resize(weight.size());
  for (size_t e = 0; e < weight.size(); ++e)
    affinity[e] = std::exp(-weight[e] * weight[e] / (2 * scale * scale));
}

Eigen::SparseMatrix<double> GroupGraph::affinity_matrix() const {
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(2 * edges.size());
  for (size_t e = 0; e < edges.size(); ++e) {
    triplets.emplace_back(edges[e][0], edges[e][1], affinity[e]);
    triplets.emplace_back(edges[e][1], edges[e][0], affinity[e]);
  }
  Eigen::SparseMatrix<double> matrix(node_count, node_count);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  return matrix;
}

}  // namespace hair
