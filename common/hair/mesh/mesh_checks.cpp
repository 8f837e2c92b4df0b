#include "hair/mesh/mesh_checks.h"

#include <algorithm>
#include <cmath>

#include "hair/core/error.h"

namespace hair {

void check_mesh(const PolyMesh& mesh, const std::string& file) {
  if (mesh.vertex_count() == 0) throw Error::bad_input(file, "empty mesh: no vertices");
  if (mesh.face_count() == 0) throw Error::bad_input(file, "mesh has no faces");
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v)
    if (!mesh.vertices.row(v).allFinite())
      throw Error::bad_input(file,
                             "vertex " + std::to_string(v + 1) +
                                 " (counting from 1, as OBJ does) has a non-finite coordinate");
  for (int32_t v : mesh.face_vertices)
    if (v < 0 || v >= mesh.vertex_count())
      throw Error::bad_input(file, "face refers to vertex " + std::to_string(v) + " of " +
                                       std::to_string(mesh.vertex_count()));
  if (mesh.has_uv() && !mesh.corner_uv.allFinite())
    throw Error::bad_input(file, "non-finite texture coordinate");
}

MeshCleanup clean_mesh(PolyMesh& mesh, const std::string& file) {
  check_mesh(mesh, file);
  MeshCleanup cleanup;
  PolyMesh cleaned;
  cleaned.vertices = std::move(mesh.vertices);
  cleaned.materials = std::move(mesh.materials);
  std::vector<float> uv;
  std::vector<int32_t> face;
  std::vector<int64_t> corners;
  for (int64_t f = 0; f < mesh.face_count(); ++f) {
    face.clear();
    corners.clear();
    auto vertex_ids = mesh.face(f);
    for (size_t c = 0; c < vertex_ids.size(); ++c) {
      int32_t previous = vertex_ids[(c + vertex_ids.size() - 1) % vertex_ids.size()];
      if (vertex_ids[c] == previous && vertex_ids.size() > 1) {
        ++cleanup.repeated_corners_removed;
        continue;
      }
      face.push_back(vertex_ids[c]);
      corners.push_back(mesh.face_offsets[f] + static_cast<int64_t>(c));
    }
    std::vector<int32_t> distinct = face;
    std::sort(distinct.begin(), distinct.end());
    if (std::unique(distinct.begin(), distinct.end()) - distinct.begin() < 3) {
      ++cleanup.degenerate_faces_removed;
      continue;
    }
    cleaned.append_face(face);
    if (mesh.has_materials()) cleaned.face_material.push_back(mesh.face_material[f]);
    if (mesh.has_uv())
      for (int64_t corner : corners) {
        uv.push_back(mesh.corner_uv(corner, 0));
        uv.push_back(mesh.corner_uv(corner, 1));
      }
  }
  if (mesh.has_uv())
    cleaned.corner_uv =
        Eigen::Map<const Uv2f>(uv.data(), static_cast<Eigen::Index>(uv.size() / 2), 2);
  mesh = std::move(cleaned);
  check_mesh(mesh, file);
  return cleanup;
}

}  // namespace hair
