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

HairDensityField::Located HairDensityField::locate(const Vec3& point_m) const {
  Vec3 u = (point_m - origin_m_) / cell_m_;
  Located located;
  for (int axis = 0; axis < 3; ++axis) {
    located.cell[axis] = static_cast<int>(std::floor(u[axis]));
    located.fraction[axis] = u[axis] - located.cell[axis];
  }
  return located;
}

double HairDensityField::density_at(const Located& point) const {
  const int x = point.cell.x(), y = point.cell.y(), z = point.cell.z();
  const Vec3& f = point.fraction;
  const double wx[2] = {1 - f.x(), f.x()}, wy[2] = {1 - f.y(), f.y()}, wz[2] = {1 - f.z(), f.z()};
  if (x >= 0 && y >= 0 && z >= 0 && x + 1 < dims_.x() && y + 1 < dims_.y() && z + 1 < dims_.z()) {
    // The whole cell inside the grid (the usual case): its corners by offsets, unchecked.
    const size_t stride_y = static_cast<size_t>(dims_.x());
    const size_t stride_z = stride_y * static_cast<size_t>(dims_.y());
    const double* base = values_.data() + static_cast<size_t>(x) +
                         stride_y * static_cast<size_t>(y) + stride_z * static_cast<size_t>(z);
    double sum = 0;
    for (int corner = 0; corner < 8; ++corner) {
      int dx = corner & 1, dy = (corner >> 1) & 1, dz = (corner >> 2) & 1;
      sum += wx[dx] * wy[dy] * wz[dz] *
             base[static_cast<size_t>(dx) + stride_y * static_cast<size_t>(dy) +
                  stride_z * static_cast<size_t>(dz)];
    }
    return sum;
  }
  double sum = 0;
  for (int corner = 0; corner < 8; ++corner) {
    int dx = corner & 1, dy = (corner >> 1) & 1, dz = (corner >> 2) & 1;
    sum += wx[dx] * wy[dy] * wz[dz] * value(x + dx, y + dy, z + dz);
  }
  return sum;
}

double HairDensityField::density(const Vec3& point_m) const {
  if (values_.empty()) return 0;
  if (!((point_m - origin_m_) / cell_m_).allFinite()) return 0;
  return density_at(locate(point_m));
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

double HairDensityField::self_density(const Located& point, const Located& self) {
  // Corners shared by the two cells: per axis, the sample's corner offset d in {0, 1}
  // matches the splat's offset d + cell_p - cell_s in {0, 1}.
  double sum = 1;
  for (int axis = 0; axis < 3; ++axis) {
    double axis_sum = 0;
    for (int d = 0; d < 2; ++d) {
      int e = d + point.cell[axis] - self.cell[axis];
      if (e < 0 || e > 1) continue;
      double wp = d ? point.fraction[axis] : 1 - point.fraction[axis];
      double ws = e ? self.fraction[axis] : 1 - self.fraction[axis];
      axis_sum += wp * ws;
    }
    sum *= axis_sum;
  }
  return sum;
}

double HairDensityField::density_without_at(const Located& point,
                                            std::span<const Located> own) const {
  double value = density_at(point);
  for (const Located& splat : own) value -= self_density(point, splat);
  return value;
}

std::span<const HairDensityField::Located> HairDensityField::locate_own(
    std::span<const Vec3> own_m, std::array<Located, kMaxOwn>& storage) const {
  if (own_m.size() > kMaxOwn)
    throw std::invalid_argument("hair density field: more than 8 own splats in a query");
  for (size_t i = 0; i < own_m.size(); ++i) storage[i] = locate(own_m[i]);
  return {storage.data(), own_m.size()};
}

double HairDensityField::density_without(const Vec3& point_m, std::span<const Vec3> own_m) const {
  if (values_.empty()) return 0;
  if (!((point_m - origin_m_) / cell_m_).allFinite()) return 0;
  std::array<Located, kMaxOwn> storage;
  return density_without_at(locate(point_m), locate_own(own_m, storage));
}

Vec3 HairDensityField::gradient_per_cell_without(const Vec3& point_m,
                                                 std::span<const Vec3> own_m) const {
  if (values_.empty() || !((point_m - origin_m_) / cell_m_).allFinite()) return Vec3::Zero();
  std::array<Located, kMaxOwn> storage;
  std::span<const Located> own = locate_own(own_m, storage);
  Vec3 gradient;
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 step = Vec3::Zero();
    step[axis] = 0.5 * cell_m_;
    gradient[axis] = density_without_at(locate(point_m + step), own) -
                     density_without_at(locate(point_m - step), own);
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
