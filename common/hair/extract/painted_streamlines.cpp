#include "hair/extract/painted_streamlines.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace hair {
namespace {

/// The faces' triangles (fans), each with its face, its neighbours across its edges within
/// the set, and the painted flow projected into its plane.
struct PatchTriangles {
  std::vector<std::array<int32_t, 3>> corners;
  std::vector<int64_t> face;
  std::vector<std::array<int32_t, 3>> neighbour;  ///< across edge k (corners k, k+1); -1: border
  std::vector<Eigen::Vector3d> flow;              ///< unit in the plane, or zero: no clear flow
  std::vector<Eigen::Vector3d> normal;
};

uint64_t edge_key(int32_t a, int32_t b) {
  if (a > b) std::swap(a, b);
  return (static_cast<uint64_t>(static_cast<uint32_t>(a)) << 32) | static_cast<uint32_t>(b);
}

Eigen::Vector3d vertex(const PolyMesh& mesh, int32_t id) {
  return mesh.vertices.row(id).cast<double>().transpose();
}

PatchTriangles patch_triangles(const PolyMesh& mesh, const PaintedFlow& flow,
                               std::span<const int64_t> faces) {
  PatchTriangles t;
  for (int64_t face : faces) {
    const int64_t first = mesh.face_offsets[static_cast<size_t>(face)];
    for (int c = 1; c + 1 < mesh.face_size(face); ++c) {
      t.corners.push_back({mesh.face_vertices[static_cast<size_t>(first)],
                           mesh.face_vertices[static_cast<size_t>(first + c)],
                           mesh.face_vertices[static_cast<size_t>(first + c + 1)]});
      t.face.push_back(face);
    }
  }
  const size_t n = t.corners.size();
  t.neighbour.assign(n, {-1, -1, -1});
  t.flow.assign(n, Eigen::Vector3d::Zero());
  t.normal.assign(n, Eigen::Vector3d::Zero());
  std::unordered_map<uint64_t, std::pair<int32_t, int>> open_edges;
  for (size_t i = 0; i < n; ++i) {
    const auto& c = t.corners[i];
    for (int k = 0; k < 3; ++k) {
      uint64_t key = edge_key(c[k], c[(k + 1) % 3]);
      auto [it, inserted] = open_edges.try_emplace(key, static_cast<int32_t>(i), k);
      if (!inserted && it->second.first >= 0) {
        t.neighbour[i][k] = it->second.first;
        t.neighbour[static_cast<size_t>(it->second.first)][it->second.second] = static_cast<int32_t>(i);
        it->second.first = -1;  // a third triangle on the edge is not joined
      }
    }
    Eigen::Vector3d a = vertex(mesh, c[0]), b = vertex(mesh, c[1]), d = vertex(mesh, c[2]);
    Eigen::Vector3d normal = (b - a).cross(d - a);
    if (!(normal.norm() > 0)) continue;
    t.normal[i] = normal.normalized();
    const auto f = static_cast<size_t>(t.face[i]);
    if (!(flow.coherence[f] >= kClearFlowCoherence)) continue;
    Eigen::Vector3d direction = flow.direction[f].cast<double>();
    Eigen::Vector3d in_plane = direction - direction.dot(t.normal[i]) * t.normal[i];
    if (in_plane.norm() > 0.5 * direction.norm()) t.flow[i] = in_plane.normalized();
  }
  return t;
}

/// Points of accepted streamlines in cells of the spacing, to find near neighbours.
class SpacingGrid {
 public:
  explicit SpacingGrid(double cell) : cell_(cell) {}
  void add(const Eigen::Vector3d& point, int32_t line) {
    cells_[key(point)].push_back({point, line});
  }
  /// Whether a point of a streamline other than `line` lies within `radius` (<= cell).
  bool near(const Eigen::Vector3d& point, double radius, int32_t line) const {
    const Eigen::Vector3i centre = cell_of(point);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          auto it = cells_.find(pack(centre + Eigen::Vector3i(dx, dy, dz)));
          if (it == cells_.end()) continue;
          for (const auto& [other, other_line] : it->second)
            if (other_line != line && (other - point).squaredNorm() < radius * radius) return true;
        }
    return false;
  }

