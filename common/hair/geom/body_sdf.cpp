#include "hair/geom/body_sdf.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <unordered_map>

#include "hair/core/error.h"

namespace hair {
namespace {

/// Voxels nearer the surface than this many voxels are walls: two 6-neighbours on
/// opposite sides of the surface are one voxel apart, so one of them is at most half a
/// voxel from it, and the components of the other voxels never cross the surface.
constexpr double kWallVoxels = 0.6;
/// A component whose deepest voxel is at least this many voxels from the surface takes
/// the winding number's sign there; shallower ones are thin pockets (inside an ear, a
/// lip) whose voxels keep their own pseudo-normal signs.
constexpr double kDeepVoxels = 2.0;
/// Side of the blocks of voxels that share a list of candidate triangles, in voxels.
constexpr int kBlockVoxels = 4;
/// Newton steps of push_out() and how far beyond the clearance they aim, in voxels.
constexpr int kPushOutSteps = 16;
constexpr double kPushOutOvershootVoxels = 0.01;
/// Gradient norm below which push_out() steps no farther than where |g| is this.
constexpr double kPushOutMinGradient = 0.5;

/// Voxels along each axis to cover [low - band, high + band] at `voxel_m`, checked
/// against `max_voxels` before anything is allocated.
Eigen::Vector3i grid_dims(const Eigen::Vector3d& box_low, const Eigen::Vector3d& box_high,
                          double voxel_m, double band_m, int64_t max_voxels,
                          const std::string& source) {
  Eigen::Vector3d size_m = (box_high - box_low).array() + 2 * band_m;
  Eigen::Vector3d counts = (size_m / voxel_m).array().ceil() + 1;
  double total = counts.prod();
  if (!(total <= static_cast<double>(max_voxels)) ||
      !(counts.maxCoeff() < std::numeric_limits<int>::max()))
    throw Error::bad_input(
        source, fmt::format("body SDF: the box grown by the band ({:.3f} x "
                            "{:.3f} x {:.3f} m) at {} m needs {:.0f} voxels, "
                            "more than the {} allowed",
                            size_m.x(), size_m.y(), size_m.z(), voxel_m, total, max_voxels));
  return counts.cast<int>();
}

void check_inputs(const Points3f& vertices, const Triangles3i& triangles,
                  const Eigen::Vector3d& box_low, const Eigen::Vector3d& box_high, double voxel_m,
                  double band_m, const std::string& source) {
  if (vertices.rows() == 0 || triangles.rows() == 0)
    throw Error::bad_input(source, fmt::format("body SDF: the body mesh is empty ({} vertices, {} "
                                               "triangles)",
                                               vertices.rows(), triangles.rows()));
  for (Eigen::Index v = 0; v < vertices.rows(); ++v)
    if (!vertices.row(v).allFinite())
      throw Error::bad_input(source, fmt::format("body SDF: vertex {} is not finite", v));
  if (triangles.minCoeff() < 0 || triangles.maxCoeff() >= vertices.rows())
    throw Error::bad_input(source, fmt::format("body SDF: a triangle names a vertex outside "
                                               "[0, {})",
                                               vertices.rows()));
  if (!box_low.allFinite() || !box_high.allFinite())
    throw Error::bad_input(source, "body SDF: the box is not finite");
  if ((box_high.array() < box_low.array()).any())
    throw Error::bad_input(source,
                           "body SDF: the box is empty (its high corner is below its low "
                           "corner on some axis)");
  if (!(voxel_m > 0) || !std::isfinite(voxel_m))
    throw Error::bad_input(
        source, fmt::format("body SDF: voxel size {} m is not a positive number", voxel_m));
  if (!(band_m >= voxel_m) || !std::isfinite(band_m))
    throw Error::bad_input(
        source,
        fmt::format("body SDF: band {} m is narrower than a voxel ({} m)", band_m, voxel_m));
}

/// The body in double precision, wound counter-clockwise seen from outside, holes capped.
struct Surface {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int32_t, 3>> triangles;

