#include "hair/cluster/kmeans.h"

#include <algorithm>
#include <limits>
#include <random>
#include <string>
#include <utility>

#include "hair/core/error.h"

namespace hair {
namespace {

/// A uniform draw in [0, 1) from the top 53 bits of one output of the generator.
double uniform01(std::mt19937_64& random) {
  return static_cast<double>(random() >> 11) * 0x1.0p-53;
}

/// A uniform index in [0, count).
Eigen::Index uniform_index(std::mt19937_64& random, Eigen::Index count) {
  auto index = static_cast<Eigen::Index>(uniform01(random) * static_cast<double>(count));
  return std::min(index, count - 1);
}

/// k-means++ seeding: the first centre a uniformly drawn point, each further one a
/// point drawn with probability proportional to its squared distance to the nearest
/// centre so far. `points` is d x n (one point a column); the result d x k.
Eigen::MatrixXd plus_plus_centres(const Eigen::MatrixXd& points, int k, std::mt19937_64& random) {
  Eigen::Index n = points.cols();
  Eigen::MatrixXd centres(points.rows(), k);
  centres.col(0) = points.col(uniform_index(random, n));
  Eigen::VectorXd nearest2 = (points.colwise() - centres.col(0)).colwise().squaredNorm();
  for (int c = 1; c < k; ++c) {
    double total = nearest2.sum();
    Eigen::Index chosen = 0;
    if (total > 0) {
      double target = uniform01(random) * total, cumulative = 0;
      chosen = -1;
      for (Eigen::Index i = 0; i < n; ++i) {
        if (nearest2[i] <= 0) continue;
        cumulative += nearest2[i];
        chosen = i;  // the last candidate, should rounding leave target beyond the sum
        if (cumulative > target) break;
      }
    } else {
      chosen = uniform_index(random, n);  // every point lies on a centre already
    }
    centres.col(c) = points.col(chosen);
    Eigen::VectorXd to_new = (points.colwise() - centres.col(c)).colwise().squaredNorm();
    nearest2 = nearest2.cwiseMin(to_new);
  }
  return centres;
}

/// One run of Lloyd's algorithm from the given centres (d x k); labels in [0, k).
struct Run {
  std::vector<int32_t> label;
  Eigen::MatrixXd centres;  // d x k
  double inertia = 0;
};

Run lloyd(const Eigen::MatrixXd& points, Eigen::MatrixXd centres, int max_iterations) {
  Eigen::Index n = points.cols();
  auto k = static_cast<int>(centres.cols());
  Run run;
  run.label.assign(static_cast<size_t>(n), -1);
  Eigen::MatrixXd sums(points.rows(), k);
  std::vector<Eigen::Index> count(static_cast<size_t>(k));
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    bool changed = false;
    for (Eigen::Index i = 0; i < n; ++i) {
      // Ties keep a point where it is (else the lower index wins), so that a point
      // moved into an emptied cluster stays there.
      int32_t current = run.label[static_cast<size_t>(i)];
      int best = current;
      double best2 = current < 0 ? std::numeric_limits<double>::infinity()
                                 : (points.col(i) - centres.col(current)).squaredNorm();
      for (int c = 0; c < k; ++c) {
        double distance2 = (points.col(i) - centres.col(c)).squaredNorm();
        if (distance2 < best2) {
          best2 = distance2;
          best = c;
        }
      }
      if (current != best) changed = true;
      run.label[static_cast<size_t>(i)] = best;
    }
    sums.setZero();
    std::fill(count.begin(), count.end(), 0);
    for (Eigen::Index i = 0; i < n; ++i) {
      int32_t c = run.label[static_cast<size_t>(i)];
      sums.col(c) += points.col(i);
      ++count[static_cast<size_t>(c)];
    }
    for (int c = 0; c < k; ++c)
      if (count[static_cast<size_t>(c)] > 0)
        centres.col(c) = sums.col(c) / static_cast<double>(count[static_cast<size_t>(c)]);
    // An empty cluster takes the point farthest from its centre among clusters of two
    // or more points (one exists while a cluster is empty, as k <= n).
    for (int empty = 0; empty < k; ++empty) {
      if (count[static_cast<size_t>(empty)] > 0) continue;
      Eigen::Index farthest = -1;
      double farthest2 = -1;
      for (Eigen::Index i = 0; i < n; ++i) {
        int32_t c = run.label[static_cast<size_t>(i)];
        if (count[static_cast<size_t>(c)] < 2) continue;
        double distance2 = (points.col(i) - centres.col(c)).squaredNorm();
        if (distance2 > farthest2) {
          farthest2 = distance2;
          farthest = i;
        }
      }
      int32_t donor = run.label[static_cast<size_t>(farthest)];
      sums.col(donor) -= points.col(farthest);
      --count[static_cast<size_t>(donor)];
      centres.col(donor) = sums.col(donor) / static_cast<double>(count[static_cast<size_t>(donor)]);
      run.label[static_cast<size_t>(farthest)] = empty;
      sums.col(empty) = points.col(farthest);
      count[static_cast<size_t>(empty)] = 1;
      centres.col(empty) = points.col(farthest);
      changed = true;
    }
    if (!changed) break;
  }
  for (Eigen::Index i = 0; i < n; ++i)
    run.inertia += (points.col(i) - centres.col(run.label[static_cast<size_t>(i)])).squaredNorm();
  run.centres = std::move(centres);
  return run;
}

}  // namespace

KMeansResult kmeans(const Eigen::MatrixXd& points, int k, const KMeansParams& params) {
  Eigen::Index n = points.rows();
  if (k < 1 || k > n)
    throw Error::usage("k-means: k = " + std::to_string(k) + " is outside [1, " +
                       std::to_string(n) + "] (the number of points)");
  if (params.restarts < 1 || params.max_iterations < 1)
    throw Error::usage("k-means: restarts (" + std::to_string(params.restarts) +
                       ") and max_iterations (" + std::to_string(params.max_iterations) +
                       ") must be at least 1");
  if (!points.allFinite()) throw Error::bad_input("", "k-means: a point is NaN or infinite");

  Eigen::MatrixXd columns = points.transpose();  // one point a column: contiguous
  std::mt19937_64 seeds(params.seed);
  Run best;
  bool have_best = false;
  int restarts = k == 1 ? 1 : params.restarts;  // one cluster: every run ends alike
  for (int restart = 0; restart < restarts; ++restart) {
    std::mt19937_64 random(seeds());
    Run run = lloyd(columns, plus_plus_centres(columns, k, random), params.max_iterations);
    if (!have_best || run.inertia < best.inertia) {
      best = std::move(run);
      have_best = true;
    }
  }

  // Renumber by first appearance.
  std::vector<int32_t> renumbered(static_cast<size_t>(k), -1);
  int32_t next = 0;
  for (int32_t label : best.label)
    if (renumbered[static_cast<size_t>(label)] < 0) renumbered[static_cast<size_t>(label)] = next++;
  KMeansResult result;
  result.label.reserve(best.label.size());
  for (int32_t label : best.label) result.label.push_back(renumbered[static_cast<size_t>(label)]);
  result.centres.resize(k, points.cols());
  for (int c = 0; c < k; ++c)
    result.centres.row(renumbered[static_cast<size_t>(c)]) = best.centres.col(c).transpose();
  result.inertia = best.inertia;
  return result;
}

}  // namespace hair
