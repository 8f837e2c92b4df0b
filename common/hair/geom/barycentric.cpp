#include "hair/geom/barycentric.h"

#include <algorithm>

namespace hair {

std::array<double, 3> clamped_barycentric(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                          const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  Eigen::Vector3d e0 = b - a, e1 = c - a, d = p - a;
  double d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1);
  double d20 = d.dot(e0), d21 = d.dot(e1);
  double denominator = d00 * d11 - d01 * d01;
  if (!(denominator > 0)) return {1.0 / 3, 1.0 / 3, 1.0 / 3};
  double v = (d11 * d20 - d01 * d21) / denominator;
  double w = (d00 * d21 - d01 * d20) / denominator;
  std::array<double, 3> weight{std::max(0.0, 1 - v - w), std::max(0.0, v), std::max(0.0, w)};
  double sum = weight[0] + weight[1] + weight[2];
  for (double& x : weight) x /= sum;
  return weight;
}

}  // namespace hair