  Eigen::Vector3d corner(size_t triangle, int k) const {
    return vertices[static_cast<size_t>(triangles[triangle][static_cast<size_t>(k)])];
  }
};

uint64_t edge_key(int32_t a, int32_t b) {
  return (static_cast<uint64_t>(static_cast<uint32_t>(a)) << 32) | static_cast<uint32_t>(b);
}

/// Caps the holes of a mesh: the edges that only one triangle uses are chained into
/// loops (each edge in its triangle's direction), and every closed loop gets a fan of
/// triangles to its centroid, wound against the loop so that the winding stays
/// consistent. Chains that do not close (non-manifold rims) stay open.
void cap_holes(Surface& surface) {
  std::unordered_map<uint64_t, int> uses;  // undirected edge -> triangles using it
  for (const auto& triangle : surface.triangles)
    for (int k = 0; k < 3; ++k) {
      int32_t a = triangle[static_cast<size_t>(k)], b = triangle[static_cast<size_t>((k + 1) % 3)];
      ++uses[edge_key(std::min(a, b), std::max(a, b))];
    }
  std::map<int32_t, std::vector<int32_t>> rim;  // start vertex -> ends of its rim edges
  for (const auto& triangle : surface.triangles)
    for (int k = 0; k < 3; ++k) {
      int32_t a = triangle[static_cast<size_t>(k)], b = triangle[static_cast<size_t>((k + 1) % 3)];
      if (uses[edge_key(std::min(a, b), std::max(a, b))] == 1) rim[a].push_back(b);
    }
  for (auto& [start, ends] : rim) std::sort(ends.begin(), ends.end(), std::greater<>());
  for (auto& [start, ends] : rim) {
    while (!ends.empty()) {
      std::vector<int32_t> loop = {start};
      int32_t at = start;
      while (true) {
        auto next = rim.find(at);
        if (next == rim.end() || next->second.empty()) break;
        at = next->second.back();
        next->second.pop_back();
        if (at == start) break;
        loop.push_back(at);
      }
      if (at != start || loop.size() < 3) continue;
      Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
      for (int32_t v : loop) centroid += surface.vertices[static_cast<size_t>(v)];
      auto centre = static_cast<int32_t>(surface.vertices.size());
      surface.vertices.push_back(centroid / static_cast<double>(loop.size()));
      for (size_t i = 0; i < loop.size(); ++i)
        surface.triangles.push_back({loop[(i + 1) % loop.size()], loop[i], centre});
    }
  }
}

/// Copies the mesh, turning every triangle round when the signed volume (divergence
/// theorem: the sum of a . (b x c) / 6) says it is wound clockwise seen from outside,
/// then caps its holes.
Surface body_surface(const Points3f& vertices, const Triangles3i& triangles) {
  Surface surface;
  surface.vertices.resize(static_cast<size_t>(vertices.rows()));
  for (Eigen::Index v = 0; v < vertices.rows(); ++v)
    surface.vertices[static_cast<size_t>(v)] = vertices.row(v).cast<double>().transpose();
  surface.triangles.resize(static_cast<size_t>(triangles.rows()));
  double volume = 0;
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    auto& triangle = surface.triangles[static_cast<size_t>(t)];
    triangle = {triangles(t, 0), triangles(t, 1), triangles(t, 2)};
    volume += surface.corner(static_cast<size_t>(t), 0)
                  .dot(surface.corner(static_cast<size_t>(t), 1)
                           .cross(surface.corner(static_cast<size_t>(t), 2)));
  }
  if (volume < 0)
    for (auto& triangle : surface.triangles) std::swap(triangle[1], triangle[2]);
  cap_holes(surface);
  return surface;
}

/// Generalized winding number of the surface around `point` (Jacobson, Kavan and
/// Sorkine-Hornung 2013, eq. 6): the triangles' signed solid angles (van Oosterom and
/// Strackee 1983) over 4 pi. 1 inside a closed surface, 0 outside; the union of
/// overlapping closed parts counts 1 or more.
double winding_number(const Surface& surface, const Eigen::Vector3d& point) {
  double total = 0;
  for (size_t t = 0; t < surface.triangles.size(); ++t) {
    Eigen::Vector3d a = surface.corner(t, 0) - point;
    Eigen::Vector3d b = surface.corner(t, 1) - point;
    Eigen::Vector3d c = surface.corner(t, 2) - point;
    double la = a.norm(), lb = b.norm(), lc = c.norm();
    double numerator = a.dot(b.cross(c));
    double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    total += 2 * std::atan2(numerator, denominator);
  }
  return total / (4 * std::numbers::pi);
}

/// The feature of a triangle nearest a point: a corner (first >= 0, second < 0), an
/// edge (both >= 0) or the face (both < 0); corners are 0, 1, 2.
struct NearestFeature {
  Eigen::Vector3d point;
  int first = -1;
  int second = -1;
};

/// closest_point_on_triangle() (Ericson, Real-Time Collision Detection, 5.1.5), also
/// saying which Voronoi region of the triangle the point fell in.
NearestFeature nearest_feature(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                               const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return {a, 0, -1};
  Eigen::Vector3d bp = p - b;
  double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return {b, 1, -1};
  double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return {a + ab * (d1 / (d1 - d3)), 0, 1};
  Eigen::Vector3d cp = p - c;
  double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return {c, 2, -1};
  double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return {a + ac * (d2 / (d2 - d6)), 0, 2};
  double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return {b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))), 1, 2};
  double denominator = va + vb + vc;
  if (denominator <= 0) return {a, 0, -1};  // degenerate triangle
  return {a + ab * (vb / denominator) + ac * (vc / denominator), -1, -1};
}

