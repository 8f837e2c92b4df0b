// Spectral clustering on graphs whose clusters are known: weakly linked blocks,
// disconnected pieces, concentric rings, and graphs without clusters (paths, rings).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "hair/cluster/adjusted_rand_index.h"
#include "hair/cluster/kmeans.h"
#include "hair/cluster/spectral_clustering.h"
#include "hair/core/error.h"

namespace hair {
namespace {

using Sparse = Eigen::SparseMatrix<double>;

/// Uniform and normal draws from a fixed generator, the same on every platform.
class Random {
 public:
  explicit Random(uint64_t seed) : random_(seed) {}
  double uniform() { return static_cast<double>(random_() >> 11) * 0x1.0p-53; }
  double normal() {
    double u = uniform(), v = uniform();
    return std::sqrt(-2 * std::log(1 - u)) * std::cos(2 * std::numbers::pi * v);
  }
  /// A random permutation of 0 .. n-1 (Fisher-Yates).
  std::vector<int32_t> permutation(int n) {
    std::vector<int32_t> order(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) order[static_cast<size_t>(i)] = i;
    for (int i = n - 1; i > 0; --i)
      std::swap(order[static_cast<size_t>(i)], order[static_cast<size_t>(uniform() * (i + 1))]);
    return order;
  }

