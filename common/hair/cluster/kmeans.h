#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace hair {

/// Settings of kmeans().
struct KMeansParams {
  int restarts = 10;         ///< runs from different seeds; the least inertia is kept (>= 1)
  int max_iterations = 300;  ///< Lloyd iterations per run (>= 1)
  uint64_t seed = 1;         ///< the seeds of the runs are drawn from this one
};

/// A partition of the rows of a point matrix into k clusters.
struct KMeansResult {
  std::vector<int32_t> label;  ///< n, in [0, k), numbered by first appearance (row 0 gets 0)
  Eigen::MatrixXd centres;     ///< k x d, row c the mean of the points labelled c
  double inertia = 0;          ///< sum of squared distances of the points to their centres
};

/// Lloyd's k-means on the rows of `points` (n x d) with k-means++ seeding.
///
/// `restarts` runs start from seeds drawn from `params.seed` (std::mt19937_64, whose
/// output the standard fixes, and uniform draws written here rather than the
/// implementation-defined std distributions), so a seed gives the same result on
/// every platform. The run of least inertia is kept (the first of equals). A run
/// stops when no label changes or after `max_iterations`. A cluster left empty
/// takes the point farthest from its centre among the clusters of two or more
/// points. Distance ties keep a point in its cluster, else go to the lower index.
///
/// Throws hair::Error: usage for k outside [1, n] or restarts / max_iterations
/// below 1; bad input for a non-finite coordinate.
KMeansResult kmeans(const Eigen::MatrixXd& points, int k, const KMeansParams& params);

}  // namespace hair
