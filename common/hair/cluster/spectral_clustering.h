#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cstdint>
#include <vector>

#include "hair/cluster/kmeans.h"

namespace hair {

/// A split of a component into k >= 2 clusters needs its normalised-Laplacian
/// eigenvalues mu = 1 - lambda to jump by at least this factor after the k-th:
/// mu_{k+1} >= ratio * mu_k. Graphs without cluster structure stay below it: on a
/// path or a ring mu_{k+1} / mu_k < 4 for every k (it approaches 4 for long ones), and
/// likewise on grids and on neighbour graphs of points filling a convex region.
/// Weakly linked clusters give large ratios (mu_k is about cut / volume).
inline constexpr double kEigengapMinRatio = 6.0;

/// Settings of spectral_clustering().
struct SpectralParams {
  /// Clusters wanted; 0: chosen per connected component by the eigengap
  /// (see eigengap_cluster_count()).
  int clusters = 0;
  /// Most clusters a component is split into when clusters == 0 (>= 1).
  int max_clusters_per_component = 16;
  /// A split into k >= 2 clusters needs lambda_k - lambda_{k+1} above this (an absolute
  /// gap of the normalised affinity's eigenvalues, which lie in [-1, 1]). Large sparse
  /// graphs (neighbour graphs of thousands of points) have all their leading gaps small,
  /// weakly linked clusters included: lower it there and let kEigengapMinRatio decide.
  /// 0.01 cuts the chains of pieces of a braid where two streams were joined by one false
  /// link (docs/clustering.md: middle ARI on the synthetic braids 0.63 at 0.05, 0.77 at
  /// 0.01, the other presets unchanged).
  double min_eigengap = 0.01;
  /// Connected components of more nodes than this have their eigenpairs computed by the
  /// sparse Lanczos solver (Spectra) instead of a dense eigendecomposition.
  int dense_limit = 600;
  /// The k-means on the embedded nodes.
  KMeansParams kmeans;
};

/// Clusters of a graph's nodes, with the spectrum they were read from.
struct SpectralResult {
  std::vector<int32_t> label;  ///< n, clusters numbered by first appearance (node 0 gets 0)
  int cluster_count = 0;
  bool count_from_eigengap = false;  ///< true when SpectralParams::clusters was 0
  /// Leading eigenvalues of D^-1/2 A D^-1/2, descending: with clusters == 0, the
  /// min(max_clusters_per_component, m - 1) + 1 leading ones of each component of m > 1
  /// nodes; with clusters > 0, the min(clusters - isolated + 1, r) leading ones of the
  /// matrix over the r non-isolated nodes. An isolated node adds the eigenvalue 1
  /// (Chung's convention: 1 has the multiplicity of the components).
  std::vector<double> eigenvalues;
  int components = 0;  ///< connected components of the affinity graph (isolated nodes count)
  bool used_sparse_solver = false;  ///< whether any eigenproblem went to Spectra
};

/// Ng-Jordan-Weiss spectral clustering of a symmetric affinity matrix (n x n, sparse,
/// non-negative; diagonal entries are ignored, as NJW sets A_ii = 0). With D the degrees,
/// M = D^-1/2 A D^-1/2; its k leading eigenvectors are the columns of an n x k matrix
/// whose rows, normalised to unit length, are clustered by kmeans() (k-means++,
/// SpectralParams::kmeans.restarts runs). A row of zeros stays zero.
///
/// clusters == 0: each connected component on its own. One node is one cluster; a
/// component of m nodes is split into eigengap_cluster_count() clusters of the
/// spectrum of its own M (k = 1: one cluster, no k-means).
///
/// clusters > 0: each of the s isolated nodes (degree 0) is a cluster; NJW with
/// k = clusters - s runs on the matrix over the other r nodes as a whole (it separates
/// its components when k is at least their number; with fewer, which components share
/// a cluster is unspecified). Needs s + (r > 0 ? 1 : 0) <= clusters <= n. That matrix
/// is block diagonal, so its leading eigenpairs are those of its components' blocks
/// merged (equal eigenvalues in component order); they are computed that way, because
/// Lanczos finds a single eigenvector of a repeated eigenvalue, and the eigenvalue 1 of
/// the matrix is repeated once per component.
///
/// A component's eigenproblem uses Eigen::SelfAdjointEigenSolver when it has at most
/// dense_limit nodes or all its m eigenpairs are wanted, Spectra::SymEigsSolver otherwise
/// (largest algebraic, ncv = min(m, max(2 nev + 1, 20)), and once more with twice that
/// should it not converge: long chains pack their eigenvalues close to 1). Deterministic
/// for a given build.
///
/// n == 0 gives an empty result (whatever clusters is). Throws hair::Error: bad input
/// for a matrix that is not square, has a NaN, infinite or negative entry, or is not
/// symmetric (|a_ij - a_ji| > 1e-9 max(|a_ij|, |a_ji|)); usage for clusters outside the
/// range above, clusters < 0 or max_clusters_per_component < 1; runtime when the sparse
/// solver does not converge.
SpectralResult spectral_clustering(const Eigen::SparseMatrix<double>& affinity,
                                   const SpectralParams& params);

/// The number of clusters the eigengap rule reads from the leading eigenvalues of one
/// connected component's normalised affinity, lambda_1 = 1 >= lambda_2 >= ... (at least
/// max_clusters + 1 of them, or all). With mu_i = 1 - lambda_i, k in [2, max_clusters] is
/// admissible when
///   lambda_k - lambda_{k+1} > min_eigengap  and  mu_{k+1} >= kEigengapMinRatio * mu_k;
/// the admissible k of the largest gap lambda_k - lambda_{k+1} is returned (the smallest
/// of equals), 1 when none is. The gap of any admissible k exceeds the gap after k = 1,
/// so this is the classic argmax of the eigengap over k in [1, max_clusters] restricted
/// to splits whose gap stands out against the spread of the eigenvalues above it (the
/// plain argmax splits paths and rings, whose gaps grow with k).
int eigengap_cluster_count(const std::vector<double>& eigenvalues, int max_clusters,
                           double min_eigengap);

/// Connected components of the graph of the non-zero off-diagonal entries of a square
/// matrix (an entry in either triangle links its two nodes), numbered by first
/// appearance. Throws hair::Error (bad input) for a matrix that is not square.
std::vector<int32_t> connected_components(const Eigen::SparseMatrix<double>& affinity);

}  // namespace hair
