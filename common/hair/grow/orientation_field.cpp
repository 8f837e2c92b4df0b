#include "hair/grow/orientation_field.h"

#include <fmt/format.h>

#include <Eigen/SparseCore>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>

// CHOLMOD's headers are C and Eigen's wrapper of them is not ours: keep their warnings out.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include <Eigen/CholmodSupport>
#pragma GCC diagnostic pop

#include "hair/core/error.h"

namespace hair {
namespace {

/// Points farther than this many voxels from the origin are refused: their lattice indices
/// would lose the exactness that consistent voxel membership relies on.
constexpr double kMaxLatticeCoordinate = 0x1.0p40;

/// A seed is kept when its summed vector is longer than this fraction of the lengths summed
/// into it (opposite segments through one voxel cancel otherwise).
constexpr double kSeedCancelFraction = 1e-9;

/// A voxel of the lattice anchored at the origin: voxel (i, j, k) covers
/// [i, i + 1) x [j, j + 1) x [k, k + 1) times voxel_m.
using LatticeVoxel = std::array<int64_t, 3>;

/// The position of a point in voxel units. Every membership test (seeding, contains(),
/// direction()) floors this one expression, so the same point always lands in the same
/// voxel.
Eigen::Vector3d lattice_position(const Eigen::Vector3d& point_m, double voxel_m) {
  return point_m / voxel_m;
}

LatticeVoxel lattice_voxel(const Eigen::Vector3d& point_m, double voxel_m) {
  Eigen::Vector3d position = lattice_position(point_m, voxel_m);
  return {static_cast<int64_t>(std::floor(position.x())),
          static_cast<int64_t>(std::floor(position.y())),
          static_cast<int64_t>(std::floor(position.z()))};
}

/// One segment's contribution to one voxel.
struct SeedEntry {
  LatticeVoxel voxel;
  Eigen::Vector3d vector;  // the segment, tip-ward, metres
  double length_m = 0;
};

/// A seeded voxel: the normalised sum of the segments through it.
struct Seed {
  LatticeVoxel voxel;
  Eigen::Vector3d direction;
};

void check_params(const OrientationFieldParams& params, int64_t max_voxels) {
  if (!std::isfinite(params.voxel_m) || params.voxel_m <= 0)
    throw Error::usage(
        fmt::format("orientation field: voxel_m = {} must be finite and > 0", params.voxel_m));
  if (!std::isfinite(params.band_m) || params.band_m < 0 ||
      params.band_m > OrientationField::kMaxBandVoxels * params.voxel_m)
    throw Error::usage(fmt::format(
        "orientation field: band_m = {} must lie in [0, {} voxel_m = {}]", params.band_m,
        OrientationField::kMaxBandVoxels, OrientationField::kMaxBandVoxels * params.voxel_m));
  if (params.direct_max_unknowns < 0)
    throw Error::usage(fmt::format("orientation field: direct_max_unknowns = {} must be >= 0",
                                   params.direct_max_unknowns));
  if (!(params.cg_tolerance > 0 && params.cg_tolerance <= 1e-4))
    throw Error::usage(fmt::format("orientation field: cg_tolerance = {} must lie in (0, 1e-4]",
                                   params.cg_tolerance));
  if (max_voxels < 1 || max_voxels > std::numeric_limits<int32_t>::max())
    throw Error::usage(
        fmt::format("orientation field: max_voxels = {} must lie in [1, 2^31 - 1]", max_voxels));
}

/// Every segment's vector added once to each voxel it passes through, sampled at steps of
/// at most voxel_m / 2, in the order of `strand_ids` and of the points.
std::vector<SeedEntry> seed_entries(const StrandSet& strands,
                                    const std::vector<int64_t>& strand_ids, double voxel_m) {
  std::vector<SeedEntry> entries;
  for (int64_t id : strand_ids) {
    auto points = strands.strand(id);
    for (Eigen::Index row = 0; row < points.rows(); ++row) {
      Eigen::Vector3d point = points.row(row).transpose().cast<double>();
      if (!point.allFinite())
        throw Error::bad_input("", fmt::format("orientation field: strand {} has a NaN or "
                                               "infinite point (point {})",
                                               id, row));
      if ((point.array().abs() / voxel_m).maxCoeff() > kMaxLatticeCoordinate)
        throw Error::bad_input("", fmt::format("orientation field: strand {} has a point {} m "
                                               "from the origin (point {})",
                                               id, point.norm(), row));
    }
    for (Eigen::Index row = 0; row + 1 < points.rows(); ++row) {
      Eigen::Vector3d start = points.row(row).transpose().cast<double>();
      Eigen::Vector3d end = points.row(row + 1).transpose().cast<double>();
      Eigen::Vector3d vector = end - start;
      double length_m = vector.norm();
      if (!(length_m > 0)) continue;
      auto steps = static_cast<int64_t>(std::ceil(length_m / (0.5 * voxel_m)));
      steps = std::max<int64_t>(steps, 1);
      LatticeVoxel previous{};
      for (int64_t step = 0; step <= steps; ++step) {
        Eigen::Vector3d sample =
            step == steps ? end : start + vector * (static_cast<double>(step) / steps);
        LatticeVoxel voxel = lattice_voxel(sample, voxel_m);
        // A straight segment leaves a (convex) voxel once: skipping repeats of the previous
        // sample's voxel adds the segment once per voxel.
        if (step > 0 && voxel == previous) continue;
        entries.push_back({voxel, vector, length_m});
        previous = voxel;
      }
    }
  }
  return entries;
}

/// The seeded voxels, in lattice order (z, then y, then x); each the normalised sum of its
/// entries, summed in the order of `entries` (so deterministic).
std::vector<Seed> seeds_of(std::vector<SeedEntry> entries) {
  auto lattice_order = [](const SeedEntry& a, const SeedEntry& b) {
    return std::tie(a.voxel[2], a.voxel[1], a.voxel[0]) <
           std::tie(b.voxel[2], b.voxel[1], b.voxel[0]);
  };
  std::stable_sort(entries.begin(), entries.end(), lattice_order);
  std::vector<Seed> seeds;
  for (size_t first = 0; first < entries.size();) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    double lengths_m = 0;
    size_t last = first;
    for (; last < entries.size() && entries[last].voxel == entries[first].voxel; ++last) {
      sum += entries[last].vector;
      lengths_m += entries[last].length_m;
    }
    double norm = sum.norm();
    if (norm > kSeedCancelFraction * lengths_m) seeds.push_back({entries[first].voxel, sum / norm});
    first = last;
  }
  return seeds;
}

/// Lattice offsets (dx, dy, dz) with |d| voxel_m <= band_m: the band around one seed. The
/// squared length is compared in voxel units with a little slack, so that a band of exactly
/// n voxels (0.015 / 0.005) reaches n whatever the rounding of the ratio.
std::vector<std::array<int, 3>> band_stencil(double band_voxels) {
  double reach2 = band_voxels * band_voxels * (1 + 1e-9);
  auto reach = static_cast<int>(std::floor(std::sqrt(reach2)));
  std::vector<std::array<int, 3>> stencil;
  for (int dz = -reach; dz <= reach; ++dz)
    for (int dy = -reach; dy <= reach; ++dy)
      for (int dx = -reach; dx <= reach; ++dx)
        if (dx * dx + dy * dy + dz * dz <= reach2) stencil.push_back({dx, dy, dz});
  return stencil;
}

/// Conjugate gradients iterations allowed: far more than the ~100 that bands need.
constexpr int kMaxCgIterations = 10'000;

/// n x 3 values, one voxel a row: the 3 components of the field.
using Columns3 = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

/// Jacobi-preconditioned conjugate gradients for L X = B, the 3 columns in lockstep (one
/// pass over L per iteration for all three) but each with its own step lengths, so each
/// column is what a solve of it alone would give. A column stops when its residual is
/// within `tolerance` of |b|; its updates are then skipped. Written out rather than Eigen's
/// ConjugateGradient, which solves the columns one after the other (3 passes over L instead
/// of 1) and reads the matrix's values: this is twice as fast. Serial on purpose: the grow
/// stage can build the fields of several clusters at once, and a parallel region per pass,
/// 100s of times over, loses more to contention than it gains (Eigen's OpenMP products made
/// it 5 times slower on a busy 2-core machine).
///
/// @param laplacian  #n x #n, symmetric, both triangles stored, compressed
/// @param rhs        #n x 3
/// @return #n x 3
Columns3 conjugate_gradients(const Eigen::SparseMatrix<double>& laplacian, const Columns3& rhs,
                             double tolerance) {
  const Eigen::Index unknowns = laplacian.rows();
  // Symmetric: the column-major arrays are those of the row-major matrix.
  const int* row_start = laplacian.outerIndexPtr();
  const int* columns = laplacian.innerIndexPtr();
  const Eigen::VectorXd diagonal = laplacian.diagonal();
  const Eigen::VectorXd inverse_diagonal = diagonal.cwiseInverse();

  Columns3 solution = Columns3::Zero(unknowns, 3);
  Columns3 residual = rhs;
  Columns3 preconditioned = residual.array().colwise() * inverse_diagonal.array();
  Columns3 search = preconditioned;
  Columns3 mapped(unknowns, 3);
  double* x = solution.data();
  double* r = residual.data();
  double* z = preconditioned.data();
  double* p = search.data();
  double* q = mapped.data();
  std::array<double, 3> residual_dot{}, residual2{}, stop2{};
  for (int c = 0; c < 3; ++c) {
    residual_dot[c] = residual.col(c).dot(preconditioned.col(c));
    residual2[c] = residual.col(c).squaredNorm();
    stop2[c] = tolerance * tolerance * rhs.col(c).squaredNorm();
  }
  for (int iteration = 0;; ++iteration) {
    std::array<bool, 3> active{};
    for (int c = 0; c < 3; ++c) active[c] = residual2[c] > stop2[c];
    if (!active[0] && !active[1] && !active[2]) break;
    if (iteration == kMaxCgIterations)
      throw Error::runtime("", fmt::format("orientation field: conjugate gradients did not reach "
                                           "a relative residual of {} on the Laplace system of "
                                           "{} voxels in {} iterations",
                                           tolerance, unknowns, kMaxCgIterations));
    // Pass 1: q = L p, and the curvature p' L p per column. Off the diagonal every entry
    // is -1, so only the column indices are read.
    std::array<double, 3> curvature{};
    for (Eigen::Index row = 0; row < unknowns; ++row) {
      double sum[3];
      for (int c = 0; c < 3; ++c) sum[c] = diagonal[row] * p[3 * row + c];
      for (int entry = row_start[row]; entry < row_start[row + 1]; ++entry) {
        if (columns[entry] == row) continue;
        const double* neighbour = p + 3 * static_cast<Eigen::Index>(columns[entry]);
        for (int c = 0; c < 3; ++c) sum[c] -= neighbour[c];
      }
      for (int c = 0; c < 3; ++c) {
        q[3 * row + c] = sum[c];
        curvature[c] += sum[c] * p[3 * row + c];
      }
    }
    // Pass 2: step along p; a finished column steps by 0 and keeps its search direction.
    std::array<double, 3> step{}, next_dot{};
    for (int c = 0; c < 3; ++c)
      if (active[c]) step[c] = residual_dot[c] / curvature[c];
    residual2 = {0, 0, 0};
    for (Eigen::Index row = 0; row < unknowns; ++row)
      for (int c = 0; c < 3; ++c) {
        Eigen::Index i = 3 * row + c;
        x[i] += step[c] * p[i];
        r[i] -= step[c] * q[i];
        z[i] = inverse_diagonal[row] * r[i];
        next_dot[c] += r[i] * z[i];
        residual2[c] += r[i] * r[i];
      }
    // Pass 3: the next search direction p = z + beta p.
    std::array<double, 3> fresh{}, beta{};
    for (int c = 0; c < 3; ++c) {
      fresh[c] = active[c] ? 1 : 0;
      beta[c] = active[c] ? next_dot[c] / residual_dot[c] : 1;
      if (active[c]) residual_dot[c] = next_dot[c];
    }
    for (Eigen::Index row = 0; row < unknowns; ++row)
      for (int c = 0; c < 3; ++c) {
        Eigen::Index i = 3 * row + c;
        p[i] = fresh[c] * z[i] + beta[c] * p[i];
      }
  }
  return solution;
}

/// The solution X of L X = B for the Laplace system L (symmetric, both triangles stored) of
/// the unseeded voxels and its 3 right-hand sides: by CHOLMOD up to
/// OrientationFieldParams::direct_max_unknowns, else by conjugate_gradients(). Both are
/// deterministic whatever the thread count (CHOLMOD with Debian's reference BLAS runs on
/// one thread).
Columns3 laplace_solution(const Eigen::SparseMatrix<double>& laplacian, const Columns3& rhs,
                          const OrientationFieldParams& params) {
  const Eigen::Index unknowns = laplacian.rows();
  Columns3 solution;
  if (unknowns <= params.direct_max_unknowns) {
    Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Lower> cholesky;
    cholesky.compute(laplacian);
    if (cholesky.info() != Eigen::Success)
      throw Error::runtime("", fmt::format("orientation field: CHOLMOD could not factorise the "
                                           "Laplace system of {} voxels",
                                           unknowns));
    Eigen::MatrixXd columns = rhs;
    solution = cholesky.solve(columns);
    if (cholesky.info() != Eigen::Success)
      throw Error::runtime("", fmt::format("orientation field: CHOLMOD could not solve the "
                                           "Laplace system of {} voxels",
                                           unknowns));
  } else {
    solution = conjugate_gradients(laplacian, rhs, params.cg_tolerance);
  }
  if (!solution.allFinite())
    throw Error::runtime("", fmt::format("orientation field: the Laplace system of {} voxels "
                                         "gave a NaN or infinite value",
                                         unknowns));
  return solution;
}

}  // namespace

