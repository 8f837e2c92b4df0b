#pragma once
// Hair-hair repulsion from a density grid (Muller, Kim and Chentanez 2012, "Fast
// simulation of inextensible hair and fur", section 5): the hair particles are splatted
// into a grid, and each is pushed down the gradient of the density, toward emptier space.
// The simulation (hair_simulation.cpp) compares it with the density of the rest state.

#include <Eigen/Core>
#include <array>
#include <span>
#include <vector>

namespace hair {

/// A density grid of particles, rebuilt for every set of positions.
class HairDensityField {
 public:
  /// @param cell_m  grid spacing
  explicit HairDensityField(double cell_m) : cell_m_(cell_m) {}

  /// Splats `points_m` (each with weight 1, trilinearly) into a grid over their bounding
  /// box. Serial, so the sums do not depend on the thread count.
  void build(const std::vector<Eigen::Vector3d>& points_m);

  /// Density at `point_m`: trilinear, particles per cell; 0 outside the grid.
  double density(const Eigen::Vector3d& point_m) const;

  /// Gradient of density() by central differences over one cell, particles per cell per
  /// cell (multiply by 1 / cell_m for per metre).
  Eigen::Vector3d gradient_per_cell(const Eigen::Vector3d& point_m) const;

  /// density() and gradient_per_cell() without the splats of the particles at `own_m` (a
  /// particle and its neighbours along its strand must not push it: its own splat's
  /// gradient at its position depends on where in its cell it is, and its neighbours move
  /// with it; either would pump energy into a moving strand).
  double density_without(const Eigen::Vector3d& point_m,
                         std::span<const Eigen::Vector3d> own_m) const;
  Eigen::Vector3d gradient_per_cell_without(const Eigen::Vector3d& point_m,
                                            std::span<const Eigen::Vector3d> own_m) const;

  /// density_without() and gradient_per_cell_without() at one point.
  struct SampleWithout {
    double density = 0;
    Eigen::Vector3d gradient_per_cell = Eigen::Vector3d::Zero();
  };
  /// Both at once, from the 3 x 3 x 3 grid values about the point: the density as
  /// density_without() computes it, bit for bit, and the gradient as
  /// gradient_per_cell_without() does up to rounding (its two samples along an axis lie one
  /// cell apart, so their difference is a trilinear sample of the grid's differences along
  /// that axis, at the lower one's fractions). What a repulsion force asks of a field: 27
  /// grid values read once, where the two calls read 56 and locate 7 points and the own
  /// splats twice. Near the grid's edge it makes the two calls.
  SampleWithout sample_without(const Eigen::Vector3d& point_m,
                               std::span<const Eigen::Vector3d> own_m) const;

  /// Mean density over the occupied cells (the reference a simulation keeps from its
  /// rest state); 0 for an empty grid.
  double mean_occupied_density() const;

 private:
  /// A point's cell (its lower corner) and its fractions within it.
  struct Located {
    Eigen::Vector3i cell;
    Eigen::Vector3d fraction;
  };
  /// At most this many own splats (a particle and its neighbours) per query.
  static constexpr size_t kMaxOwn = 8;

  double value(int x, int y, int z) const;
  Located locate(const Eigen::Vector3d& point_m) const;
  /// density() at a located point.
  double density_at(const Located& point) const;
  /// The trilinear weight that a splat at `self` gives the density sampled at `point`.
  static double self_density(const Located& point, const Located& self);
  /// density_at(point) less the own splats' weights there.
  double density_without_at(const Located& point, std::span<const Located> own) const;
  /// The own splats located, once per query (into `storage`).
  std::span<const Located> locate_own(std::span<const Eigen::Vector3d> own_m,
                                      std::array<Located, kMaxOwn>& storage) const;

  double cell_m_;
  Eigen::Vector3d origin_m_ = Eigen::Vector3d::Zero();
  Eigen::Vector3i dims_ = Eigen::Vector3i::Zero();
  std::vector<double> values_;
};

}  // namespace hair