/// Distance from `p` to triangle `t` of the surface.
double triangle_distance(const Surface& surface, size_t t, const Eigen::Vector3d& p) {
  return (nearest_feature(p, surface.corner(t, 0), surface.corner(t, 1), surface.corner(t, 2))
              .point -
          p)
      .norm();
}

/// Angle-weighted pseudo-normals of faces, edges and vertices (Baerentzen and Aanaes,
/// "Signed distance computation using the angle weighted pseudonormal", IEEE TVCG 11(3),
/// 2005): for a point p whose nearest point on a closed, consistently wound surface is
/// c, (p - c) . n > 0 exactly when p is outside, n being the pseudo-normal of the
/// feature (face, edge or vertex) that c lies on.
class PseudoNormals {
 public:
  explicit PseudoNormals(const Surface& surface)
      : face_(surface.triangles.size()), vertex_(surface.vertices.size(), Eigen::Vector3d::Zero()) {
    for (size_t t = 0; t < surface.triangles.size(); ++t) {
      std::array<Eigen::Vector3d, 3> corner = {surface.corner(t, 0), surface.corner(t, 1),
                                               surface.corner(t, 2)};
      Eigen::Vector3d normal = (corner[1] - corner[0]).cross(corner[2] - corner[0]);
      if (normal.norm() > 0) normal.normalize();
      face_[t] = normal;
      for (int k = 0; k < 3; ++k) {
        const auto& at = corner[static_cast<size_t>(k)];
        Eigen::Vector3d along = corner[static_cast<size_t>((k + 1) % 3)] - at;
        Eigen::Vector3d back = corner[static_cast<size_t>((k + 2) % 3)] - at;
        double angle = std::atan2(along.cross(back).norm(), along.dot(back));
        int32_t v = surface.triangles[t][static_cast<size_t>(k)];
        int32_t w = surface.triangles[t][static_cast<size_t>((k + 1) % 3)];
        vertex_[static_cast<size_t>(v)] += angle * normal;
        // (Eigen leaves a default-constructed vector unset: start from zero.)
        edge_.try_emplace(edge_key(std::min(v, w), std::max(v, w)), Eigen::Vector3d::Zero())
            .first->second += normal;
      }
    }
  }

  /// Pseudo-normal of `feature` of `triangle` (not unit: only its direction counts).
  Eigen::Vector3d at(const Surface& surface, size_t triangle, const NearestFeature& feature) const {
    if (feature.first < 0) return face_[triangle];
    int32_t v = surface.triangles[triangle][static_cast<size_t>(feature.first)];
    if (feature.second < 0) return vertex_[static_cast<size_t>(v)];
    int32_t w = surface.triangles[triangle][static_cast<size_t>(feature.second)];
    return edge_.at(edge_key(std::min(v, w), std::max(v, w)));
  }

 private:
  std::vector<Eigen::Vector3d> face_;
  std::vector<Eigen::Vector3d> vertex_;
  std::unordered_map<uint64_t, Eigen::Vector3d> edge_;
};

/// The voxel lattice: voxel (i, j, k) has its centre at origin + voxel * (i, j, k) and
/// index i + nx * (j + ny * k).
struct Lattice {
  Eigen::Vector3d origin_m;
  double voxel_m = 0;
  Eigen::Vector3i dims;