int64_t OrientationField::cell_of(double lattice_x, double lattice_y, double lattice_z) const {
  // Lattice indices and low_ are integers below 2^41, so these differences are exact; NaN
  // fails every comparison.
  double x = lattice_x - static_cast<double>(low_[0]);
  double y = lattice_y - static_cast<double>(low_[1]);
  double z = lattice_z - static_cast<double>(low_[2]);
  if (!(x >= 0 && y >= 0 && z >= 0 && x < static_cast<double>(size_[0]) &&
        y < static_cast<double>(size_[1]) && z < static_cast<double>(size_[2])))
    return -1;
  return static_cast<int64_t>(x) +
         size_[0] * (static_cast<int64_t>(y) + size_[1] * static_cast<int64_t>(z));
}

OrientationField OrientationField::build(const StrandSet& strands,
                                         const std::vector<int64_t>& strand_ids,
                                         const OrientationFieldParams& params, int64_t max_voxels) {
  check_params(params, max_voxels);
  if (strand_ids.empty()) throw Error::usage("orientation field: no strands given");
  for (int64_t id : strand_ids)
    if (id < 0 || id >= strands.strand_count())
      throw Error::usage(fmt::format("orientation field: strand {} is outside [0, {})", id,
                                     strands.strand_count()));

  const double voxel_m = params.voxel_m;
  std::vector<Seed> seeds = seeds_of(seed_entries(strands, strand_ids, voxel_m));
  if (seeds.empty())
    throw Error::bad_input("",
                           "orientation field: the strands give no direction (every "
                           "segment of zero length, or opposite segments cancelling)");

  // The box: the seeds' bounding box grown by the band's reach.
  std::vector<std::array<int, 3>> stencil = band_stencil(params.band_m / voxel_m);
  int reach = 0;
  for (const auto& offset : stencil) reach = std::max(reach, offset[0]);
  OrientationField field;
  field.voxel_m_ = voxel_m;
  std::vector<std::array<int64_t, 3>> seed_voxels;
  for (const Seed& seed : seeds) seed_voxels.push_back(seed.voxel);
  field.place_box(seed_voxels, reach, max_voxels);

  // The band: every voxel within the stencil of a seed (all inside the box by its margin).
  const int64_t size_x = field.size_[0], size_xy = field.size_[0] * field.size_[1];
  std::vector<int64_t> stencil_cells;
  for (const auto& offset : stencil)
    stencil_cells.push_back(offset[0] + size_x * offset[1] + size_xy * offset[2]);
  std::vector<int64_t> seed_cells;
  std::vector<Eigen::Vector3d> seed_directions;
  for (const Seed& seed : seeds) {
    seed_cells.push_back((seed.voxel[0] - field.low_[0]) + size_x * (seed.voxel[1] - field.low_[1]) +
                         size_xy * (seed.voxel[2] - field.low_[2]));
    seed_directions.push_back(seed.direction);
  }
  field.mark_band(seed_cells, seed_directions, stencil_cells);
  field.check_band_joined();
  field.interpolate_unseeded(params);
  return field;
}

