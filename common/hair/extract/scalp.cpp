#include "hair/extract/scalp.h"

#include <Eigen/Geometry>
#include <array>

namespace hair {

std::vector<uint8_t> scalp_triangles(const Points3f& body_vertices,
                                     const Triangles3i& body_triangles, double neck_y,
                                     const PolyMesh& hair_mesh, double max_distance_m,
                                     double under_hair_m, double under_hair_min_height_m) {
  const TriangleMeshDistance hair_distance(
      hair_mesh.vertices, fan_triangulation(hair_mesh.face_offsets, hair_mesh.face_vertices));
  std::vector<uint8_t> scalp(static_cast<size_t>(body_triangles.rows()), 0);
#pragma omp parallel for schedule(static)
  for (Eigen::Index t = 0; t < body_triangles.rows(); ++t) {
    std::array<Eigen::Vector3d, 3> corner;
    for (int k = 0; k < 3; ++k)
      corner[static_cast<size_t>(k)] =
          body_vertices.row(body_triangles(t, k)).cast<double>().transpose();
    const Eigen::Vector3d centroid = (corner[0] + corner[1] + corner[2]) / 3.0;
    if (centroid.y() < neck_y) continue;
    if (hair_distance.is_within(centroid, max_distance_m)) {
      scalp[static_cast<size_t>(t)] = 1;
      continue;
    }
    if (!(under_hair_m > max_distance_m)) continue;
    if (centroid.y() < neck_y + under_hair_min_height_m) continue;
    const Eigen::Vector3d normal =
        (corner[1] - corner[0]).cross(corner[2] - corner[0]).normalized();
    if (!(normal.z() <= kFaceNormalZ)) continue;
    for (double height_m = max_distance_m; height_m <= under_hair_m; height_m += max_distance_m)
      if (hair_distance.is_within(centroid + height_m * normal, max_distance_m)) {
        scalp[static_cast<size_t>(t)] = 1;
        break;
      }
  }
  return scalp;
}

}  // namespace hair
