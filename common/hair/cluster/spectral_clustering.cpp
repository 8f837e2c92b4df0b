#include "hair/cluster/spectral_clustering.h"

#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/SymEigsSolver.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <sstream>
#include <string>
#include <utility>

#include "hair/core/error.h"

namespace hair {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

constexpr double kSymmetryTolerance = 1e-9;  // relative
constexpr int kSparseMaxRestarts = 1000;     // Spectra's default
constexpr double kSparseTolerance = 1e-10;   // Spectra's default, relative

std::string entry_name(Eigen::Index row, Eigen::Index col) {
  return "(" + std::to_string(row) + ", " + std::to_string(col) + ")";
}

std::string number(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

/// The affinity checked (see spectral_clustering()), without its diagonal and explicit
/// zeros, with sorted indices, and made exactly symmetric by averaging with its
/// transpose.
SparseMatrix checked_affinity(const SparseMatrix& affinity) {
  if (affinity.rows() != affinity.cols())
    throw Error::bad_input("", "affinity matrix is " + std::to_string(affinity.rows()) + " x " +
                                   std::to_string(affinity.cols()) + ", not square");
  for (Eigen::Index col = 0; col < affinity.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(affinity, col); it; ++it) {
      if (!std::isfinite(it.value()))
        throw Error::bad_input(
            "", "affinity " + entry_name(it.row(), it.col()) + " is " + number(it.value()));
      if (it.value() < 0)
        throw Error::bad_input("", "affinity " + entry_name(it.row(), it.col()) + " = " +
                                       number(it.value()) + " is negative");
    }
  SparseMatrix pruned = affinity;
  pruned.prune(
      [](Eigen::Index row, Eigen::Index col, double value) { return row != col && value != 0; });
  SparseMatrix transposed = pruned.transpose();
  SparseMatrix a = transposed.transpose();  // evaluating a transpose sorts the indices
  for (Eigen::Index col = 0; col < a.outerSize(); ++col) {
    // Column col of a against row col of a, merged by row.
    SparseMatrix::InnerIterator column(a, col), row_of(transposed, col);
    while (column || row_of) {
      Eigen::Index row =
          !row_of || (column && column.row() < row_of.row()) ? column.row() : row_of.row();
      double value = 0, mirrored = 0;
      if (column && column.row() == row) {
        value = column.value();
        ++column;
      }
      if (row_of && row_of.row() == row) {
        mirrored = row_of.value();
        ++row_of;
      }
      if (std::abs(value - mirrored) > kSymmetryTolerance * std::max(value, mirrored))
        throw Error::bad_input("", "affinity matrix is not symmetric: " + entry_name(row, col) +
                                       " = " + number(value) + " but " + entry_name(col, row) +
                                       " = " + number(mirrored));
    }
  }
  SparseMatrix symmetric = 0.5 * (a + transposed);
  symmetric.makeCompressed();
  return symmetric;
}

/// Leading eigenpairs, eigenvalues descending.
struct Eigenpairs {
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;  // one eigenvector a column
  bool sparse = false;
};

/// The `count` leading eigenpairs of the symmetric m x m matrix `matrix`.
Eigenpairs leading_eigenpairs(const SparseMatrix& matrix, int count, int dense_limit) {
  Eigen::Index m = matrix.rows();
  Eigenpairs pairs;
  if (m <= dense_limit || count >= m) {  // Spectra needs count < m
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(Eigen::MatrixXd(matrix),
                                                          Eigen::ComputeEigenvectors);
    if (solver.info() != Eigen::Success)
      throw Error::runtime(
          "", "dense eigensolver failed on a " + std::to_string(m) + "-node affinity matrix");
    pairs.values = solver.eigenvalues().tail(count).reverse();
    pairs.vectors = solver.eigenvectors().rightCols(count).rowwise().reverse();
    return pairs;
  }
  // ncv as asked for; should that not converge (eigenvalues packed close to 1, as on long
  // chains), once more with twice the Krylov space.
  Spectra::SparseSymMatProd<double> product(matrix);
  Eigen::Index ncv = std::min<Eigen::Index>(m, std::max(2 * count + 1, 20));
  for (int attempt = 0;; ++attempt) {
    Spectra::SymEigsSolver<Spectra::SparseSymMatProd<double>> solver(product, count, ncv);
    solver.init();
    solver.compute(Spectra::SortRule::LargestAlge, kSparseMaxRestarts, kSparseTolerance,
                   Spectra::SortRule::LargestAlge);
    if (solver.info() == Spectra::CompInfo::Successful) {
      pairs.values = solver.eigenvalues();
      pairs.vectors = solver.eigenvectors();
      pairs.sparse = true;
      return pairs;
    }
    if (attempt == 1 || ncv == m)
      throw Error::runtime("", "sparse eigensolver (Spectra) did not converge on a " +
                                   std::to_string(m) + "-node affinity matrix for " +
                                   std::to_string(count) + " eigenpairs (ncv " +
                                   std::to_string(ncv) + ")");
    ncv = std::min(m, 2 * ncv);
  }
}

/// D^-1/2 A D^-1/2 over `nodes` (ascending, each of positive degree within them);
/// `local` maps a node to its index in `nodes` (it is left as it was found, -1 everywhere).
SparseMatrix normalised_affinity(const SparseMatrix& a, const std::vector<int32_t>& nodes,
                                 std::vector<int32_t>& local) {
  for (size_t i = 0; i < nodes.size(); ++i)
    local[static_cast<size_t>(nodes[i])] = static_cast<int32_t>(i);
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd degree = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(nodes.size()));
  for (size_t j = 0; j < nodes.size(); ++j)
    for (SparseMatrix::InnerIterator it(a, nodes[j]); it; ++it) {
      int32_t i = local[static_cast<size_t>(it.row())];
      if (i < 0) continue;
      entries.emplace_back(i, static_cast<int32_t>(j), it.value());
      degree[static_cast<Eigen::Index>(j)] += it.value();
    }
  for (int32_t node : nodes) local[static_cast<size_t>(node)] = -1;
  Eigen::VectorXd scale = degree.cwiseSqrt().cwiseInverse();
  for (auto& entry : entries)
    entry = Eigen::Triplet<double>(entry.row(), entry.col(),
                                   entry.value() * scale[entry.row()] * scale[entry.col()]);
  auto m = static_cast<Eigen::Index>(nodes.size());
  SparseMatrix normalised(m, m);
  normalised.setFromTriplets(entries.begin(), entries.end());
  return normalised;
}

/// NJW: the rows of the k leading eigenvectors, normalised, clustered by k-means.
std::vector<int32_t> cluster_embedding(const Eigen::MatrixXd& vectors, int k,
                                       const KMeansParams& params) {
  auto m = static_cast<size_t>(vectors.rows());
  if (k == 1) return std::vector<int32_t>(m, 0);
  if (static_cast<size_t>(k) == m) {
    std::vector<int32_t> label(m);
    std::iota(label.begin(), label.end(), 0);
    return label;
  }
  Eigen::MatrixXd rows = vectors.leftCols(k);
  for (Eigen::Index i = 0; i < rows.rows(); ++i) {
    double norm = rows.row(i).norm();
    if (norm > 0) rows.row(i) /= norm;
  }
  return kmeans(rows, k, params).label;
}

/// Labels (non-negative) renumbered by first appearance; returns how many there are.
int renumber_by_first_appearance(std::vector<int32_t>& label) {
  std::vector<int32_t> renumbered;
  int32_t next = 0;
  for (int32_t& value : label) {
    auto old = static_cast<size_t>(value);
    if (old >= renumbered.size()) renumbered.resize(old + 1, -1);
    if (renumbered[old] < 0) renumbered[old] = next++;
    value = renumbered[old];
  }
  return next;
}

/// Node lists of the components, each ascending.
std::vector<std::vector<int32_t>> component_nodes(const std::vector<int32_t>& component) {
  std::vector<std::vector<int32_t>> nodes;
  for (size_t i = 0; i < component.size(); ++i) {
    auto c = static_cast<size_t>(component[i]);
    if (c >= nodes.size()) nodes.resize(c + 1);
    nodes[c].push_back(static_cast<int32_t>(i));
  }
  return nodes;
}

SpectralResult by_eigengap(const SparseMatrix& a, const std::vector<int32_t>& component,
                           const SpectralParams& params) {
  SpectralResult result;
  auto n = static_cast<size_t>(a.rows());
  result.label.assign(n, -1);
  std::vector<int32_t> local(n, -1);
  int32_t next_cluster = 0;
  for (const std::vector<int32_t>& nodes : component_nodes(component)) {
    auto m = static_cast<int>(nodes.size());
    if (m == 1) {
      result.eigenvalues.push_back(1.0);
      result.label[static_cast<size_t>(nodes[0])] = next_cluster++;
      continue;
    }
    int max_k = std::min(params.max_clusters_per_component, m - 1);
    Eigenpairs pairs =
        leading_eigenpairs(normalised_affinity(a, nodes, local), max_k + 1, params.dense_limit);
    result.used_sparse_solver = result.used_sparse_solver || pairs.sparse;
    std::vector<double> values(pairs.values.data(), pairs.values.data() + pairs.values.size());
    result.eigenvalues.insert(result.eigenvalues.end(), values.begin(), values.end());
    int k = eigengap_cluster_count(values, max_k, params.min_eigengap);
    std::vector<int32_t> label = cluster_embedding(pairs.vectors, k, params.kmeans);
    for (size_t i = 0; i < nodes.size(); ++i)
      result.label[static_cast<size_t>(nodes[i])] = next_cluster + label[i];
    next_cluster += k;
  }
  return result;
}

/// Fixed mode. The eigenproblem of the matrix over all non-isolated nodes is solved
/// component by component (the matrix is block diagonal, so its spectrum is the union of
/// theirs): Lanczos finds one eigenvector of a repeated eigenvalue only, and 1 is
/// repeated once per component.
SpectralResult by_count(const SparseMatrix& a, const std::vector<int32_t>& component,
                        const SpectralParams& params) {
  SpectralResult result;
  auto n = static_cast<size_t>(a.rows());
  result.label.assign(n, -1);
  std::vector<std::vector<int32_t>> components = component_nodes(component);
  int isolated = 0;
  for (const std::vector<int32_t>& nodes : components) isolated += nodes.size() == 1 ? 1 : 0;
  auto r = static_cast<int>(n) - isolated;
  int least = isolated + (r > 0 ? 1 : 0);
  if (params.clusters < least || params.clusters > static_cast<int>(n))
    throw Error::usage("spectral clustering: " + std::to_string(params.clusters) +
                       " clusters asked for, but the graph's " + std::to_string(n) + " nodes (" +
                       std::to_string(isolated) + " isolated) make between " +
                       std::to_string(least) + " and " + std::to_string(n));
  int k = params.clusters - isolated;  // over the r connected nodes

  // Each component's leading eigenpairs, then the k + 1 leading ones of them all (ties in
  // component order).
  std::vector<int32_t> row(n, -1);  // a connected node's row in the embedding
  std::vector<const std::vector<int32_t>*> spectrum_nodes;
  std::vector<Eigenpairs> spectra;
  std::vector<int32_t> local(n, -1);
  int32_t next_cluster = 0, next_row = 0;
  for (const std::vector<int32_t>& nodes : components) {
    auto m = static_cast<int>(nodes.size());
    if (m == 1) {
      result.label[static_cast<size_t>(nodes[0])] = next_cluster++;
      result.eigenvalues.push_back(1.0);
      continue;
    }
    for (int32_t node : nodes) row[static_cast<size_t>(node)] = next_row++;
    spectra.push_back(leading_eigenpairs(normalised_affinity(a, nodes, local), std::min(k + 1, m),
                                         params.dense_limit));
    result.used_sparse_solver = result.used_sparse_solver || spectra.back().sparse;
    spectrum_nodes.push_back(&nodes);
  }
  if (r == 0) return result;
  struct Pair {
    double value;
    size_t spectrum;
    Eigen::Index column;
  };
  std::vector<Pair> candidates;
  for (size_t s = 0; s < spectra.size(); ++s)
    for (Eigen::Index c = 0; c < spectra[s].values.size(); ++c)
      candidates.push_back({spectra[s].values[c], s, c});
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Pair& x, const Pair& y) { return x.value > y.value; });
  candidates.resize(std::min(candidates.size(), static_cast<size_t>(k + 1)));
  for (const Pair& pair : candidates) result.eigenvalues.push_back(pair.value);
  Eigen::MatrixXd vectors = Eigen::MatrixXd::Zero(r, k);
  for (int c = 0; c < k; ++c) {
    const Pair& pair = candidates[static_cast<size_t>(c)];
    const std::vector<int32_t>& nodes = *spectrum_nodes[pair.spectrum];
    for (size_t i = 0; i < nodes.size(); ++i)
      vectors(row[static_cast<size_t>(nodes[i])], c) =
          spectra[pair.spectrum].vectors(static_cast<Eigen::Index>(i), pair.column);
  }
  std::vector<int32_t> label = cluster_embedding(vectors, k, params.kmeans);
  for (size_t i = 0; i < n; ++i)
    if (row[i] >= 0) result.label[i] = next_cluster + label[static_cast<size_t>(row[i])];
  return result;
}

}  // namespace