void OrientationField::place_box(const std::vector<std::array<int64_t, 3>>& seed_voxels, int reach,
                                 int64_t max_voxels) {
  double box_voxels = 1;
  for (int axis = 0; axis < 3; ++axis) {
    int64_t low = seed_voxels.front()[axis], high = low;
    for (const auto& voxel : seed_voxels) {
      low = std::min(low, voxel[axis]);
      high = std::max(high, voxel[axis]);
    }
    low_[axis] = low - reach;
    size_[axis] = high - low + 1 + 2 * reach;
    box_voxels *= static_cast<double>(size_[axis]);
  }
  if (box_voxels > static_cast<double>(max_voxels))
    throw Error::usage(fmt::format(
        "orientation field: the band's box of {} x {} x {} voxels of {} m exceeds max_voxels = "
        "{} (raise voxel_m)",
        size_[0], size_[1], size_[2], voxel_m_, max_voxels));
}

void OrientationField::mark_band(const std::vector<int64_t>& seed_cells,
                                 const std::vector<Eigen::Vector3d>& seed_directions,
                                 const std::vector<int64_t>& stencil_cells) {
  const int64_t cells = size_[0] * size_[1] * size_[2];
  std::vector<uint8_t> in_band(static_cast<size_t>(cells), 0);
  for (int64_t centre : seed_cells)
    for (int64_t offset : stencil_cells) in_band[static_cast<size_t>(centre + offset)] = 1;

  // Band voxels numbered in lattice order; seeds are in lattice order too.
  band_index_.assign(static_cast<size_t>(cells), -1);
  for (int64_t cell = 0; cell < cells; ++cell) {
    if (!in_band[static_cast<size_t>(cell)]) continue;
    band_index_[static_cast<size_t>(cell)] = static_cast<int32_t>(band_cell_.size());
    band_cell_.push_back(cell);
  }
  const auto band = static_cast<size_t>(band_cell_.size());
  direction_.assign(band, Eigen::Vector3d::Zero());
  seeded_.assign(band, 0);
  for (size_t s = 0; s < seed_cells.size(); ++s) {
    auto voxel = static_cast<size_t>(band_index_[static_cast<size_t>(seed_cells[s])]);
    seeded_[voxel] = 1;
    direction_[voxel] = seed_directions[s];
  }
  seeded_count_ = static_cast<int64_t>(seed_cells.size());
}