 private:
  Eigen::Vector3i cell_of(const Eigen::Vector3d& p) const {
    return (p / cell_).array().floor().cast<int>();
  }
  static uint64_t pack(const Eigen::Vector3i& c) {
    auto part = [](int v) { return static_cast<uint64_t>(static_cast<uint32_t>(v) & 0x1fffff); };
    return (part(c.x()) << 42) | (part(c.y()) << 21) | part(c.z());
  }
  uint64_t key(const Eigen::Vector3d& p) const { return pack(cell_of(p)); }
  double cell_;
  std::unordered_map<uint64_t, std::vector<std::pair<Eigen::Vector3d, int32_t>>> cells_;
};

/// Where the ray from `point` along `direction` (in the triangle's plane) leaves the
/// triangle, other than through edge `entered` (-1: none): the edge and the point.
bool exit_of(const PolyMesh& mesh, const PatchTriangles& t, int32_t triangle, int entered,
             const Eigen::Vector3d& point, const Eigen::Vector3d& direction, int& edge,
             Eigen::Vector3d& exit) {
  const auto& c = t.corners[static_cast<size_t>(triangle)];
  const Eigen::Vector3d& n = t.normal[static_cast<size_t>(triangle)];
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    if (k == entered) continue;
    Eigen::Vector3d a = vertex(mesh, c[k]), b = vertex(mesh, c[(k + 1) % 3]);
    // point + l d = a + m (b - a), in the plane: cross with n to get two equations.
    Eigen::Vector3d e = b - a, w = a - point;
    const double denominator = direction.cross(e).dot(n);
    if (std::abs(denominator) < 1e-15) continue;
    const double l = w.cross(e).dot(n) / denominator;
    const double m = w.cross(direction).dot(n) / denominator;
    if (l > 1e-12 && m >= -1e-9 && m <= 1 + 1e-9 && l < best) {
      best = l;
      edge = k;
      exit = a + std::clamp(m, 0.0, 1.0) * e;
    }
  }
  return std::isfinite(best);
}

/// One way of a streamline from the centroid of `seed` along `sense`: the points passed
/// (the centroid first) and the face of each segment.
void trace(const PolyMesh& mesh, const PatchTriangles& t, int32_t seed,
           const Eigen::Vector3d& sense, const StreamlineParams& params, const SpacingGrid& grid,
           int32_t line, std::vector<Eigen::Vector3d>& points, std::vector<int64_t>& segment_face) {
  const auto& c = t.corners[static_cast<size_t>(seed)];
  Eigen::Vector3d point = (vertex(mesh, c[0]) + vertex(mesh, c[1]) + vertex(mesh, c[2])) / 3;
  points.assign(1, point);
  segment_face.clear();
  const double min_cosine = std::cos(params.max_turn_deg * M_PI / 180);
  Eigen::Vector3d previous = sense;
  int32_t triangle = seed;
  int entered = -1;
  for (int64_t step = 0; step < params.max_crossings; ++step) {
    Eigen::Vector3d direction = t.flow[static_cast<size_t>(triangle)];
    if (direction.isZero()) break;
    if (direction.dot(previous) < 0) direction = -direction;
    if (step > 0 && direction.dot(previous) < min_cosine) break;
    int edge = -1;
    Eigen::Vector3d exit;
    if (!exit_of(mesh, t, triangle, entered, point, direction, edge, exit)) break;
    if (grid.near(exit, 0.5 * params.spacing_m, line)) break;
    points.push_back(exit);
    segment_face.push_back(t.face[static_cast<size_t>(triangle)]);
    int32_t next = t.neighbour[static_cast<size_t>(triangle)][edge];
    if (next < 0) break;
    // The edge we enter the next triangle through.
    const auto& here = t.corners[static_cast<size_t>(triangle)];
    const auto& there = t.corners[static_cast<size_t>(next)];
    uint64_t key = edge_key(here[edge], here[(edge + 1) % 3]);
    entered = -1;
    for (int k = 0; k < 3; ++k)
      if (edge_key(there[k], there[(k + 1) % 3]) == key) entered = k;
    previous = direction;
    point = exit;
    triangle = next;
  }
}