 private:
  std::mt19937_64 random_;
};

/// A graph under construction: symmetric weighted edges, nodes renamed by `name`.
struct Graph {
  explicit Graph(int n) : node_count(n) {
    for (int i = 0; i < n; ++i) name.push_back(i);
  }
  void link(int i, int j, double weight) {
    int a = name[static_cast<size_t>(i)], b = name[static_cast<size_t>(j)];
    entries.emplace_back(a, b, weight);
    entries.emplace_back(b, a, weight);
  }
  Sparse matrix() const {
    Sparse a(node_count, node_count);
    a.setFromTriplets(entries.begin(), entries.end());
    return a;
  }
  /// Cluster of every node under its new name.
  std::vector<int32_t> renamed(const std::vector<int32_t>& truth) const {
    std::vector<int32_t> result(truth.size());
    for (size_t i = 0; i < truth.size(); ++i) result[static_cast<size_t>(name[i])] = truth[i];
    return result;
  }
  int node_count;
  std::vector<int32_t> name;
  std::vector<Eigen::Triplet<double>> entries;
};

/// Blocks of the given sizes, dense inside (weights in [0.5, 1]), joined by `links`
/// random edges of weight `link_weight` between consecutive blocks; nodes shuffled.
Graph weakly_linked_blocks(const std::vector<int>& sizes, int links, double link_weight,
                           uint64_t seed, std::vector<int32_t>& truth) {
  Random random(seed);
  int n = 0;
  std::vector<int> first;
  for (int size : sizes) {
    first.push_back(n);
    n += size;
  }
  Graph graph(n);
  graph.name = random.permutation(n);
  truth.clear();
  for (size_t b = 0; b < sizes.size(); ++b) {
    for (int i = 0; i < sizes[b]; ++i) {
      truth.push_back(static_cast<int32_t>(b));
      for (int j = 0; j < i; ++j)
        graph.link(first[b] + i, first[b] + j, 0.5 + 0.5 * random.uniform());
    }
    if (b + 1 < sizes.size())
      for (int l = 0; l < links; ++l)
        graph.link(first[b] + static_cast<int>(random.uniform() * sizes[b]),
                   first[b + 1] + static_cast<int>(random.uniform() * sizes[b + 1]), link_weight);
  }
  truth = graph.renamed(truth);
  return graph;
}

/// Gaussian affinities exp(-d^2 / 2 sigma^2) between each point and its `k` nearest
/// (either way round); sigma the median distance to the k-th neighbour. Brute force.
Sparse knn_affinity(const Eigen::MatrixXd& points, int k) {
  auto n = static_cast<int>(points.rows());
  std::vector<std::vector<std::pair<double, int>>> nearest(static_cast<size_t>(n));
  std::vector<double> kth;
  for (int i = 0; i < n; ++i) {
    auto& candidates = nearest[static_cast<size_t>(i)];
    for (int j = 0; j < n; ++j)
      if (j != i) candidates.emplace_back((points.row(i) - points.row(j)).squaredNorm(), j);
    std::partial_sort(candidates.begin(), candidates.begin() + k, candidates.end());
    candidates.resize(static_cast<size_t>(k));
    kth.push_back(std::sqrt(candidates.back().first));
  }
  std::nth_element(kth.begin(), kth.begin() + n / 2, kth.end());
  double sigma = kth[static_cast<size_t>(n / 2)];
  Sparse a(n, n);
  for (int i = 0; i < n; ++i)
    for (auto [distance2, j] : nearest[static_cast<size_t>(i)]) {
      double weight = std::exp(-distance2 / (2 * sigma * sigma));
      a.coeffRef(i, j) = weight;
      a.coeffRef(j, i) = weight;
    }
  a.makeCompressed();
  return a;
}

int count_of(const std::vector<int32_t>& label) {
  return label.empty() ? 0 : *std::max_element(label.begin(), label.end()) + 1;
}

bool numbered_by_first_appearance(const std::vector<int32_t>& label) {
  int32_t next = 0;
  for (int32_t value : label) {
    if (value > next || value < 0) return false;
    if (value == next) ++next;
  }
  return true;
}

TEST(SpectralClustering, WeaklyLinkedBlocksSplitByEigengap) {
  std::vector<int32_t> truth;
  Graph graph = weakly_linked_blocks({20, 30}, 3, 0.01, 1, truth);
  SpectralResult result = spectral_clustering(graph.matrix(), {});
  EXPECT_TRUE(result.count_from_eigengap);
  EXPECT_EQ(result.components, 1);
  EXPECT_EQ(result.cluster_count, 2);
  EXPECT_DOUBLE_EQ(adjusted_rand_index(result.label, truth), 1.0);
  EXPECT_TRUE(numbered_by_first_appearance(result.label));
  EXPECT_EQ(count_of(result.label), result.cluster_count);
  ASSERT_EQ(result.eigenvalues.size(), 17u);  // max_clusters_per_component + 1
  EXPECT_NEAR(result.eigenvalues[0], 1.0, 1e-12);
  EXPECT_FALSE(result.used_sparse_solver);
}

TEST(SpectralClustering, EigengapFindsThreeBlocks) {
  std::vector<int32_t> truth;
  Graph graph = weakly_linked_blocks({15, 25, 20}, 2, 0.02, 2, truth);
  SpectralResult result = spectral_clustering(graph.matrix(), {});
  EXPECT_EQ(result.cluster_count, 3);
  EXPECT_DOUBLE_EQ(adjusted_rand_index(result.label, truth), 1.0);
}

TEST(SpectralClustering, ComponentsAndIsolatedNodesAreClusters) {
  // Cliques of 5, 7 and 9 nodes and 2 isolated nodes, names shuffled.
  int n = 23;
  Graph graph(n);
  graph.name = Random(3).permutation(n);
  std::vector<int32_t> truth;
  int first = 0, cluster = 0;
  for (int size : {5, 7, 9}) {
    for (int i = 0; i < size; ++i) {
      truth.push_back(cluster);
      for (int j = 0; j < i; ++j) graph.link(first + i, first + j, 1.0);
    }
    first += size;
    ++cluster;
  }
  truth.push_back(cluster++);
  truth.push_back(cluster++);
  truth = graph.renamed(truth);
  Sparse a = graph.matrix();

  SpectralResult result = spectral_clustering(a, {});
  EXPECT_EQ(result.components, 5);
  EXPECT_EQ(result.cluster_count, 5);
  EXPECT_DOUBLE_EQ(adjusted_rand_index(result.label, truth), 1.0);
  EXPECT_TRUE(numbered_by_first_appearance(result.label));
  // min(16, m - 1) + 1 per clique and a 1 per isolated node; 1 once per component.
  ASSERT_EQ(result.eigenvalues.size(), 5u + 7u + 9u + 2u);
  EXPECT_TRUE(std::is_sorted(result.eigenvalues.rbegin(), result.eigenvalues.rend()));
  EXPECT_EQ(std::count_if(result.eigenvalues.begin(), result.eigenvalues.end(),
                          [](double value) { return std::abs(value - 1) < 1e-9; }),
            5);
  EXPECT_EQ(connected_components(a), [&] {
    std::vector<int32_t> component = truth;  // cliques are the components
    int32_t next = 0;
    std::vector<int32_t> renumbered(5, -1);
    for (int32_t& value : component) {
      if (renumbered[static_cast<size_t>(value)] < 0)
        renumbered[static_cast<size_t>(value)] = next++;
      value = renumbered[static_cast<size_t>(value)];
    }
    return component;
  }());

  // A fixed count of 5 finds the same clusters: 2 isolated + NJW with 3 over the cliques.
  SpectralParams params;
  params.clusters = 5;
  SpectralResult fixed = spectral_clustering(a, params);
  EXPECT_FALSE(fixed.count_from_eigengap);
  EXPECT_EQ(fixed.cluster_count, 5);
  EXPECT_EQ(fixed.components, 5);
  EXPECT_EQ(fixed.label, result.label);
}

/// Two noisy concentric rings, 1 and 2 in radius, interleaved.
struct Rings {
  Eigen::MatrixXd points;
  std::vector<int32_t> truth;
};

Rings concentric_rings(int per_ring, uint64_t seed) {
  Random random(seed);
  Rings rings;
  rings.points.resize(2 * per_ring, 2);
  for (int i = 0; i < 2 * per_ring; ++i) {
    int ring = i % 2;
    double radius = (ring == 0 ? 1.0 : 2.0) + 0.1 * random.normal();
    double angle = 2 * std::numbers::pi * random.uniform();
    rings.points.row(i) << radius * std::cos(angle), radius * std::sin(angle);
    rings.truth.push_back(ring);
  }
  return rings;
}

TEST(SpectralClustering, SeparatesConcentricRingsWhereKMeansCannot) {
  Rings rings = concentric_rings(150, 4);
  Sparse a = knn_affinity(rings.points, 10);
  ASSERT_EQ(connected_components(a), std::vector<int32_t>(300, 0));  // one piece: no shortcut
  SpectralParams params;
  params.clusters = 2;
  SpectralResult result = spectral_clustering(a, params);
  EXPECT_EQ(result.cluster_count, 2);
  EXPECT_EQ(result.components, 1);
  EXPECT_DOUBLE_EQ(adjusted_rand_index(result.label, rings.truth), 1.0);
  EXPECT_EQ(result.eigenvalues.size(), 3u);
  // k-means on the coordinates cuts both rings in half instead.
  EXPECT_LT(adjusted_rand_index(kmeans(rings.points, 2, {}).label, rings.truth), 0.1);
}

/// A path (or, closed, a ring) of n nodes with unit weights, nodes in order.
Sparse chain(int n, bool closed) {
  Graph graph(n);
  for (int i = 0; i + 1 < n; ++i) graph.link(i, i + 1, 1.0);
  if (closed) graph.link(n - 1, 0, 1.0);
  return graph.matrix();
}

TEST(SpectralClustering, PathsAndRingsStayOneCluster) {
  for (bool closed : {false, true})
    for (int n : {8, 20, 60, 200, 1000}) {
      SCOPED_TRACE((closed ? "ring of " : "path of ") + std::to_string(n));
      for (double min_eigengap : {0.05, 0.0}) {
        SpectralParams params;
        params.min_eigengap = min_eigengap;
        SpectralResult result = spectral_clustering(chain(n, closed), params);
        EXPECT_EQ(result.cluster_count, 1) << "min_eigengap " << min_eigengap;
        EXPECT_EQ(result.components, 1);
        EXPECT_EQ(result.used_sparse_solver, n > params.dense_limit);
        // The plain argmax of the eigengap would have split it: gaps grow with k.
        const std::vector<double>& lambda = result.eigenvalues;
        double largest_later_gap = 0;
        for (size_t k = 2; k < lambda.size(); ++k)
          largest_later_gap = std::max(largest_later_gap, lambda[k - 1] - lambda[k]);
        EXPECT_GT(largest_later_gap, lambda[0] - lambda[1]);
      }
    }
}

TEST(SpectralClustering, SparseSolverConvergesOnALongRing) {
  // 17 eigenvalues within 2e-4 of 1, in pairs: the first Krylov space is too small.
  SpectralParams params;
  params.dense_limit = 0;
  SpectralResult result = spectral_clustering(chain(3000, true), params);
  EXPECT_TRUE(result.used_sparse_solver);
  EXPECT_EQ(result.cluster_count, 1);
  ASSERT_EQ(result.eigenvalues.size(), 17u);
  for (size_t j = 0; j < 17; ++j)  // cos(2 pi ceil(j / 2) / 3000)
    EXPECT_NEAR(result.eigenvalues[j],
                std::cos(2 * std::numbers::pi * static_cast<double>((j + 1) / 2) / 3000), 1e-9)
        << j;
}

TEST(SpectralClustering, MinEigengapGuardsSplits) {
  std::vector<int32_t> truth;
  Graph graph = weakly_linked_blocks({20, 30}, 3, 0.01, 1, truth);
  Sparse a = graph.matrix();
  std::vector<double> lambda = spectral_clustering(a, {}).eigenvalues;
  double gap = lambda[1] - lambda[2];
  SpectralParams params;
  params.min_eigengap = gap * 0.99;
  EXPECT_EQ(spectral_clustering(a, params).cluster_count, 2);
  params.min_eigengap = gap * 1.01;
  EXPECT_EQ(spectral_clustering(a, params).cluster_count, 1);
  params.max_clusters_per_component = 1;  // no split allowed at all
  params.min_eigengap = 0;
  EXPECT_EQ(spectral_clustering(a, params).cluster_count, 1);
  EXPECT_EQ(spectral_clustering(a, params).eigenvalues.size(), 2u);
}

TEST(EigengapClusterCount, ReadsTheRuleFromHandMadeSpectra) {
  // Three clusters: three eigenvalues near 1, then a drop.
  EXPECT_EQ(eigengap_cluster_count({1.0, 0.99, 0.98, 0.4, 0.35, 0.3}, 5, 0.05), 3);
  // The largest admissible gap wins over an earlier smaller one.
  EXPECT_EQ(eigengap_cluster_count({1.0, 0.999, 0.9, 0.899, 0.2, 0.1}, 5, 0.05), 4);
  // Gaps large enough but growing like a path's (mu_{k+1} / mu_k < 6): no split.
  EXPECT_EQ(eigengap_cluster_count({1.0, 0.9, 0.6, 0.1, -0.5}, 4, 0.05), 1);
  // A clear split whose gap is below min_eigengap: none.
  EXPECT_EQ(eigengap_cluster_count({1.0, 0.999, 0.97, 0.96}, 3, 0.05), 1);
  EXPECT_EQ(eigengap_cluster_count({1.0, 0.999, 0.97, 0.96}, 3, 0.01), 2);
  // max_clusters bounds the search; too few eigenvalues bound it too.
  EXPECT_EQ(eigengap_cluster_count({1.0, 0.99, 0.98, 0.4}, 2, 0.05), 1);
  EXPECT_EQ(eigengap_cluster_count({1.0, 0.99, 0.98}, 16, 0.05), 1);
  EXPECT_EQ(eigengap_cluster_count({1.0}, 16, 0.05), 1);
  // Equal gaps: the smaller k.
  EXPECT_EQ(eigengap_cluster_count({1.0, 1.0, 0.5, 0.5, 0.0}, 4, 0.05), 2);
}

TEST(SpectralClustering, DenseAndSparseSolversAgree) {
  std::vector<int32_t> truth;
  Graph graph = weakly_linked_blocks({40, 60, 50}, 4, 0.01, 5, truth);
  // A fourth, separate component: a path of 30 (simple eigenvalues, unlike a ring's,
  // so that a fixed count that cuts it gives one embedding up to sign).
  Sparse blocks = graph.matrix(), path = chain(30, false);
  Sparse a(180, 180);
  std::vector<Eigen::Triplet<double>> entries;
  for (const Sparse* part : {&blocks, &path})
    for (Eigen::Index col = 0; col < part->outerSize(); ++col)
      for (Sparse::InnerIterator it(*part, col); it; ++it) {
        Eigen::Index offset = part == &path ? 150 : 0;
        entries.emplace_back(it.row() + offset, it.col() + offset, it.value());
      }
  a.setFromTriplets(entries.begin(), entries.end());
  truth.resize(180, 3);

  for (int clusters : {0, 4, 5}) {
    SCOPED_TRACE("clusters " + std::to_string(clusters));
    SpectralParams dense, sparse;
    dense.clusters = sparse.clusters = clusters;
    dense.dense_limit = 100000;
    sparse.dense_limit = 0;
    SpectralResult by_dense = spectral_clustering(a, dense);
    SpectralResult by_sparse = spectral_clustering(a, sparse);
    EXPECT_FALSE(by_dense.used_sparse_solver);
    EXPECT_TRUE(by_sparse.used_sparse_solver);
    EXPECT_DOUBLE_EQ(adjusted_rand_index(by_dense.label, by_sparse.label), 1.0);
    ASSERT_EQ(by_dense.eigenvalues.size(), by_sparse.eigenvalues.size());
    for (size_t i = 0; i < by_dense.eigenvalues.size(); ++i)
      EXPECT_NEAR(by_dense.eigenvalues[i], by_sparse.eigenvalues[i], 1e-8) << i;
    if (clusters == 5) {  // the path cut in two halves
      std::vector<int32_t> halves = truth;
      for (size_t i = 165; i < 180; ++i) halves[i] = 4;
      EXPECT_DOUBLE_EQ(adjusted_rand_index(by_dense.label, halves), 1.0);
    } else {
      EXPECT_EQ(by_dense.cluster_count, 4);
      EXPECT_DOUBLE_EQ(adjusted_rand_index(by_dense.label, truth), 1.0);
    }
  }
}

TEST(SpectralClustering, SameInputSameResult) {
  Rings rings = concentric_rings(100, 6);
  Sparse a = knn_affinity(rings.points, 8);
  for (int clusters : {0, 2, 5}) {
    SpectralParams params;
    params.clusters = clusters;
    SpectralResult first = spectral_clustering(a, params), second = spectral_clustering(a, params);
    EXPECT_EQ(first.label, second.label);
    EXPECT_EQ(first.eigenvalues, second.eigenvalues);
  }
}

/// The kind of the hair::Error spectral_clustering() throws, or nothing.
std::optional<ErrorKind> error_of(const Sparse& a, int clusters = 0) {
  SpectralParams params;
  params.clusters = clusters;
  try {
    spectral_clustering(a, params);
  } catch (const Error& error) {
    return error.kind();
  }
  return std::nullopt;
}

TEST(SpectralClustering, InvalidAffinityIsBadInput) {
  Sparse good = chain(5, false);
  EXPECT_EQ(error_of(good), std::nullopt);
  EXPECT_EQ(error_of(Sparse(3, 4)), ErrorKind::bad_input);
  Sparse asymmetric = good;
  asymmetric.coeffRef(0, 1) = 0.9;
  EXPECT_EQ(error_of(asymmetric), ErrorKind::bad_input);
  Sparse one_sided(3, 3);
  one_sided.insert(2, 0) = 1.0;
  EXPECT_EQ(error_of(one_sided), ErrorKind::bad_input);
  Sparse negative = good;
  negative.coeffRef(1, 2) = negative.coeffRef(2, 1) = -0.5;
  EXPECT_EQ(error_of(negative), ErrorKind::bad_input);
  Sparse not_a_number = good;
  not_a_number.coeffRef(3, 4) = not_a_number.coeffRef(4, 3) = std::nan("");
  EXPECT_EQ(error_of(not_a_number), ErrorKind::bad_input);
  Sparse infinite = good;
  infinite.coeffRef(3, 4) = infinite.coeffRef(4, 3) = std::numeric_limits<double>::infinity();
  EXPECT_EQ(error_of(infinite), ErrorKind::bad_input);
  try {
    spectral_clustering(asymmetric, {});
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("not symmetric"), std::string::npos) << error.what();
  }

