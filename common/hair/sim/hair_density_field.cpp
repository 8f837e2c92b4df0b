#include "hair/sim/hair_density_field.h"

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

namespace {

/// A splat's weight along one axis at a sample in cell `cell` at `fraction` (the factor
/// self_density() multiplies per axis): over the sample's two corners d, the splat's
/// corner e = d + cell - splat_cell where it is 0 or 1.
double axis_overlap(int cell, double fraction, int splat_cell, double splat_fraction) {
  double sum = 0;
  for (int d = 0; d < 2; ++d) {
    const int e = d + cell - splat_cell;
    if (e < 0 || e > 1) continue;
    sum += (d ? fraction : 1 - fraction) * (e ? splat_fraction : 1 - splat_fraction);
  }
  return sum;
}

}  // namespace

HairDensityField::SampleWithout HairDensityField::sample_without(
    const Vec3& point_m, std::span<const Vec3> own_m) const {
  SampleWithout sample;
  if (values_.empty() || !((point_m - origin_m_) / cell_m_).allFinite()) return sample;
  std::array<Located, kMaxOwn> storage;
  const std::span<const Located> own = locate_own(own_m, storage);
  const Located point = locate(point_m);
  // Per axis, the cell and fraction of the gradient's lower sample, half a cell below the
  // point; its upper sample is in the next cell, at the same fraction.
  Eigen::Vector3i lower;
  Vec3 lower_fraction;
  for (int axis = 0; axis < 3; ++axis) {
    const double u = point.cell[axis] + point.fraction[axis] - 0.5;
    lower[axis] = static_cast<int>(std::floor(u));
    lower_fraction[axis] = u - lower[axis];
  }
  if ((lower.array() < 0).any() || (lower.array() + 3 > dims_.array()).any()) {
    sample.density = density_without(point_m, own_m);
    sample.gradient_per_cell = gradient_per_cell_without(point_m, own_m);
    return sample;
  }
  // The values of cells lower to lower + 2 per axis, x fastest, and where the point's own
  // cell starts among them (0 or 1 per axis).
  const size_t stride_y = static_cast<size_t>(dims_.x());
  const size_t stride_z = stride_y * static_cast<size_t>(dims_.y());
  const double* base = values_.data() + static_cast<size_t>(lower.x()) +
                       stride_y * static_cast<size_t>(lower.y()) +
                       stride_z * static_cast<size_t>(lower.z());
  double near[27];
  for (size_t z = 0; z < 3; ++z)
    for (size_t y = 0; y < 3; ++y)
      for (size_t x = 0; x < 3; ++x)
        near[x + 3 * y + 9 * z] = base[x + stride_y * y + stride_z * z];
  constexpr int kStride[3] = {1, 3, 9};
  const Eigen::Vector3i start = point.cell - lower;
  const int own_cell = start.x() + 3 * start.y() + 9 * start.z();
  const Vec3& f = point.fraction;
  const double w[3][2] = {{1 - f.x(), f.x()}, {1 - f.y(), f.y()}, {1 - f.z(), f.z()}};
  // The density as density_at() sums it.
  for (int corner = 0; corner < 8; ++corner) {
    const int dx = corner & 1, dy = (corner >> 1) & 1, dz = (corner >> 2) & 1;
    sample.density += w[0][dx] * w[1][dy] * w[2][dz] * near[own_cell + dx + 3 * dy + 9 * dz];
  }
  // Along each axis, over the point's four corners across it: the lower sample's two
  // corners' differences to the next, weighted by its fraction.
  for (int axis = 0; axis < 3; ++axis) {
    const int b = (axis + 1) % 3, c = (axis + 2) % 3;
    const double g = lower_fraction[axis];
    const int row = own_cell - start[axis] * kStride[axis];  // lower's cell along the axis
    double sum = 0;
    for (int corner = 0; corner < 4; ++corner) {
      const int db = corner & 1, dc = corner >> 1;
      const double* along = near + row + db * kStride[b] + dc * kStride[c];
      const double first = along[0], second = along[kStride[axis]],
                   third = along[2 * kStride[axis]];
      sum += w[b][db] * w[c][dc] * ((1 - g) * (second - first) + g * (third - second));
    }
    sample.gradient_per_cell[axis] = sum;
  }
  // The own splats out: their weights at the point, and the differences of their weights
  // at the two samples along each axis (the other axes' factors are the point's).
  for (const Located& splat : own) {
    Vec3 centre, rise;
    for (int axis = 0; axis < 3; ++axis) {
      centre[axis] =
          axis_overlap(point.cell[axis], f[axis], splat.cell[axis], splat.fraction[axis]);
      rise[axis] =
          axis_overlap(lower[axis] + 1, lower_fraction[axis], splat.cell[axis],
                       splat.fraction[axis]) -
          axis_overlap(lower[axis], lower_fraction[axis], splat.cell[axis], splat.fraction[axis]);
    }
    sample.density -= centre.x() * centre.y() * centre.z();  // as self_density()
    sample.gradient_per_cell -=
        Vec3(rise.x() * centre.y() * centre.z(), centre.x() * rise.y() * centre.z(),
             centre.x() * centre.y() * rise.z());
  }
  return sample;
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
