#pragma once

#include <Eigen/Core>
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
  /// Ids of the `count` nearest points, nearest first (fewer if the index is smaller).
  std::vector<int32_t> nearest(const Eigen::Vector3f& query, int count) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace hair