  size_t size() const {
    return static_cast<size_t>(dims.x()) * static_cast<size_t>(dims.y()) *
           static_cast<size_t>(dims.z());
  }
  size_t index(int x, int y, int z) const {
    return static_cast<size_t>(x) +
           static_cast<size_t>(dims.x()) *
               (static_cast<size_t>(y) + static_cast<size_t>(dims.y()) * static_cast<size_t>(z));
  }
  Eigen::Vector3i coordinates(size_t index) const {
    auto nx = static_cast<size_t>(dims.x()), ny = static_cast<size_t>(dims.y());
    return {static_cast<int>(index % nx), static_cast<int>((index / nx) % ny),
            static_cast<int>(index / (nx * ny))};
  }
  Eigen::Vector3d centre(const Eigen::Vector3i& voxel) const {
    return origin_m + voxel_m * voxel.cast<double>();
  }
};

/// Exact unsigned distance from every voxel centre to the surface, up to the band.
struct BandDistances {
  std::vector<float> distance_m;  ///< per voxel; band_m where no triangle is nearer
  std::vector<int32_t> nearest;   ///< a nearest triangle, -1 beyond the band
};

/// Distances by blocks of kBlockVoxels^3 voxels: each block lists the triangles whose
/// bounding sphere comes within the band of the block's bounding sphere, sorted by their
/// distance from the block's centre, and each of its voxels takes the nearest of them,
/// stopping at the first whose distance from the centre, less the block's radius, is
/// more than its best so far. Every triangle within the band of a voxel is on its
/// block's list, so the distances are exact (in double, stored as float), unlike
/// OpenVDB's, which propagates nearest triangles from voxel to voxel beyond the first
/// voxel. Blocks run in parallel, each writing only its own voxels in a fixed order, so
/// the result does not depend on the thread count.
BandDistances band_distances(const Surface& surface, const Lattice& lattice, double band_m) {
  const size_t triangle_count = surface.triangles.size();
  std::vector<Eigen::Vector3d> centroid(triangle_count);
  std::vector<double> radius(triangle_count);
  for (size_t t = 0; t < triangle_count; ++t) {
    centroid[t] = (surface.corner(t, 0) + surface.corner(t, 1) + surface.corner(t, 2)) / 3.0;
    radius[t] = std::max({(surface.corner(t, 0) - centroid[t]).norm(),
                          (surface.corner(t, 1) - centroid[t]).norm(),
                          (surface.corner(t, 2) - centroid[t]).norm()});
  }

  const double block_m = kBlockVoxels * lattice.voxel_m;
  const Eigen::Vector3i blocks = (lattice.dims.array() + kBlockVoxels - 1) / kBlockVoxels;
  const size_t block_count = static_cast<size_t>(blocks.x()) * static_cast<size_t>(blocks.y()) *
                             static_cast<size_t>(blocks.z());
  const double block_radius = 0.5 * (kBlockVoxels - 1) * lattice.voxel_m * std::sqrt(3.0);
  auto block_index = [&](const Eigen::Vector3i& b) {
    return static_cast<size_t>(b.x()) +
           static_cast<size_t>(blocks.x()) *
               (static_cast<size_t>(b.y()) + static_cast<size_t>(blocks.y()) * b.z());
  };
  auto block_centre = [&](const Eigen::Vector3i& b) {
    return Eigen::Vector3d(lattice.origin_m + block_m * b.cast<double>() +
                           Eigen::Vector3d::Constant(0.5 * (kBlockVoxels - 1) * lattice.voxel_m));
  };
  // Candidate lists in CSR form, in triangle order: count, then fill.
  auto for_each_block_near = [&](size_t t, const auto& visit) {
    Eigen::Vector3d reach = Eigen::Vector3d::Constant(radius[t] + band_m + block_radius);
    Eigen::Vector3d low = ((centroid[t] - reach - lattice.origin_m) / block_m).array().floor();
    Eigen::Vector3d high = ((centroid[t] + reach - lattice.origin_m) / block_m).array().floor();
    Eigen::Vector3i first = low.cwiseMax(0).cwiseMin(blocks.cast<double>()).cast<int>();
    Eigen::Vector3i last =
        high.cwiseMax(-1).cwiseMin((blocks - Eigen::Vector3i::Ones()).cast<double>()).cast<int>();
    for (int z = first.z(); z <= last.z(); ++z)
      for (int y = first.y(); y <= last.y(); ++y)
        for (int x = first.x(); x <= last.x(); ++x) {
          Eigen::Vector3i b(x, y, z);
          if ((block_centre(b) - centroid[t]).norm() - radius[t] - block_radius <= band_m)
            visit(block_index(b));
        }
  };
  std::vector<int64_t> offsets(block_count + 1, 0);
  for (size_t t = 0; t < triangle_count; ++t)
    for_each_block_near(t, [&](size_t b) { ++offsets[b + 1]; });
  for (size_t b = 0; b < block_count; ++b) offsets[b + 1] += offsets[b];
  std::vector<int32_t> candidates(static_cast<size_t>(offsets.back()));
  std::vector<int64_t> filled(offsets.begin(), offsets.end() - 1);
  for (size_t t = 0; t < triangle_count; ++t)
    for_each_block_near(t, [&](size_t b) {
      candidates[static_cast<size_t>(filled[b]++)] = static_cast<int32_t>(t);
    });

  BandDistances band;
  band.distance_m.assign(lattice.size(), static_cast<float>(band_m));
  band.nearest.assign(lattice.size(), -1);
#pragma omp parallel
  {
    std::vector<std::pair<double, int32_t>> nearby;  // (lower bound from the block's centre, id)
#pragma omp for schedule(dynamic)
    for (int64_t b = 0; b < static_cast<int64_t>(block_count); ++b) {
      const auto first = static_cast<size_t>(offsets[static_cast<size_t>(b)]);
      const auto last = static_cast<size_t>(offsets[static_cast<size_t>(b) + 1]);
      if (first == last) continue;
      Eigen::Vector3i block(static_cast<int>(b % blocks.x()),
                            static_cast<int>((b / blocks.x()) % blocks.y()),
                            static_cast<int>(b / (static_cast<int64_t>(blocks.x()) * blocks.y())));
      // Nearest candidates first, by their exact distance from the block's centre: a
      // voxel stops at the first one that, less the block's radius, exceeds its best
      // distance so far (which starts from its predecessor's nearest triangle).
      Eigen::Vector3d centre = block_centre(block);
      nearby.clear();
      for (size_t c = first; c < last; ++c) {
        auto t = static_cast<size_t>(candidates[c]);
        double from_centre = triangle_distance(surface, t, centre);
        if (from_centre - block_radius <= band_m) nearby.push_back({from_centre, candidates[c]});
      }
      if (nearby.empty()) continue;
      std::sort(nearby.begin(), nearby.end());
      Eigen::Vector3i low = kBlockVoxels * block;
      Eigen::Vector3i high = (low + Eigen::Vector3i::Constant(kBlockVoxels)).cwiseMin(lattice.dims);
      int32_t previous = -1;
      for (int z = low.z(); z < high.z(); ++z)
        for (int y = low.y(); y < high.y(); ++y)
          for (int x = low.x(); x < high.x(); ++x) {
            Eigen::Vector3d p = lattice.centre({x, y, z});
            double best = band_m;
            int32_t nearest = -1;
            if (previous >= 0) {
              double d = triangle_distance(surface, static_cast<size_t>(previous), p);
              if (d < best) {
                best = d;
                nearest = previous;
              }
            }
            for (const auto& [bound, id] : nearby) {
              if (bound - block_radius > best) break;
              auto t = static_cast<size_t>(id);
              if ((p - centroid[t]).squaredNorm() > (best + radius[t]) * (best + radius[t]))
                continue;
              double d = triangle_distance(surface, t, p);
              if (d < best) {
                best = d;
                nearest = id;
              }
            }
            previous = nearest;
            size_t i = lattice.index(x, y, z);
            band.distance_m[i] = static_cast<float>(best);
            band.nearest[i] = nearest;
          }
    }
  }
  return band;
}