std::array<int32_t, 6> OrientationField::band_neighbours(size_t voxel) const {
  const int64_t size_x = size_[0], size_xy = size_[0] * size_[1];
  int64_t cell = band_cell_[voxel];
  int64_t x = cell % size_x, y = (cell / size_x) % size_[1], z = cell / size_xy;
  std::array<int32_t, 6> result;
  auto at = [&](bool inside, int64_t neighbour) {
    return inside ? band_index_[static_cast<size_t>(neighbour)] : -1;
  };
  result[0] = at(z > 0, cell - size_xy);
  result[1] = at(y > 0, cell - size_x);
  result[2] = at(x > 0, cell - 1);
  result[3] = at(x + 1 < size_x, cell + 1);
  result[4] = at(y + 1 < size_[1], cell + size_x);
  result[5] = at(z + 1 < size_[2], cell + size_xy);
  return result;
}

void OrientationField::check_band_joined() const {
  const size_t band = band_cell_.size();
  std::vector<uint8_t> reached(seeded_);
  std::vector<size_t> queue;
  for (size_t voxel = 0; voxel < band; ++voxel)
    if (reached[voxel]) queue.push_back(voxel);
  for (size_t next = 0; next < queue.size(); ++next)
    for (int32_t neighbour : band_neighbours(queue[next]))
      if (neighbour >= 0 && !reached[static_cast<size_t>(neighbour)]) {
        reached[static_cast<size_t>(neighbour)] = 1;
        queue.push_back(static_cast<size_t>(neighbour));
      }
  if (queue.size() != band)
    throw Error::runtime("", fmt::format("orientation field: {} band voxels are not joined to "
                                         "any seed (cannot happen: the band is grown from "
                                         "the seeds)",
                                         band - queue.size()));
}