int eigengap_cluster_count(const std::vector<double>& eigenvalues, int max_clusters,
                           double min_eigengap) {
  int best = 1;
  double best_gap = 0;
  int last = std::min(max_clusters, static_cast<int>(eigenvalues.size()) - 1);
  for (int k = 2; k <= last; ++k) {
    double above = eigenvalues[static_cast<size_t>(k - 1)];  // lambda_k
    double below = eigenvalues[static_cast<size_t>(k)];      // lambda_{k+1}
    double gap = above - below;
    bool stands_out = 1 - below >= kEigengapMinRatio * std::max(1 - above, 0.0);
    if (gap > min_eigengap && stands_out && (best == 1 || gap > best_gap)) {
      best = k;
      best_gap = gap;
    }
  }
  return best;
}

std::vector<int32_t> connected_components(const SparseMatrix& affinity) {
  if (affinity.rows() != affinity.cols())
    throw Error::bad_input("", "affinity matrix is " + std::to_string(affinity.rows()) + " x " +
                                   std::to_string(affinity.cols()) + ", not square");
  auto n = static_cast<size_t>(affinity.rows());
  std::vector<int32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&parent](int32_t node) {
    while (parent[static_cast<size_t>(node)] != node) {
      int32_t& up = parent[static_cast<size_t>(node)];
      up = parent[static_cast<size_t>(up)];  // path halving
      node = up;
    }
    return node;
  };
  for (Eigen::Index col = 0; col < affinity.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(affinity, col); it; ++it) {
      if (it.value() == 0 || it.row() == it.col()) continue;
      int32_t first = root(static_cast<int32_t>(it.row()));
      int32_t second = root(static_cast<int32_t>(it.col()));
      if (first != second)
        parent[static_cast<size_t>(std::max(first, second))] = std::min(first, second);
    }
  std::vector<int32_t> component(n, -1);
  int32_t next = 0;
  for (size_t i = 0; i < n; ++i) {
    auto r = static_cast<size_t>(root(static_cast<int32_t>(i)));
    if (component[r] < 0) component[r] = next++;
    component[i] = component[r];
  }
  return component;
}

SpectralResult spectral_clustering(const SparseMatrix& affinity, const SpectralParams& params) {
  if (params.clusters < 0)
    throw Error::usage("spectral clustering: clusters = " + std::to_string(params.clusters) +
                       " is negative");
  if (params.clusters == 0 && params.max_clusters_per_component < 1)
    throw Error::usage("spectral clustering: max_clusters_per_component = " +
                       std::to_string(params.max_clusters_per_component) + " is below 1");
  SparseMatrix a = checked_affinity(affinity);
  if (a.rows() == 0) {
    SpectralResult empty;
    empty.count_from_eigengap = params.clusters == 0;
    return empty;
  }
  std::vector<int32_t> component = connected_components(a);
  SpectralResult result =
      params.clusters == 0 ? by_eigengap(a, component, params) : by_count(a, component, params);
  result.count_from_eigengap = params.clusters == 0;
  result.components =
      component.empty() ? 0 : *std::max_element(component.begin(), component.end()) + 1;
  result.cluster_count = renumber_by_first_appearance(result.label);
  std::sort(result.eigenvalues.begin(), result.eigenvalues.end(), std::greater<>());
  return result;
}

}  // namespace hair