/// A run of voxels off the walls along x: voxels [begin, end) of row y + ny * z.
struct Run {
  size_t row = 0;
  int begin = 0;
  int end = 0;
};

/// Runs of the voxels farther than `wall_m` from the surface, row by row (rows in index
/// order, runs along x), and where each row's runs start (#rows + 1).
std::vector<Run> off_wall_runs(const Lattice& lattice, const std::vector<float>& distance_m,
                               float wall_m, std::vector<size_t>& row_start) {
  const size_t rows = static_cast<size_t>(lattice.dims.y()) * static_cast<size_t>(lattice.dims.z());
  const int nx = lattice.dims.x();
  std::vector<Run> runs;
  row_start.assign(rows + 1, 0);
  for (size_t row = 0; row < rows; ++row) {
    row_start[row] = runs.size();
    const float* line = distance_m.data() + row * static_cast<size_t>(nx);
    for (int x = 0; x < nx;) {
      if (line[x] <= wall_m) {
        ++x;
        continue;
      }
      Run run{row, x, x};
      while (run.end < nx && line[run.end] > wall_m) ++run.end;
      runs.push_back(run);
      x = run.end;
    }
  }
  row_start[rows] = runs.size();
  return runs;
}

/// 6-connected components of the runs: each run is joined to the runs it overlaps in the
/// rows below it in y and in z (union-find whose root is always the lowest run), and
/// components are numbered by their first run. Returns the component of every run.
std::vector<int32_t> run_components(const Lattice& lattice, const std::vector<Run>& runs,
                                    const std::vector<size_t>& row_start, size_t& count) {
  std::vector<size_t> parent(runs.size());
  for (size_t r = 0; r < runs.size(); ++r) parent[r] = r;
  auto root = [&](size_t r) {
    while (parent[r] != r) r = parent[r] = parent[parent[r]];
    return r;
  };
  auto join = [&](size_t a, size_t b) {
    a = root(a);
    b = root(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  };
  const auto ny = static_cast<size_t>(lattice.dims.y());
  for (size_t row = 0; row + 1 < row_start.size(); ++row) {
    std::array<bool, 2> has = {row % ny > 0, row >= ny};
    std::array<size_t, 2> below = {row - 1, row - ny};
    for (int side = 0; side < 2; ++side) {
      if (!has[static_cast<size_t>(side)]) continue;
      size_t other = below[static_cast<size_t>(side)];
      size_t a = row_start[row], b = row_start[other];
      while (a < row_start[row + 1] && b < row_start[other + 1]) {
        if (runs[a].begin < runs[b].end && runs[b].begin < runs[a].end) join(a, b);
        if (runs[a].end < runs[b].end)
          ++a;
        else
          ++b;
      }
    }
  }
  std::vector<int32_t> component(runs.size(), -1);
  count = 0;
  for (size_t r = 0; r < runs.size(); ++r) {
    size_t first = root(r);
    if (first == r)
      component[r] = static_cast<int32_t>(count++);
    else
      component[r] = component[first];
  }
  return component;
}

/// Turns the unsigned distances negative inside, as the class comment says: wall voxels
/// by the pseudo-normal at their nearest point; the 6-connected components of the others
/// by the winding number at their deepest voxel, or voxel by voxel by the pseudo-normal
/// for shallow components.
void sign_distances(const Surface& surface, const Lattice& lattice, BandDistances& band) {
  std::vector<float>& distance_m = band.distance_m;
  const auto wall_m = static_cast<float>(kWallVoxels * lattice.voxel_m);
  PseudoNormals normals(surface);
  auto pseudo_normal_inside = [&](size_t i) {
    int32_t t = band.nearest[i];
    if (t < 0) return false;  // beyond the band: only components reach here
    Eigen::Vector3d p = lattice.centre(lattice.coordinates(i));
    auto triangle = static_cast<size_t>(t);
    NearestFeature feature = nearest_feature(
        p, surface.corner(triangle, 0), surface.corner(triangle, 1), surface.corner(triangle, 2));
    return (p - feature.point).dot(normals.at(surface, triangle, feature)) < 0;
  };
  for (size_t i = 0; i < distance_m.size(); ++i)
    if (distance_m[i] <= wall_m && pseudo_normal_inside(i)) distance_m[i] = -distance_m[i];

  std::vector<size_t> row_start;
  std::vector<Run> runs = off_wall_runs(lattice, distance_m, wall_m, row_start);
  size_t component_count = 0;
  std::vector<int32_t> component = run_components(lattice, runs, row_start, component_count);
  const auto nx = static_cast<size_t>(lattice.dims.x());
  // Deepest voxel of each component (the first one, on ties).
  std::vector<size_t> deepest(component_count, 0);
  std::vector<float> depth(component_count, -1);
  for (size_t r = 0; r < runs.size(); ++r) {
    auto c = static_cast<size_t>(component[r]);
    for (int x = runs[r].begin; x < runs[r].end; ++x) {
      size_t i = runs[r].row * nx + static_cast<size_t>(x);
      if (distance_m[i] > depth[c]) {
        depth[c] = distance_m[i];
        deepest[c] = i;
      }
    }
  }
  // Per component: 1 inside, 0 outside, -1 shallow (voxel by voxel).
  std::vector<int> inside(component_count, -1);
  const double deep_m = kDeepVoxels * lattice.voxel_m;
#pragma omp parallel for schedule(dynamic)
  for (size_t c = 0; c < component_count; ++c)
    if (depth[c] >= deep_m || band.nearest[deepest[c]] < 0)
      inside[c] = winding_number(surface, lattice.centre(lattice.coordinates(deepest[c]))) > 0.5;
  for (size_t r = 0; r < runs.size(); ++r) {
    int decided = inside[static_cast<size_t>(component[r])];
    for (int x = runs[r].begin; x < runs[r].end; ++x) {
      size_t i = runs[r].row * nx + static_cast<size_t>(x);
      if (decided == 1 || (decided < 0 && pseudo_normal_inside(i))) distance_m[i] = -distance_m[i];
    }
  }
}

}  // namespace

