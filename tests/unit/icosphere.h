#pragma once

// A triangulated sphere for tests that need a closed body with known geometry.

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "hair/core/strand_set.h"
#include "hair/geom/triangle_mesh_distance.h"

namespace hair::testing {

struct SphereMesh {
  Points3f vertices;
  Triangles3i triangles;
};

/// A sphere of `radius_m` about `centre_m`: an icosahedron whose triangles are split in
/// four `subdivisions` times, the new vertices pushed onto the sphere. Triangles are
/// wound counter-clockwise seen from outside, so right-hand normals point outward.
inline SphereMesh icosphere(int subdivisions, double radius_m = 1.0,
                            const Eigen::Vector3d& centre_m = Eigen::Vector3d::Zero()) {
  const double g = (1 + std::sqrt(5.0)) / 2;
  std::vector<Eigen::Vector3d> points = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0},
                                         {0, -1, g}, {0, 1, g}, {0, -1, -g}, {0, 1, -g},
                                         {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  for (auto& p : points) p.normalize();
  std::vector<std::array<int32_t, 3>> faces = {
      {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int level = 0; level < subdivisions; ++level) {
    std::map<std::pair<int32_t, int32_t>, int32_t> midpoints;
    auto midpoint = [&](int32_t a, int32_t b) {
      auto key = std::minmax(a, b);
      auto [it, added] = midpoints.try_emplace(key, static_cast<int32_t>(points.size()));
      if (added) points.push_back((points[a] + points[b]).normalized());
      return it->second;
    };
    std::vector<std::array<int32_t, 3>> split;
    for (const auto& [a, b, c] : faces) {
      int32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      split.insert(split.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
    }
    faces = std::move(split);
  }
  SphereMesh mesh;
  mesh.vertices.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (size_t v = 0; v < points.size(); ++v)
    mesh.vertices.row(static_cast<Eigen::Index>(v)) =
        (centre_m + radius_m * points[v]).cast<float>().transpose();
  mesh.triangles.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (size_t t = 0; t < faces.size(); ++t)
    mesh.triangles.row(static_cast<Eigen::Index>(t)) << faces[t][0], faces[t][1], faces[t][2];
  return mesh;
}

}  // namespace hair::testing
