#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

#include "hair/core/strand_set.h"
#include "hair/mesh/mesh_material.h"

namespace hair {

/// Row-major n x 2 float32 texture coordinates.
using Uv2f = Eigen::Matrix<float, Eigen::Dynamic, 2, Eigen::RowMajor>;

/// A polygon mesh with faces of any size in CSR layout, as artists' hair meshes
/// come (quads mostly, some triangles). Vertex order is the source file's order,
/// which the paper's root-to-tip convention relies on (section 3).
struct PolyMesh {
  Points3f vertices;                     ///< #vertices x 3
  std::vector<int64_t> face_offsets{0};  ///< #faces + 1; face f owns corners [f], [f+1)
  std::vector<int32_t> face_vertices;    ///< #corners vertex ids
  Uv2f corner_uv;                        ///< #corners x 2, or 0 rows when the source has none
  /// The materials the file names, and each face's (-1: none); empty when the file
  /// assigns none. Whatever rebuilds faces (cleaning, quads from triangles) carries both.
  std::vector<MeshMaterial> materials;
  std::vector<int32_t> face_material;

  int64_t vertex_count() const { return vertices.rows(); }
  int64_t face_count() const { return static_cast<int64_t>(face_offsets.size()) - 1; }
  int face_size(int64_t face) const {
    return static_cast<int>(face_offsets[face + 1] - face_offsets[face]);
  }
  std::span<const int32_t> face(int64_t face) const {
    return {face_vertices.data() + face_offsets[face], static_cast<size_t>(face_size(face))};
  }
  bool has_uv() const { return corner_uv.rows() > 0; }
  bool has_materials() const { return !face_material.empty(); }
  /// Face f's material, or nullptr.
  const MeshMaterial* material_of(int64_t face) const {
    if (face_material.empty() || face_material[static_cast<size_t>(face)] < 0) return nullptr;
    return &materials[static_cast<size_t>(face_material[static_cast<size_t>(face)])];
  }

  /// Appends a face given its vertex ids (and their texture coordinates, if the mesh has them).
  void append_face(std::span<const int32_t> vertex_ids);
};

}  // namespace hair
