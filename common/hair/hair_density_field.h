#pragma once
// Hair-hair repulsion from a density grid (Muller, Kim and Chentanez 2012, "Fast
// simulation of inextensible hair and fur", section 5): the hair particles are splatted
// into a grid, and each is pushed down the gradient of the density, toward emptier space.

#include <Eigen/Core>
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

  /// Repulsion acceleration at `point_m`: -strength * cell * grad(density) / reference,
  /// so that a density rising by `reference` over one cell pushes with `strength_m_s2`.
  /// The gradient is a central difference over one cell.
  Eigen::Vector3d repulsion(const Eigen::Vector3d& point_m, double strength_m_s2,
                            double reference_density) const;

  /// Mean density over the occupied cells (the reference a simulation keeps from its
  /// rest state); 0 for an empty grid.
  double mean_occupied_density() const;

 private:
  double value(int x, int y, int z) const;

  double cell_m_;
  Eigen::Vector3d origin_m_ = Eigen::Vector3d::Zero();
  Eigen::Vector3i dims_ = Eigen::Vector3i::Zero();
  std::vector<double> values_;
};

}  // namespace hair
