#include "hair/grow/card_surfaces.h"

#include <stdexcept>

namespace hair {

void fan_triangulation_with_groups(const std::vector<int64_t>& face_offsets,
                                   const std::vector<int32_t>& face_vertices,
                                   const std::vector<int32_t>& face_group, Triangles3i& triangles,
                                   std::vector<int32_t>& triangle_group) {
  if (face_offsets.empty() || face_group.size() != face_offsets.size() - 1)
    throw std::invalid_argument("one group per face");
  triangles = fan_triangulation(face_offsets, face_vertices);
  triangle_group.clear();
  for (size_t face = 0; face < face_group.size(); ++face) {
    const int64_t corners = face_offsets[face + 1] - face_offsets[face];
    if (corners > 2)
      triangle_group.insert(triangle_group.end(), static_cast<size_t>(corners - 2),
                            face_group[face]);
  }
}

Points3f fan_painted_flow(const std::vector<int64_t>& face_offsets, const Points3f& face_flow,
                          const std::vector<float>& coherence, double min_coherence) {
  if (face_offsets.empty() || static_cast<size_t>(face_flow.rows()) != face_offsets.size() - 1 ||
      coherence.size() != face_offsets.size() - 1)
    throw std::invalid_argument("one painted axis and coherence per face");
  std::vector<Eigen::Index> triangle_face;
  for (size_t face = 0; face + 1 < face_offsets.size(); ++face)
    for (int64_t k = 2; k < face_offsets[face + 1] - face_offsets[face]; ++k)
      triangle_face.push_back(static_cast<Eigen::Index>(face));
  Points3f flow = Points3f::Zero(static_cast<Eigen::Index>(triangle_face.size()), 3);
  for (size_t t = 0; t < triangle_face.size(); ++t)
    if (coherence[static_cast<size_t>(triangle_face[t])] >= min_coherence)
      flow.row(static_cast<Eigen::Index>(t)) = face_flow.row(triangle_face[t]);
  return flow;
}

CardSurfaces::CardSurfaces(const Points3f& vertices, const Triangles3i& triangles,
                           const std::vector<int32_t>& triangle_group, int64_t group_count) {
  if (triangle_group.size() != static_cast<size_t>(triangles.rows()))
    throw std::invalid_argument("CardSurfaces: one group per triangle");
  std::vector<std::vector<Eigen::Index>> group_triangles(static_cast<size_t>(group_count));
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    const int32_t group = triangle_group[static_cast<size_t>(t)];
    if (group >= 0 && group < group_count) group_triangles[static_cast<size_t>(group)].push_back(t);
  }
  surfaces_.resize(static_cast<size_t>(group_count));
  for (size_t g = 0; g < group_triangles.size(); ++g) {
    if (group_triangles[g].empty()) continue;
    Triangles3i own(static_cast<Eigen::Index>(group_triangles[g].size()), 3);
    for (size_t i = 0; i < group_triangles[g].size(); ++i)
      own.row(static_cast<Eigen::Index>(i)) = triangles.row(group_triangles[g][i]);
    surfaces_[g] = std::make_unique<TriangleMeshDistance>(vertices, own);
  }
}

std::optional<TriangleMeshDistance::Nearest> CardSurfaces::nearest(
    int32_t group, const Eigen::Vector3d& point) const {
  if (!has(group)) return std::nullopt;
  return surfaces_[static_cast<size_t>(group)]->nearest(point);
}

}  // namespace hair
