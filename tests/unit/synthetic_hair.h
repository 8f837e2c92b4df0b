#pragma once
// Hand-made meshes with known truth for the extract tests: a body whose head, neck and
// shoulders are simple solids, and hair strips whose root end is known, built with any
// vertex order, triangulated or not, with or without texture coordinates.

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>
#include <vector>

#include "hair/mesh/poly_mesh.h"

namespace hair::testing {

/// Appends `other` to `mesh` (vertex ids shifted; UVs kept only if both have them).
inline void append_mesh(PolyMesh& mesh, const PolyMesh& other) {
  auto base = static_cast<int32_t>(mesh.vertex_count());
  bool keep_uv = (mesh.face_count() == 0 || mesh.has_uv()) && other.has_uv();
  Points3f vertices(mesh.vertex_count() + other.vertex_count(), 3);
  vertices << mesh.vertices, other.vertices;
  mesh.vertices = vertices;
  for (int64_t f = 0; f < other.face_count(); ++f) {
    std::vector<int32_t> face;
    for (int32_t v : other.face(f)) face.push_back(v + base);
    mesh.append_face(face);
  }
  if (keep_uv) {
    Uv2f uv(mesh.corner_uv.rows() + other.corner_uv.rows(), 2);
    uv << mesh.corner_uv, other.corner_uv;
    mesh.corner_uv = uv;
  } else {
    mesh.corner_uv.resize(0, 2);
  }
}

/// A body as three solids of revolution around the y axis, in metres: a head sphere of
/// radius 0.1 centred at y = 1.6 (crown at 1.7), a neck cylinder of radius 0.05 from
/// y = 1.40 to 1.56, and shoulders: a cylinder of radius 0.2 from y = 1.0 to 1.40.
/// Truth: the neck's waist lies in [1.40, 1.56], so H is in [0.14, 0.30].
inline PolyMesh snowman_body(int segments = 48) {
  PolyMesh body;
  auto add_revolution = [&](const std::vector<Eigen::Vector2d>& profile) {  // (radius, y)
    PolyMesh part;
    int rings = static_cast<int>(profile.size());
    part.vertices.resize(rings * segments, 3);
    for (int r = 0; r < rings; ++r)
      for (int s = 0; s < segments; ++s) {
        double angle = 2 * std::numbers::pi * s / segments;
        part.vertices.row(r * segments + s) << static_cast<float>(profile[r].x() * std::cos(angle)),
            static_cast<float>(profile[r].y()),
            static_cast<float>(profile[r].x() * std::sin(angle));
      }
    for (int r = 0; r + 1 < rings; ++r)
      for (int s = 0; s < segments; ++s) {
        int32_t a = r * segments + s, b = r * segments + (s + 1) % segments;
        part.append_face(std::vector<int32_t>{a, b, b + segments, a + segments});
      }
    append_mesh(body, part);
  };
  std::vector<Eigen::Vector2d> sphere;
  for (int i = 0; i <= 24; ++i) {
    double polar = std::numbers::pi * (0.02 + 0.96 * i / 24.0);  // top to bottom, open poles
    sphere.push_back({0.1 * std::sin(polar), 1.6 + 0.1 * std::cos(polar)});
  }
  add_revolution(sphere);
  std::vector<Eigen::Vector2d> neck, shoulders;  // rings every centimetre, as a body mesh has
  for (int i = 0; i <= 16; ++i) neck.push_back({0.05, 1.56 - 0.01 * i});
  for (int i = 0; i <= 40; ++i) shoulders.push_back({0.2, 1.40 - 0.01 * i});
  add_revolution(neck);
  add_revolution(shoulders);
  return body;
}

/// How a strip's vertices are numbered and its faces made.
struct StripOptions {
  int rails = 2;               ///< points across (>= 2)
  int segments = 10;           ///< quads along
  bool reverse_order = false;  ///< vertex ids grow from tip to root
  bool shuffle_order = false;  ///< vertex ids in random order
  bool triangulate = false;    ///< each quad split into two triangles
  bool with_uv = true;         ///< v grows from root (0) to tip (1)
  uint32_t seed = 1;
};

/// A strip of hair along the polyline `centre` (root first), `width` wide across the
/// direction `across`; returns the mesh, whose rails run root to tip.
inline PolyMesh hair_strip(const std::vector<Eigen::Vector3d>& centre,
                           const Eigen::Vector3d& across, double width,
                           const StripOptions& options) {
  int rows = static_cast<int>(centre.size());
  int columns = options.rails;
  int count = rows * columns;
  std::vector<int32_t> id(count);  // natural index (row-major, root first) -> vertex id
  std::iota(id.begin(), id.end(), 0);
  if (options.reverse_order)
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < columns; ++c) id[r * columns + c] = (rows - 1 - r) * columns + c;
  if (options.shuffle_order) std::shuffle(id.begin(), id.end(), std::mt19937(options.seed));
  PolyMesh strip;
  strip.vertices.resize(count, 3);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < columns; ++c) {
      double t = columns > 1 ? static_cast<double>(c) / (columns - 1) - 0.5 : 0.0;
      strip.vertices.row(id[r * columns + c]) =
          (centre[r] + t * width * across).cast<float>().transpose();
    }
  std::vector<float> uv;
  auto corner_uv = [&](int r, int c) {
    uv.push_back(static_cast<float>(c) / static_cast<float>(columns - 1));
    uv.push_back(static_cast<float>(r) / static_cast<float>(rows - 1));
  };
  for (int r = 0; r + 1 < rows; ++r)
    for (int c = 0; c + 1 < columns; ++c) {
      std::array<std::pair<int, int>, 4> quad = {{{r, c}, {r, c + 1}, {r + 1, c + 1}, {r + 1, c}}};
      auto emit = [&](std::initializer_list<int> corners) {
        std::vector<int32_t> face;
        for (int k : corners) {
          face.push_back(id[quad[k].first * columns + quad[k].second]);
          corner_uv(quad[k].first, quad[k].second);
        }
        strip.append_face(face);
      };
      if (options.triangulate) {
        emit({0, 1, 2});
        emit({0, 2, 3});
      } else {
        emit({0, 1, 2, 3});
      }
    }
  if (options.with_uv)
    strip.corner_uv =
        Eigen::Map<const Uv2f>(uv.data(), static_cast<Eigen::Index>(uv.size() / 2), 2);
  return strip;
}

/// A polyline from `root` along `direction` (normalised), `length` long, bending by
/// `droop` towards -y along the way: hair leaving the scalp and falling.
inline std::vector<Eigen::Vector3d> falling_polyline(const Eigen::Vector3d& root,
                                                     const Eigen::Vector3d& direction,
                                                     double length, int segments,
                                                     double droop = 0.0) {
  std::vector<Eigen::Vector3d> points;
  Eigen::Vector3d d = direction.normalized();
  for (int i = 0; i <= segments; ++i) {
    double t = static_cast<double>(i) / segments;
    points.push_back(root + t * length * d + Eigen::Vector3d(0, -droop * t * t, 0));
  }
  return points;
}

/// A point on the snowman's head sphere at `azimuth` around y and `polar` from the top.
inline Eigen::Vector3d head_point(double azimuth, double polar, double lift = 0.005) {
  double r = 0.1 + lift;
  return {r * std::sin(polar) * std::cos(azimuth), 1.6 + r * std::cos(polar),
          r * std::sin(polar) * std::sin(azimuth)};
}

}  // namespace hair::testing