BodySdf::BodySdf(const Points3f& vertices, const Triangles3i& triangles,
                 const Eigen::Vector3d& box_low, const Eigen::Vector3d& box_high, double voxel_m,
                 double band_m, const std::string& source, int64_t max_voxels)
    : voxel_m_(voxel_m), band_m_(band_m) {
  check_inputs(vertices, triangles, box_low, box_high, voxel_m, band_m, source);
  dims_ = grid_dims(box_low, box_high, voxel_m, band_m, max_voxels, source);
  origin_m_ = box_low - Eigen::Vector3d::Constant(band_m);
  far_corner_m_ = origin_m_ + voxel_m * (dims_ - Eigen::Vector3i::Ones()).cast<double>();

  Surface surface = body_surface(vertices, triangles);
  Lattice lattice{origin_m_, voxel_m, dims_};
  BandDistances band = band_distances(surface, lattice, band_m);
  sign_distances(surface, lattice, band);
  values_ = std::move(band.distance_m);

  // Cells run 0 .. dims - 2 (locate clamps to them); block b holds cells b * kBlockCells
  // .. + kBlockCells - 1, whose corners are voxels b * kBlockCells .. + kBlockCells.
  for (int axis = 0; axis < 3; ++axis)
    block_dims_[axis] = std::max(1, (dims_[axis] - 2) / kBlockCells + 1);
  block_minimum_.assign(static_cast<size_t>(block_dims_.prod()),
                        std::numeric_limits<float>::infinity());
  for (int z = 0; z < dims_.z(); ++z)
    for (int y = 0; y < dims_.y(); ++y)
      for (int x = 0; x < dims_.x(); ++x) {
        float v = value(x, y, z);
        // A voxel on a block boundary is a corner of the cells on both sides.
        for (int bz = std::max(0, (z - 1) / kBlockCells);
             bz <= std::min(block_dims_.z() - 1, z / kBlockCells); ++bz)
          for (int by = std::max(0, (y - 1) / kBlockCells);
               by <= std::min(block_dims_.y() - 1, y / kBlockCells); ++by)
            for (int bx = std::max(0, (x - 1) / kBlockCells);
                 bx <= std::min(block_dims_.x() - 1, x / kBlockCells); ++bx) {
              float& minimum = block_minimum_[static_cast<size_t>(
                  bx + block_dims_.x() * (by + block_dims_.y() * bz))];
              minimum = std::min(minimum, v);
            }
      }
}