/// `points` at about `step` apart along their arc, the ends kept.
Points3f resampled(const std::vector<Eigen::Vector3d>& points, double step) {
  std::vector<double> arc(points.size(), 0.0);
  for (size_t i = 1; i < points.size(); ++i) arc[i] = arc[i - 1] + (points[i] - points[i - 1]).norm();
  const auto count = std::max<Eigen::Index>(2, static_cast<Eigen::Index>(std::lround(arc.back() / step)) + 1);
  Points3f out(count, 3);
  size_t segment = 1;
  for (Eigen::Index i = 0; i < count; ++i) {
    const double s = arc.back() * static_cast<double>(i) / static_cast<double>(count - 1);
    while (segment + 1 < points.size() && arc[segment] < s) ++segment;
    const double length = arc[segment] - arc[segment - 1];
    const double w = length > 0 ? std::clamp((s - arc[segment - 1]) / length, 0.0, 1.0) : 0.0;
    out.row(i) = ((1 - w) * points[segment - 1] + w * points[segment]).cast<float>().transpose();
  }
  return out;
}

}  // namespace

std::vector<PaintedStreamline> painted_streamlines(const PolyMesh& mesh, const PaintedFlow& flow,
                                                   std::span<const int64_t> faces,
                                                   const StreamlineParams& params) {
  std::vector<PaintedStreamline> lines;
  if (flow.coherence.size() != static_cast<size_t>(mesh.face_count())) return lines;
  const PatchTriangles t = patch_triangles(mesh, flow, faces);
  SpacingGrid grid(params.spacing_m);
  for (int32_t seed = 0; seed < static_cast<int32_t>(t.corners.size()); ++seed) {
    if (t.flow[static_cast<size_t>(seed)].isZero()) continue;
    const auto& c = t.corners[static_cast<size_t>(seed)];
    const Eigen::Vector3d centroid =
        (vertex(mesh, c[0]) + vertex(mesh, c[1]) + vertex(mesh, c[2])) / 3;
    const auto line = static_cast<int32_t>(lines.size());
    if (grid.near(centroid, params.spacing_m, -1)) continue;
    std::vector<Eigen::Vector3d> forward, backward;
    std::vector<int64_t> forward_faces, backward_faces;
    const Eigen::Vector3d& d = t.flow[static_cast<size_t>(seed)];
    trace(mesh, t, seed, d, params, grid, line, forward, forward_faces);
    trace(mesh, t, seed, -d, params, grid, line, backward, backward_faces);
    // backward reversed, then forward without its repeated first point
    std::vector<Eigen::Vector3d> points(backward.rbegin(), backward.rend());
    points.insert(points.end(), forward.begin() + 1, forward.end());
    std::vector<int64_t> segment_face(backward_faces.rbegin(), backward_faces.rend());
    segment_face.insert(segment_face.end(), forward_faces.begin(), forward_faces.end());
    double length = 0;
    for (size_t i = 1; i < points.size(); ++i) length += (points[i] - points[i - 1]).norm();
    if (points.size() < 2 || length < params.min_length_m) continue;

    PaintedStreamline streamline;
    double signed_sum = 0, magnitude_sum = 0, crossed = 0;
    for (size_t i = 1; i < points.size(); ++i) {
      Eigen::Vector3d segment = points[i] - points[i - 1];
      const double segment_length = segment.norm();
      if (!(segment_length > 0)) continue;
      const auto f = static_cast<size_t>(segment_face[i - 1]);
      const double fall = segment.dot(flow.direction[f].cast<double>()) / segment_length *
                          flow.alpha_fall[f];
      signed_sum += segment_length * fall;
      magnitude_sum += segment_length * std::abs(fall);
      crossed += segment_length;
    }
    if (magnitude_sum > 0) streamline.fade_vote = signed_sum / magnitude_sum;
    if (crossed > 0) streamline.fade_mean_fall = magnitude_sum / crossed;
    streamline.points = resampled(points, params.spacing_m);
    for (Eigen::Index i = 0; i < streamline.points.rows(); ++i)
      grid.add(streamline.points.row(i).cast<double>().transpose(), line);
    for (const Eigen::Vector3d& p : points) grid.add(p, line);
    lines.push_back(std::move(streamline));
  }
  return lines;
}

}  // namespace hair
