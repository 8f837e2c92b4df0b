#pragma once

#include <Eigen/SparseCore>
#include <array>
#include <cstdint>
#include <vector>

namespace hair {

/// Kind of an edge of a clustering graph (section 4.3).
enum class EdgeKind : int8_t {
  similarity = 0,    ///< between free-root groups, equations (4)-(5)
  connectivity = 1,  ///< between other groups or middle clusters, equations (1)-(3)
};

/// A weighted undirected graph over clustering nodes, each edge once (smaller node
/// first), with the weight w (a cost) and the affinity spectral clustering sees.
struct GroupGraph {
  int32_t node_count = 0;
  std::vector<std::array<int32_t, 2>> edges;
  std::vector<double> weight;                  ///< per edge, after the local-similarity halving
  std::vector<std::array<float, 4>> features;  ///< f1-f4 per edge (0 for similarity edges)
  std::vector<EdgeKind> kind;                  ///< per edge
  std::vector<double> affinity;                ///< per edge, set by set_affinities()
  double affinity_scale = 0;                   ///< sigma, set by set_affinities()

  /// Adds an edge; `a` != `b`.
  void add_edge(int32_t a, int32_t b, double edge_weight, EdgeKind edge_kind,
                std::array<float, 4> edge_features = {0, 0, 0, 0});
  /// Sets affinity = exp(-w^2 / (2 sigma^2)) for every edge, sigma = `scale` when it is
  /// positive, else the median of the edge weights (1 without edges, and a floor of
  /// 1e-6 so that a graph of perfect connections keeps finite affinities).
  void set_affinities(double scale);
  /// The symmetric node_count x node_count affinity matrix, zero diagonal.
  Eigen::SparseMatrix<double> affinity_matrix() const;
};

}  // namespace hair
