#pragma once

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <vector>

#include "hair/core/strand_set.h"

namespace hair {

/// A k-d tree (nanoflann) over 3-D points for nearest-neighbour and radius queries.
/// Queries are thread-safe; results are sorted by distance, ties by point id, so they
/// do not depend on the thread count.
class PointIndex {
 public:
  /// @param points  #P x 3 positions; copied
  explicit PointIndex(const Points3f& points);
  ~PointIndex();
  PointIndex(PointIndex&&) noexcept;
  PointIndex& operator=(PointIndex&&) noexcept;

  int64_t size() const;

  /// Ids of the points within `radius` of `query`, nearest first.
  std::vector<int32_t> within(const Eigen::Vector3f& query, float radius) const;
  /// Calls `visit` with the ids of within(query, radius), in that order, until it returns
  /// false: the points are ordered in growing batches, as far as they are visited (a
  /// dense mesh puts thousands of points within a radius of which a caller reads a few).
  void visit_within(const Eigen::Vector3f& query, float radius,
                    const std::function<bool(int32_t)>& visit) const;
  /// The same ids as within(query, radius) in the k-d tree's own order (the same for the
  /// same points and query, whatever the thread count), for callers whose result does not
  /// depend on the order.
  std::vector<int32_t> within_unordered(const Eigen::Vector3f& query, float radius) const;
  /// Whether any point lies within `radius` of `query`.
  bool any_within(const Eigen::Vector3f& query, float radius) const;
  /// Ids of the `count` nearest points, nearest first (fewer if the index is smaller).
  std::vector<int32_t> nearest(const Eigen::Vector3f& query, int count) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace hair
