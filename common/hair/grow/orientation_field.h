#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "hair/core/strand_set.h"

namespace hair {

/// Settings of OrientationField::build().
struct OrientationFieldParams {
  /// Edge of the cubic voxels (> 0). The lattice is anchored at the origin: voxel (i, j, k)
  /// covers [i, i + 1) x [j, j + 1) x [k, k + 1) times voxel_m.
  double voxel_m = 0.005;
  /// The field is defined on every voxel whose centre lies within this distance of a seeded
  /// voxel's centre (>= 0, at most kMaxBandVoxels voxels). 0: the seeded voxels only.
  double band_m = 0.015;
  /// Laplace systems of at most this many unknowns (unseeded band voxels) are factorised by
  /// CHOLMOD, exact to rounding; larger ones are solved by conjugate gradients (>= 0; 0:
  /// always CG). The band around a cluster's strands is a 3-D graph whose factorisation
  /// costs grow like unknowns^2: 20k unknowns take ~0.03 s, 60k ~0.4 s and 130k ~3 s with
  /// Debian's reference BLAS, where CG takes 0.03, 0.09 and 0.25 s.
  int64_t direct_max_unknowns = 20'000;
  /// Relative residual at which conjugate gradients stop (in (0, 1e-4]). The directions then
  /// differ from CHOLMOD's by about 4 times this (measured); every unknown lies within
  /// band_m of a seed, so ~100 iterations suffice whatever the cluster's size.
  double cg_tolerance = 1e-8;
};

/// A 3-D orientation field of one cluster of hair (section 4.4, after [CSW*16]): a unit
/// direction per voxel on a sparse band of voxels around the cluster's input strands,
/// grown strands follow it. One field per cluster, so that directions of clusters that
/// meet are never averaged.
///
/// Built once, then read only: every const member is thread-safe (no caches).
class OrientationField {
 public:
  /// The band may reach at most this many voxels (band_m / voxel_m) from a seed.
  static constexpr double kMaxBandVoxels = 16;

  /// An empty field: contains() nothing.
  OrientationField() = default;

  /// The field of the strands `strand_ids` of `strands` (polylines, root first, metres).
  ///
  /// Seeds: each segment adds its vector (tip-ward, so direction and length) once to every
  /// voxel it passes through, found by sampling the segment at steps of at most voxel_m / 2
  /// (so a voxel whose corner the segment merely clips may be missed). A voxel whose sum is
  /// not zero (more than 1e-9 of the lengths added there) is seeded with the normalised sum;
  /// one where opposite segments cancel is left to the interpolation like an empty voxel.
  ///
  /// The band: every voxel whose centre lies within band_m of a seeded voxel's centre.
  ///
  /// Unseeded band voxels get the harmonic interpolation of the seeded ones, componentwise:
  /// the graph Laplacian of the band's 6-neighbour voxel graph, with the seeds as Dirichlet
  /// values and a natural (Neumann) boundary at the band's edge (neighbours outside the band
  /// are left out): for each unseeded voxel i, sum over band neighbours j of (x_i - x_j) = 0.
  /// The matrix over the unseeded voxels is SPD because every connected component of the
  /// band holds a seed (a band voxel is joined to its seed by a monotone lattice path, which
  /// stays within band_m of it; checked all the same). It is block diagonal over the
  /// components, so one solve treats each on its own: one CHOLMOD factorisation and 3
  /// right-hand sides up to params.direct_max_unknowns unknowns, Jacobi-preconditioned
  /// conjugate gradients on the 3 columns at once beyond. The solutions are normalised; one
  /// that vanishes (between opposite seeds, exactly) is stored as zero and left out of
  /// direction()'s blend.
  ///
  /// Deterministic: the same inputs give bit-identical fields whatever the thread count.
  ///
  /// @param strands     the strand set (metres)
  /// @param strand_ids  #ids strands of `strands` that make up the cluster (repeats count twice)
  /// @param max_voxels  most voxels the field's box (the band's bounding box) may hold: it
  ///                    bounds the memory, 4 bytes a voxel (plus 33 a band voxel)
  /// Throws hair::Error: usage for an empty `strand_ids`, an id out of range, a parameter
  /// not finite or out of range, max_voxels outside [1, 2^31 - 1], or a box of more than
  /// max_voxels voxels (raise voxel_m); bad input for a non-finite point or one more than
  /// 2^40 voxels from the origin (names the strand) or strands that give no direction
  /// (every segment of zero length, or all cancelling); runtime when the solve fails.
  static OrientationField build(const StrandSet& strands, const std::vector<int64_t>& strand_ids,
                                const OrientationFieldParams& params,
                                int64_t max_voxels = 20'000'000);

