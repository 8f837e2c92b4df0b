#include "hair/mesh/poly_mesh.h"

namespace hair {

void PolyMesh::append_face(std::span<const int32_t> vertex_ids) {
  face_vertices.insert(face_vertices.end(), vertex_ids.begin(), vertex_ids.end());
  face_offsets.push_back(static_cast<int64_t>(face_vertices.size()));
}

}  // namespace hair