  // Rounding-level asymmetry, self-loops and stored zeros are accepted (and ignored).
  Sparse tolerable = good;
  tolerable.coeffRef(0, 1) = 1.0 + 1e-13;
  tolerable.coeffRef(2, 2) = 5.0;
  tolerable.coeffRef(0, 4) = 0.0;
  SpectralResult result = spectral_clustering(tolerable, {});
  EXPECT_EQ(result.components, 1);
  EXPECT_EQ(result.cluster_count, 1);
}

TEST(SpectralClustering, FixedCountOutOfRangeIsAUsageError) {
  // A path of 10 nodes and 2 isolated ones: between 3 and 12 clusters.
  Sparse path = chain(10, false);
  Sparse a(12, 12);
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index col = 0; col < path.outerSize(); ++col)
    for (Sparse::InnerIterator it(path, col); it; ++it)
      entries.emplace_back(it.row() + 1, it.col() + 1, it.value());  // nodes 0 and 11 isolated
  a.setFromTriplets(entries.begin(), entries.end());
  EXPECT_EQ(error_of(a, 2), ErrorKind::usage);
  EXPECT_EQ(error_of(a, 13), ErrorKind::usage);
  EXPECT_EQ(error_of(a, -1), ErrorKind::usage);
  try {
    SpectralParams params;
    params.clusters = 2;
    spectral_clustering(a, params);
  } catch (const Error& error) {
    std::string what = error.what();
    EXPECT_NE(what.find("2 clusters"), std::string::npos) << what;
    EXPECT_NE(what.find("between 3 and 12"), std::string::npos) << what;
  }
  SpectralParams params;
  params.clusters = 3;
  SpectralResult three = spectral_clustering(a, params);
  EXPECT_EQ(three.cluster_count, 3);
  EXPECT_EQ(three.components, 3);
  EXPECT_EQ(three.label, (std::vector<int32_t>{0, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 2}));
  params.clusters = 4;  // the path cut in two halves
  SpectralResult four = spectral_clustering(a, params);
  EXPECT_EQ(four.label, (std::vector<int32_t>{0, 1, 1, 1, 1, 1, 2, 2, 2, 2, 2, 3}));
  params.clusters = 12;
  std::vector<int32_t> singletons(12);
  for (int i = 0; i < 12; ++i) singletons[static_cast<size_t>(i)] = i;
  EXPECT_EQ(spectral_clustering(a, params).label, singletons);
  // Isolated nodes only: exactly their number.
  EXPECT_EQ(error_of(Sparse(4, 4), 4), std::nullopt);
  EXPECT_EQ(error_of(Sparse(4, 4), 3), ErrorKind::usage);
}

