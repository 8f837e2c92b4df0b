#pragma once
// Points written as a list of {x, y, z} in tests.

#include <array>
#include <initializer_list>

#include "hair/core/strand_set.h"

namespace hair::test {

/// A #points x 3 matrix from a list of points.
inline Points3f rows(std::initializer_list<std::array<float, 3>> points) {
  Points3f matrix(static_cast<Eigen::Index>(points.size()), 3);
  Eigen::Index row = 0;
  for (const auto& point : points) matrix.row(row++) << point[0], point[1], point[2];
  return matrix;
}

}  // namespace hair::test
