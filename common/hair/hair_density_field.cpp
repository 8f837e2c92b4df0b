#include "hair/hair_density_field.h"

#include <cmath>

namespace hair {

using Vec3 = Eigen::Vector3d;

void HairDensityField::build(const std::vector<Vec3>& points_m) {
  values_.clear();
  dims_.setZero();
  if (points_m.empty()) return;
  Vec3 low = points_m.front(), high = points_m.front();
  for (const Vec3& p : points_m) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  // Two cells of margin, so that the gradient's samples near the edge read zeros.
  origin_m_ = low - Vec3::Constant(2 * cell_m_);
  for (int axis = 0; axis < 3; ++axis)
    dims_[axis] = static_cast<int>(std::ceil((high[axis] - low[axis]) / cell_m_)) + 5;
  values_.assign(static_cast<size_t>(dims_.x()) * static_cast<size_t>(dims_.y()) *
                     static_cast<size_t>(dims_.z()),
                 0.0);
  for (const Vec3& p : points_m) {
    Vec3 u = (p - origin_m_) / cell_m_;
    int x = static_cast<int>(std::floor(u.x())), y = static_cast<int>(std::floor(u.y())),
        z = static_cast<int>(std::floor(u.z()));
    Vec3 f(u.x() - x, u.y() - y, u.z() - z);
    for (int corner = 0; corner < 8; ++corner) {
      int dx = corner & 1, dy = (corner >> 1) & 1, dz = (corner >> 2) & 1;
      double weight =
          (dx ? f.x() : 1 - f.x()) * (dy ? f.y() : 1 - f.y()) * (dz ? f.z() : 1 - f.z());
      values_[static_cast<size_t>(x + dx) +
              static_cast<size_t>(dims_.x()) *
                  (static_cast<size_t>(y + dy) +
                   static_cast<size_t>(dims_.y()) * static_cast<size_t>(z + dz))] += weight;
    }
  }
}

double HairDensityField::value(int x, int y, int z) const {
  if (x < 0 || y < 0 || z < 0 || x >= dims_.x() || y >= dims_.y() || z >= dims_.z()) return 0;
  return values_[static_cast<size_t>(x) +
                 static_cast<size_t>(dims_.x()) *
                     (static_cast<size_t>(y) +
                      static_cast<size_t>(dims_.y()) * static_cast<size_t>(z))];
}

double HairDensityField::density(const Vec3& point_m) const {
  if (values_.empty()) return 0;
  Vec3 u = (point_m - origin_m_) / cell_m_;
  if (!u.allFinite()) return 0;
  int x = static_cast<int>(std::floor(u.x())), y = static_cast<int>(std::floor(u.y())),
      z = static_cast<int>(std::floor(u.z()));
  Vec3 f(u.x() - x, u.y() - y, u.z() - z);
  double sum = 0;
  for (int corner = 0; corner < 8; ++corner) {
    int dx = corner & 1, dy = (corner >> 1) & 1, dz = (corner >> 2) & 1;
    double weight = (dx ? f.x() : 1 - f.x()) * (dy ? f.y() : 1 - f.y()) * (dz ? f.z() : 1 - f.z());
    sum += weight * value(x + dx, y + dy, z + dz);
  }
  return sum;
}

Vec3 HairDensityField::repulsion(const Vec3& point_m, double strength_m_s2,
                                 double reference_density) const {
  if (!(reference_density > 0) || strength_m_s2 == 0) return Vec3::Zero();
  Vec3 gradient;  // per cell
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 step = Vec3::Zero();
    step[axis] = 0.5 * cell_m_;
    gradient[axis] = density(point_m + step) - density(point_m - step);
  }
  return -strength_m_s2 * gradient / reference_density;
}

double HairDensityField::mean_occupied_density() const {
  double sum = 0;
  int64_t occupied = 0;
  for (double v : values_) {
    if (v > 0) {
      sum += v;
      ++occupied;
    }
  }
  return occupied ? sum / static_cast<double>(occupied) : 0.0;
}

}  // namespace hair
