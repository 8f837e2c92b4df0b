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
  return scalp;
}

}  // namespace hair