TEST(SpectralClustering, EmptyGraphGivesEmptyResult) {
  SpectralResult result = spectral_clustering(Sparse(0, 0), {});
  EXPECT_TRUE(result.label.empty());
  EXPECT_EQ(result.cluster_count, 0);
  EXPECT_EQ(result.components, 0);
  EXPECT_TRUE(result.eigenvalues.empty());
}

TEST(ConnectedComponents, LinksEitherTriangleAndNumbersByFirstAppearance) {
  Sparse a(6, 6);
  a.insert(5, 1) = 0.3;  // one triangle only: still a link
  a.insert(4, 3) = 1.0;
  a.insert(3, 4) = 1.0;
  a.insert(0, 2) = 0.0;  // a stored zero is no link
  a.insert(2, 2) = 1.0;  // nor is a self-loop
  EXPECT_EQ(connected_components(a), (std::vector<int32_t>{0, 1, 2, 3, 3, 1}));
  EXPECT_THROW(connected_components(Sparse(2, 3)), Error);
}

TEST(SpectralClustering, SparseNeighbourGraphTiming) {
  // Four Gaussian blobs in 3-D, 500 points each, on a 10-nearest-neighbour graph.
  Random random(9);
  const int n = 2000;
  Eigen::MatrixXd points(n, 3);
  std::vector<int32_t> truth;
  for (int i = 0; i < n; ++i) {
    int blob = i % 4;
    for (int d = 0; d < 3; ++d)
      points(i, d) = random.normal() + (d == blob % 3 ? 6.0 : 0.0) * (blob == 3 ? -1 : 1);
    truth.push_back(blob);
  }
  Sparse a = knn_affinity(points, 10);
  SpectralParams params;
  params.min_eigengap = 0;  // neighbour graphs have small gaps; the ratio rule decides
  auto start = std::chrono::steady_clock::now();
  SpectralResult result = spectral_clustering(a, params);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "[ spectral ] %d-node 10-NN graph (%lld entries), %d component(s): %d clusters, "
      "ARI %.4f, sparse solver %s, %.3f s\n",
      n, static_cast<long long>(a.nonZeros()), result.components, result.cluster_count,
      adjusted_rand_index(result.label, truth), result.used_sparse_solver ? "yes" : "no", seconds);
  EXPECT_TRUE(result.used_sparse_solver);
  EXPECT_EQ(result.cluster_count, 4);
  EXPECT_DOUBLE_EQ(adjusted_rand_index(result.label, truth), 1.0);
}

}  // namespace
}  // namespace hair
