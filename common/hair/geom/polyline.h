#pragma once
// A polyline's arc length, and points along it by arc length.

#include <Eigen/Core>
#include <vector>

namespace hair {

/// The polyline's length: the sum of its segments' lengths (0 for fewer than two points).
double polyline_length(const std::vector<Eigen::Vector3d>& points);

/// The point at `fraction` (0 the first point, 1 the last, clamped) of the arc length of
/// the polyline `points` (at least one point); the first point if it has no length.
Eigen::Vector3d point_at_arc_fraction(const std::vector<Eigen::Vector3d>& points,
                                      double fraction);

}  // namespace hair
