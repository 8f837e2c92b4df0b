#pragma once
// The centre of a triangle of a mesh, as growing computes it wherever it needs one.

#include <Eigen/Core>

#include "hair/core/strand_set.h"
#include "hair/geom/triangle_mesh_distance.h"

namespace hair {

/// Centre of triangle `t` of `triangles` over `vertices`: its three corners, cast to
/// `Scalar`, summed from zero in order and divided by 3 (in `Scalar`).
template <typename Scalar>
Eigen::Matrix<Scalar, 3, 1> triangle_centre(const Points3f& vertices, const Triangles3i& triangles,
                                            Eigen::Index t) {
  Eigen::Matrix<Scalar, 3, 1> centre = Eigen::Matrix<Scalar, 3, 1>::Zero();
  for (int k = 0; k < 3; ++k)
    centre += vertices.row(triangles(t, k)).transpose().template cast<Scalar>();
  return centre / 3;
}

}  // namespace hair