void OrientationField::interpolate_unseeded(const OrientationFieldParams& params) {
  // For each unseeded voxel i, sum over band neighbours j of (x_i - x_j) = 0, seeded
  // neighbours moved to the right-hand side. Unknowns are numbered in band order, so a
  // voxel's +x, +y, +z neighbours follow it and the lower triangle is written column by
  // column in order.
  const size_t band = band_cell_.size();
  std::vector<int32_t> unknown(band, -1);
  int32_t unknowns = 0;
  for (size_t voxel = 0; voxel < band; ++voxel)
    if (!seeded_[voxel]) unknown[voxel] = unknowns++;
  if (unknowns == 0) return;

  // The full symmetric matrix, column by column; a column's rows ascend as -z, -y, -x,
  // itself, +x, +y, +z, since unknowns are numbered in lattice order.
  Eigen::SparseMatrix<double> laplacian(unknowns, unknowns);
  laplacian.reserve(7 * static_cast<Eigen::Index>(unknowns));
  Columns3 rhs = Columns3::Zero(unknowns, 3);
  for (size_t voxel = 0; voxel < band; ++voxel) {
    int32_t column = unknown[voxel];
    if (column < 0) continue;
    std::array<int32_t, 6> around = band_neighbours(voxel);
    int degree = 0;
    for (int32_t neighbour : around) {
      if (neighbour < 0) continue;
      ++degree;
      if (seeded_[static_cast<size_t>(neighbour)])
        rhs.row(column) += direction_[static_cast<size_t>(neighbour)].transpose();
    }
    if (degree == 0)  // the band is grown in lattice steps from the seeds: cannot happen
      throw Error::runtime("", "orientation field: a band voxel has no band neighbour");
    laplacian.startVec(column);
    for (int side = 0; side < 6; ++side) {
      if (side == 3) laplacian.insertBack(column, column) = degree;
      int32_t neighbour = around[static_cast<size_t>(side)];
      if (neighbour >= 0 && unknown[static_cast<size_t>(neighbour)] >= 0)
        laplacian.insertBack(unknown[static_cast<size_t>(neighbour)], column) = -1;
    }
  }
  laplacian.finalize();
  Columns3 solution = laplace_solution(laplacian, rhs, params);
  for (size_t voxel = 0; voxel < band; ++voxel) {
    int32_t row = unknown[voxel];
    if (row < 0) continue;
    // A convex blend of unit seeds: at most 1 long, zero only where seeds cancel.
    Eigen::Vector3d value = solution.row(row).transpose();
    double norm = value.norm();
    direction_[voxel] = norm > 1e-12 ? Eigen::Vector3d(value / norm) : Eigen::Vector3d::Zero();
  }
}