bool BodySdf::certainly_farther_than(const Eigen::Vector3d& point_m, double distance_m) const {
  Eigen::Vector3i cell;
  Eigen::Vector3d fraction;
  if (!locate(point_m, cell, fraction)) return band_m_ >= distance_m;
  Eigen::Vector3i block = cell / kBlockCells;
  return block_minimum_[static_cast<size_t>(
             block.x() + block_dims_.x() * (block.y() + block_dims_.y() * block.z()))] >=
         distance_m;
}

bool BodySdf::contains(const Eigen::Vector3d& point_m) const {
  return (point_m.array() >= origin_m_.array()).all() &&
         (point_m.array() <= far_corner_m_.array()).all();
}

bool BodySdf::locate(const Eigen::Vector3d& point_m, Eigen::Vector3i& cell,
                     Eigen::Vector3d& fraction) const {
  if (!contains(point_m)) return false;
  Eigen::Vector3d index = (point_m - origin_m_) / voxel_m_;
  for (int axis = 0; axis < 3; ++axis) {
    int lower = std::clamp(static_cast<int>(std::floor(index[axis])), 0, dims_[axis] - 2);
    cell[axis] = lower;
    fraction[axis] = std::clamp(index[axis] - lower, 0.0, 1.0);
  }
  return true;
}

