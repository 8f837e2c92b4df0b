#include "hair/extract/scalp.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "hair/geom/point_index.h"

namespace hair {

namespace {

std::array<Eigen::Vector3d, 3> corners_of(const Points3f& vertices, const Triangles3i& triangles,
                                          Eigen::Index t) {
  std::array<Eigen::Vector3d, 3> corner;
  for (int k = 0; k < 3; ++k)
    corner[static_cast<size_t>(k)] = vertices.row(triangles(t, k)).cast<double>().transpose();
  return corner;
}

}  // namespace

std::vector<uint8_t> face_triangles(const Points3f& body_vertices,
                                    const Triangles3i& body_triangles, double neck_y,
                                    double below_y, double radius_m, double depth_m,
                                    double half_width_m) {
  const Eigen::Index count = body_triangles.rows();
  std::vector<uint8_t> face(static_cast<size_t>(count), 0);
  Points3f centroids(count, 3);
  std::vector<Eigen::Vector3d> area_normals(static_cast<size_t>(count));
  for (Eigen::Index t = 0; t < count; ++t) {
    const auto corner = corners_of(body_vertices, body_triangles, t);
    centroids.row(t) = ((corner[0] + corner[1] + corner[2]) / 3.0).cast<float>().transpose();
    area_normals[static_cast<size_t>(t)] = (corner[1] - corner[0]).cross(corner[2] - corner[0]);
  }
  if (count == 0) return face;
  double front_x = 0, front_z = -std::numeric_limits<double>::infinity();
  for (Eigen::Index v = 0; v < body_vertices.rows(); ++v)
    if (body_vertices(v, 1) > neck_y && body_vertices(v, 1) < below_y &&
        body_vertices(v, 2) > front_z) {
      front_x = body_vertices(v, 0);
      front_z = body_vertices(v, 2);
    }
  const PointIndex index(centroids);
#pragma omp parallel for schedule(static)
  for (Eigen::Index t = 0; t < count; ++t) {
    const Eigen::Vector3f centroid = centroids.row(t).transpose();
    if (!(centroid.y() < below_y) || !(centroid.y() > neck_y)) continue;
    if (depth_m > 0 && centroid.z() > front_z - depth_m &&
        std::abs(centroid.x() - front_x) < half_width_m) {
      face[static_cast<size_t>(t)] = 1;
      continue;
    }
    if (!(radius_m > 0)) continue;
    Eigen::Vector3d around = Eigen::Vector3d::Zero();
    for (int32_t id : index.within(centroid, static_cast<float>(radius_m)))
      around += area_normals[static_cast<size_t>(id)];
    if (around.norm() > 0 && around.normalized().z() > kFaceNormalZ)
      face[static_cast<size_t>(t)] = 1;
  }
  return face;
}

std::vector<uint8_t> thin_triangles(const Points3f& body_vertices,
                                    const Triangles3i& body_triangles, double neck_y,
                                    double max_thickness_m, const std::vector<uint8_t>* only) {
  const Eigen::Index count = body_triangles.rows();
  std::vector<uint8_t> thin(static_cast<size_t>(count), 0);
  if (count == 0 || !(max_thickness_m > 0)) return thin;
  // The head's triangles, indexed by centroid; a ray's candidates are those whose centroid
  // lies within half the ray and the longest edge of the ray's middle.
  Points3f centroids(count, 3);
  double longest_edge_m = 0;
  for (Eigen::Index t = 0; t < count; ++t) {
    const auto corner = corners_of(body_vertices, body_triangles, t);
    centroids.row(t) = ((corner[0] + corner[1] + corner[2]) / 3.0).cast<float>().transpose();
    if (centroids(t, 1) > neck_y - max_thickness_m)
      for (int k = 0; k < 3; ++k)
        longest_edge_m = std::max(
            longest_edge_m,
            (corner[static_cast<size_t>(k)] - corner[static_cast<size_t>((k + 1) % 3)]).norm());
  }
  const PointIndex index(centroids);
  const auto reach_m = static_cast<float>(0.5 * max_thickness_m + longest_edge_m);
#pragma omp parallel for schedule(dynamic, 256)
  for (Eigen::Index t = 0; t < count; ++t) {
    if (!(centroids(t, 1) > neck_y) || (only && !(*only)[static_cast<size_t>(t)])) continue;
    const auto corner = corners_of(body_vertices, body_triangles, t);
    const Eigen::Vector3d cross = (corner[1] - corner[0]).cross(corner[2] - corner[0]);
    if (!(cross.norm() > 0)) continue;
    const Eigen::Vector3d inward = -cross.normalized();
    const Eigen::Vector3d origin = centroids.row(t).cast<double>().transpose();
    const Eigen::Vector3f middle = (origin + 0.5 * max_thickness_m * inward).cast<float>();
    for (int32_t other : index.within(middle, reach_m)) {
      if (other == t) continue;
      // Moller-Trumbore: origin + d inward meets the triangle for d in (0, max_thickness_m].
      const auto c = corners_of(body_vertices, body_triangles, other);
      const Eigen::Vector3d e1 = c[1] - c[0], e2 = c[2] - c[0];
      const Eigen::Vector3d p = inward.cross(e2);
      const double det = e1.dot(p);
      if (std::abs(det) < 1e-15) continue;
      const Eigen::Vector3d from = origin - c[0];
      const double u = from.dot(p) / det;
      if (u < 0 || u > 1) continue;
      const Eigen::Vector3d q = from.cross(e1);
      const double v = inward.dot(q) / det;
      if (v < 0 || u + v > 1) continue;
      const double d = e2.dot(q) / det;
      if (d > 1e-9 && d <= max_thickness_m) {
        thin[static_cast<size_t>(t)] = 1;
        break;
      }
    }
  }
  return thin;
}

std::vector<uint8_t> scalp_triangles(const Points3f& body_vertices,
                                     const Triangles3i& body_triangles, const PolyMesh& hair_mesh,
                                     const ScalpParams& params) {
  const TriangleMeshDistance hair_distance(
      hair_mesh.vertices, fan_triangulation(hair_mesh.face_offsets, hair_mesh.face_vertices));
  const std::vector<uint8_t> face =
      face_triangles(body_vertices, body_triangles, params.neck_y, params.face_below_y,
                     params.face_radius_m, params.face_depth_m, params.face_half_width_m);
  const double max_distance_m = params.max_distance_m;
  std::vector<uint8_t> scalp(static_cast<size_t>(body_triangles.rows()), 0);
#pragma omp parallel for schedule(static)
  for (Eigen::Index t = 0; t < body_triangles.rows(); ++t) {
    const auto corner = corners_of(body_vertices, body_triangles, t);
    const Eigen::Vector3d centroid = (corner[0] + corner[1] + corner[2]) / 3.0;
    if (centroid.y() < params.neck_y || face[static_cast<size_t>(t)]) continue;
    if (hair_distance.is_within(centroid, max_distance_m)) {
      scalp[static_cast<size_t>(t)] = 1;
      continue;
    }
    if (!(params.under_hair_m > max_distance_m)) continue;
    if (centroid.y() < params.neck_y + params.under_hair_min_height_m) continue;
    const Eigen::Vector3d normal =
        (corner[1] - corner[0]).cross(corner[2] - corner[0]).normalized();
    if (!(normal.z() <= kFaceNormalZ)) continue;
    for (double height_m = max_distance_m; height_m <= params.under_hair_m;
         height_m += max_distance_m)
      if (hair_distance.is_within(centroid + height_m * normal, max_distance_m)) {
        scalp[static_cast<size_t>(t)] = 1;
        break;
      }
  }
  // The ears, tested only where the scalp would otherwise be (the ray casts are the costly
  // part).
  const std::vector<uint8_t> ear =
      thin_triangles(body_vertices, body_triangles, params.neck_y, params.ear_thickness_m, &scalp);
  for (size_t t = 0; t < scalp.size(); ++t)
    if (ear[t]) scalp[t] = 0;
  return scalp;
}

}  // namespace hair