  /// Whether `point_m` lies in a band voxel (false for a non-finite point).
  bool contains(const Eigen::Vector3d& point_m) const;

  /// The unit direction at `point_m`: the trilinear blend of the directions at the 8 voxel
  /// centres around it, corners outside the band left out (and the weights renormalised),
  /// normalised. nullopt when the point's own voxel is not in the band or the blend
  /// vanishes. The point's own voxel always has weight >= 1/8, so inside the band the
  /// blend is defined unless directions cancel.
  std::optional<Eigen::Vector3d> direction(const Eigen::Vector3d& point_m) const;

  int64_t band_voxel_count() const { return static_cast<int64_t>(band_cell_.size()); }
  int64_t seeded_voxel_count() const { return seeded_count_; }
  double voxel_m() const { return voxel_m_; }

  /// Corners of the box of voxels the field stores (the band's bounding box); empty field:
  /// both zero.
  Eigen::Vector3d box_low_m() const;
  Eigen::Vector3d box_high_m() const;

  /// Band voxels are numbered 0 .. band_voxel_count() - 1 in lattice order (x fastest,
  /// then y, then z). The centre of band voxel `band_voxel`, metres.
  Eigen::Vector3d voxel_centre_m(int64_t band_voxel) const;
  /// The stored unit direction of band voxel `band_voxel` (zero where the interpolation
  /// vanished).
  const Eigen::Vector3d& voxel_direction(int64_t band_voxel) const {
    return direction_[static_cast<size_t>(band_voxel)];
  }
  /// Whether band voxel `band_voxel` is seeded by the strands.
  bool voxel_seeded(int64_t band_voxel) const {
    return seeded_[static_cast<size_t>(band_voxel)] != 0;
  }

 private:
  /// Box cell of a lattice voxel, -1 outside the box.
  int64_t cell_of(double lattice_x, double lattice_y, double lattice_z) const;
  /// The box: the bounding box of the seeds' lattice voxels grown by `reach` voxels on
  /// every side. Throws Error::usage if it holds more than `max_voxels`.
  void place_box(const std::vector<std::array<int64_t, 3>>& seed_voxels, int reach,
                 int64_t max_voxels);
  /// The band: every box cell within the stencil (`stencil_cells`, as cell offsets) of a
  /// seed's cell, numbered in lattice order; the seeds' directions set.
  void mark_band(const std::vector<int64_t>& seed_cells,
                 const std::vector<Eigen::Vector3d>& seed_directions,
                 const std::vector<int64_t>& stencil_cells);
  /// The 6 neighbours of a band voxel that lie in the band, in increasing band order
  /// (-z, -y, -x, +x, +y, +z); -1 for none.
  std::array<int32_t, 6> band_neighbours(size_t voxel) const;
  /// Every band component holds a seed: a band voxel lies within band_m of a seed, and a
  /// monotone lattice path to that seed never moves farther from it. Checked all the
  /// same, since the Laplace system is singular otherwise: throws Error::runtime.
  void check_band_joined() const;
  /// The harmonic interpolation of the seeds' directions over the unseeded band voxels
  /// (the Laplace system, laplace_solution()), normalised.
  void interpolate_unseeded(const OrientationFieldParams& params);

  double voxel_m_ = 0;
  int64_t low_[3] = {0, 0, 0};              ///< lattice index of the box's first voxel
  int64_t size_[3] = {0, 0, 0};             ///< voxels of the box along x, y, z
  std::vector<int32_t> band_index_;         ///< #box cells (x fastest): band voxel or -1
  std::vector<int64_t> band_cell_;          ///< #band: its box cell
  std::vector<Eigen::Vector3d> direction_;  ///< #band: unit direction (or zero)
  std::vector<uint8_t> seeded_;             ///< #band: 1 for a seeded voxel
  int64_t seeded_count_ = 0;
};

}  // namespace hair