double BodySdf::distance(const Eigen::Vector3d& point_m) const {
  Eigen::Vector3i cell;
  Eigen::Vector3d f;
  if (!locate(point_m, cell, f)) return band_m_;
  const int x = cell.x(), y = cell.y(), z = cell.z();
  double c00 = value(x, y, z) * (1 - f.x()) + value(x + 1, y, z) * f.x();
  double c10 = value(x, y + 1, z) * (1 - f.x()) + value(x + 1, y + 1, z) * f.x();
  double c01 = value(x, y, z + 1) * (1 - f.x()) + value(x + 1, y, z + 1) * f.x();
  double c11 = value(x, y + 1, z + 1) * (1 - f.x()) + value(x + 1, y + 1, z + 1) * f.x();
  double c0 = c00 * (1 - f.y()) + c10 * f.y();
  double c1 = c01 * (1 - f.y()) + c11 * f.y();
  return c0 * (1 - f.z()) + c1 * f.z();
}

Eigen::Vector3d BodySdf::gradient(const Eigen::Vector3d& point_m) const {
  Eigen::Vector3i cell;
  Eigen::Vector3d f;
  if (!locate(point_m, cell, f)) return Eigen::Vector3d::Zero();
  const int x = cell.x(), y = cell.y(), z = cell.z();
  // Corner values v[dz][dy][dx]; each partial derivative is the difference across the
  // cell along its axis, interpolated over the other two.
  double v[2][2][2];
  for (int dz = 0; dz < 2; ++dz)
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx) v[dz][dy][dx] = value(x + dx, y + dy, z + dz);
  auto lerp = [](double a, double b, double t) { return a + (b - a) * t; };
  double gx = lerp(lerp(v[0][0][1] - v[0][0][0], v[0][1][1] - v[0][1][0], f.y()),
                   lerp(v[1][0][1] - v[1][0][0], v[1][1][1] - v[1][1][0], f.y()), f.z());
  double gy = lerp(lerp(v[0][1][0] - v[0][0][0], v[0][1][1] - v[0][0][1], f.x()),
                   lerp(v[1][1][0] - v[1][0][0], v[1][1][1] - v[1][0][1], f.x()), f.z());
  double gz = lerp(lerp(v[1][0][0] - v[0][0][0], v[1][0][1] - v[0][0][1], f.x()),
                   lerp(v[1][1][0] - v[0][1][0], v[1][1][1] - v[0][1][1], f.x()), f.y());
  return Eigen::Vector3d(gx, gy, gz) / voxel_m_;
}

bool BodySdf::push_out(Eigen::Vector3d& point_m, double clearance_m) const {
  const double target_m = clearance_m + kPushOutOvershootVoxels * voxel_m_;
  bool moved = false;
  for (int step = 0; step < kPushOutSteps; ++step) {
    double distance_m = distance(point_m);
    if (distance_m >= clearance_m) break;
    Eigen::Vector3d g = gradient(point_m);
    double norm = g.norm();
    if (!(norm > 1e-6)) break;
    // Newton's step for distance(p) = target along the gradient, where the field is a
    // distance (|g| near 1). Where |g| is small, between two close surfaces (inside an
    // ear) or at a kink, Newton's step grows as 1 / |g| without bound and throws the point
    // far off the ear. The step is held to twice what is missing.
    point_m += (g / norm) * ((target_m - distance_m) / std::max(norm, kPushOutMinGradient));
    moved = true;
  }
  return moved;
}

}  // namespace hair
