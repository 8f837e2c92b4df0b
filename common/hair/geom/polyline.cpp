#include "hair/geom/polyline.h"

#include <algorithm>

namespace hair {

double polyline_length(const std::vector<Eigen::Vector3d>& points) {
  double length = 0;
  for (size_t i = 0; i + 1 < points.size(); ++i) length += (points[i + 1] - points[i]).norm();
  return length;
}

Eigen::Vector3d point_at_arc_fraction(const std::vector<Eigen::Vector3d>& points, double fraction) {
  const double length = polyline_length(points);
  const double goal = std::clamp(fraction, 0.0, 1.0) * length;
  double walked = 0;
  for (size_t i = 0; i + 1 < points.size(); ++i) {
    const double step = (points[i + 1] - points[i]).norm();
    if (walked + step >= goal && step > 0)
      return points[i] + (goal - walked) / step * (points[i + 1] - points[i]);
    walked += step;
  }
  return length > 0 ? points.back() : points.front();
}

}  // namespace hair
