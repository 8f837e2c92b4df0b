#pragma once
// Barycentric coordinates on a triangle, shared by the altitude springs
// (altitude_strand.cpp: the foot of a point-face altitude) and the interpolation of
// strands from three guides (interp/guide_choice.cpp).

#include <Eigen/Core>
#include <array>

namespace hair {

/// Barycentric coordinates (for a, b, c) of the projection of `p` on the plane of the
/// triangle (a, b, c), clamped into the triangle: negative ones set to zero, the rest
/// renormalised to sum to 1. A degenerate triangle (collinear or coincident corners)
/// gives (1/3, 1/3, 1/3).
std::array<double, 3> clamped_barycentric(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                          const Eigen::Vector3d& b, const Eigen::Vector3d& c);

}  // namespace hair
