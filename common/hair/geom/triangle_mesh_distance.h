#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "hair/core/strand_set.h"

namespace hair {

/// Row-major n x 3 int32 triangle vertex ids.
using Triangles3i = Eigen::Matrix<int32_t, Eigen::Dynamic, 3, Eigen::RowMajor>;

/// Exact unsigned distance from points to a triangle mesh. One pass of a k-d tree
/// (nanoflann) over triangle centroids, nearest first, tests each triangle it meets; with
/// d the nearest distance so far, only centroids within d + R are searched on (R: the
/// largest distance from a triangle's centroid to its corners), since no other triangle
/// can be nearer. Triangles over twice the median size are indexed as pieces (split at
/// their edge midpoints) so that R stays small.
class TriangleMeshDistance {
 public:
  /// @param vertices   #V x 3 positions
  /// @param triangles  #T x 3 vertex ids (non-empty)
  TriangleMeshDistance(const Points3f& vertices, const Triangles3i& triangles);
  ~TriangleMeshDistance();
  TriangleMeshDistance(TriangleMeshDistance&&) noexcept;
  TriangleMeshDistance& operator=(TriangleMeshDistance&&) noexcept;

  struct Nearest {
    double distance = 0;
    int32_t triangle = -1;
    Eigen::Vector3d closest_point = Eigen::Vector3d::Zero();
  };

  /// Nearest point of the mesh to `point`.
  Nearest nearest(const Eigen::Vector3d& point) const;
  /// Distance only; thread-safe, like nearest().
  double distance(const Eigen::Vector3d& point) const { return nearest(point).distance; }
  /// Whether some triangle lies within `radius` of `point` (cheaper than distance()).
  bool is_within(const Eigen::Vector3d& point, double radius) const;

 private:
  struct Index;
  std::unique_ptr<Index> index_;
};

/// Closest point to `p` on the triangle (a, b, c) (Ericson, Real-Time Collision
/// Detection, 5.1.5).
Eigen::Vector3d closest_point_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                          const Eigen::Vector3d& b, const Eigen::Vector3d& c);

/// Splits every polygon of CSR faces into a fan of triangles, #T x 3.
Triangles3i fan_triangulation(const std::vector<int64_t>& face_offsets,
                              const std::vector<int32_t>& face_vertices);

}  // namespace hair
