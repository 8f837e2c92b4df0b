#include "hair/cluster/group_scalp_distance.h"

#include <string>

#include "hair/core/error.h"

namespace hair {

std::vector<double> start_scalp_distances(const StrandSet& centres, const Points3f& body_vertices,
                                          const Triangles3i& body_triangles,
                                          const std::vector<uint8_t>& scalp_triangle) {
  if (scalp_triangle.size() != static_cast<size_t>(body_triangles.rows()))
    throw Error::bad_input("", "scalp flags (" + std::to_string(scalp_triangle.size()) +
                                   ") do not match the body's triangles (" +
                                   std::to_string(body_triangles.rows()) + ")");
  Triangles3i scalp(body_triangles.rows(), 3);
  Eigen::Index count = 0;
  for (Eigen::Index t = 0; t < body_triangles.rows(); ++t)
    if (scalp_triangle[static_cast<size_t>(t)]) scalp.row(count++) = body_triangles.row(t);
  scalp.conservativeResize(count, 3);
  if (count == 0) scalp = body_triangles;
  if (scalp.rows() == 0) throw Error::bad_input("", "the body has no triangles");
  TriangleMeshDistance distance(body_vertices, scalp);
  std::vector<double> result(static_cast<size_t>(centres.strand_count()));
  for (int64_t g = 0; g < centres.strand_count(); ++g)
    result[static_cast<size_t>(g)] =
        distance.distance(point_of(centres.points, centres.offsets[g]));
  return result;
}

}  // namespace hair