bool OrientationField::contains(const Eigen::Vector3d& point_m) const {
  if (band_index_.empty()) return false;
  Eigen::Vector3d position = lattice_position(point_m, voxel_m_);
  int64_t cell =
      cell_of(std::floor(position.x()), std::floor(position.y()), std::floor(position.z()));
  return cell >= 0 && band_index_[static_cast<size_t>(cell)] >= 0;
}

std::optional<Eigen::Vector3d> OrientationField::direction(const Eigen::Vector3d& point_m) const {
  if (band_index_.empty()) return std::nullopt;
  Eigen::Vector3d position = lattice_position(point_m, voxel_m_);
  int64_t own =
      cell_of(std::floor(position.x()), std::floor(position.y()), std::floor(position.z()));
  if (own < 0 || band_index_[static_cast<size_t>(own)] < 0) return std::nullopt;

  // Trilinear weights between the 8 voxel centres around the point. The point lies in
  // the box, so these lattice indices are small and the casts exact; the own voxel is one
  // of the corners, with weight >= 1/8.
  Eigen::Vector3d centred = position - Eigen::Vector3d::Constant(0.5);
  int64_t base[3];
  double fraction[3];
  for (int axis = 0; axis < 3; ++axis) {
    double floored = std::floor(centred[axis]);
    base[axis] = static_cast<int64_t>(floored) - low_[axis];
    fraction[axis] = centred[axis] - floored;
  }
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double weights = 0;
  for (int dz = 0; dz < 2; ++dz) {
    int64_t z = base[2] + dz;
    if (z < 0 || z >= size_[2]) continue;
    double weight_z = dz ? fraction[2] : 1 - fraction[2];
    for (int dy = 0; dy < 2; ++dy) {
      int64_t y = base[1] + dy;
      if (y < 0 || y >= size_[1]) continue;
      double weight_yz = weight_z * (dy ? fraction[1] : 1 - fraction[1]);
      const int64_t row = size_[0] * (y + size_[1] * z);
      for (int dx = 0; dx < 2; ++dx) {
        int64_t x = base[0] + dx;
        if (x < 0 || x >= size_[0]) continue;
        int32_t voxel = band_index_[static_cast<size_t>(row + x)];
        if (voxel < 0) continue;
        double weight = weight_yz * (dx ? fraction[0] : 1 - fraction[0]);
        sum += weight * direction_[static_cast<size_t>(voxel)];
        weights += weight;
      }
    }
  }
  // Renormalising the weights does not change the direction; only the vanishing test
  // needs their sum.
  double norm = sum.norm();
  if (!(norm > 1e-9 * weights)) return std::nullopt;
  return Eigen::Vector3d(sum / norm);
}

Eigen::Vector3d OrientationField::box_low_m() const {
  return Eigen::Vector3d(static_cast<double>(low_[0]), static_cast<double>(low_[1]),
                         static_cast<double>(low_[2])) *
         voxel_m_;
}

Eigen::Vector3d OrientationField::box_high_m() const {
  return Eigen::Vector3d(static_cast<double>(low_[0] + size_[0]),
                         static_cast<double>(low_[1] + size_[1]),
                         static_cast<double>(low_[2] + size_[2])) *
         voxel_m_;
}

Eigen::Vector3d OrientationField::voxel_centre_m(int64_t band_voxel) const {
  int64_t cell = band_cell_[static_cast<size_t>(band_voxel)];
  int64_t x = cell % size_[0], y = (cell / size_[0]) % size_[1], z = cell / (size_[0] * size_[1]);
  return Eigen::Vector3d(static_cast<double>(low_[0] + x) + 0.5,
                         static_cast<double>(low_[1] + y) + 0.5,
                         static_cast<double>(low_[2] + z) + 0.5) *
         voxel_m_;
}

}  // namespace hair
