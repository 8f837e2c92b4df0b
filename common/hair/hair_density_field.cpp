#include "hair/hair_density_field.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace hair {

using Vec3 = Eigen::Vector3d;

void HairDensityField::build(const std::vector<Vec3>& points_m) {
  values_.clear();
  dims_.setZero();
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (const Vec3& p : points_m) {
    if (!p.allFinite()) continue;
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  if (!(low.x() <= high.x())) return;
  if (((high - low) / cell_m_).maxCoeff() > 4096)
    throw std::runtime_error("hair density grid: the hair spans more than 4096 cells");
  // Two cells of margin, so that the gradient's samples near the edge read zeros.
  origin_m_ = low - Vec3::Constant(2 * cell_m_);
  for (int axis = 0; axis < 3; ++axis)
    dims_[axis] = static_cast<int>(std::ceil((high[axis] - low[axis]) / cell_m_)) + 5;
  values_.assign(static_cast<size_t>(dims_.x()) * static_cast<size_t>(dims_.y()) *
                     static_cast<size_t>(dims_.z()),
                 0.0);
  for (const Vec3& p : points_m) {
    if (!p.allFinite()) continue;
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

Vec3 HairDensityField::gradient_per_cell(const Vec3& point_m) const {
  Vec3 gradient;
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 step = Vec3::Zero();
    step[axis] = 0.5 * cell_m_;
    gradient[axis] = density(point_m + step) - density(point_m - step);
  }
  return gradient;
}

void HairDensityField::locate(const Vec3& point_m, Eigen::Vector3i& cell, Vec3& fraction) const {
  Vec3 u = (point_m - origin_m_) / cell_m_;
  for (int axis = 0; axis < 3; ++axis) {
    cell[axis] = static_cast<int>(std::floor(u[axis]));
    fraction[axis] = u[axis] - cell[axis];
  }
}

double HairDensityField::self_density(const Vec3& point_m, const Vec3& self_m) const {
  Eigen::Vector3i cell_p, cell_s;
  Vec3 f_p, f_s;
  locate(point_m, cell_p, f_p);
  locate(self_m, cell_s, f_s);
  // Corners shared by the two cells: per axis, the sample's corner offset d in {0, 1}
  // matches the splat's offset d + cell_p - cell_s in {0, 1}.
  double sum = 1;
  for (int axis = 0; axis < 3; ++axis) {
    double axis_sum = 0;
    for (int d = 0; d < 2; ++d) {
      int e = d + cell_p[axis] - cell_s[axis];
      if (e < 0 || e > 1) continue;
      double wp = d ? f_p[axis] : 1 - f_p[axis];
      double ws = e ? f_s[axis] : 1 - f_s[axis];
      axis_sum += wp * ws;
    }
    sum *= axis_sum;
  }
  return sum;
}

double HairDensityField::density_without(const Vec3& point_m, std::span<const Vec3> own_m) const {
  if (values_.empty()) return 0;
  double value = density(point_m);
  for (const Vec3& own : own_m) value -= self_density(point_m, own);
  return value;
}

Vec3 HairDensityField::gradient_per_cell_without(const Vec3& point_m,
                                                 std::span<const Vec3> own_m) const {
  Vec3 gradient;
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 step = Vec3::Zero();
    step[axis] = 0.5 * cell_m_;
    gradient[axis] =
        density_without(point_m + step, own_m) - density_without(point_m - step, own_m);
  }
  return gradient;
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
