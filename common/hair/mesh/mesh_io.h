#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "hair/mesh/poly_mesh.h"

namespace hair {

/// How a mesh file is read.
enum class MeshReader {
  automatic,  ///< the native OBJ reader for .obj, assimp for everything else
  assimp,     ///< assimp for every format (its OBJ import renumbers vertices)
};

/// The most a mesh may hold: a mesh over it is refused before it is processed, so that a
/// file far larger than hair meshes are is not read until the machine swaps.
struct MeshLimit {
  int64_t max_triangles = 0;          ///< a polygon of n corners counts n - 2; 0: no limit
  std::string name = "max_triangles";  ///< the setting that holds it, named in the error
};

/// Reads a polygon mesh from any format assimp reads (OBJ, glTF/GLB, FBX, PLY, ...).
///
/// OBJ files go through a native reader by default because assimp's OBJ importer
/// renumbers vertices by first use in the face list and splits them at texture
/// seams, which destroys the root-to-tip vertex order the paper relies on. Every
/// other format goes through assimp (scene node transforms applied, all meshes
/// merged, points and lines dropped, vertices at identical positions welded in
/// order of first appearance).
///
/// Throws hair::Error (bad_input) naming the file for: a missing or unreadable
/// file, an unsupported format, a parse error (with the line for OBJ), more triangles
/// than `limit` allows (OBJ: at the face that passes it, before the rest is read; other
/// formats: after assimp's import, before the mesh is converted).
PolyMesh read_mesh(const std::filesystem::path& path, MeshReader reader = MeshReader::automatic,
                   const MeshLimit& limit = {});

/// Reads a Wavefront OBJ file keeping the file's vertex order: `v`, `vt` and `f`
/// records (v, v/vt, v//vn, v/vt/vn, negative indices); other records are ignored.
PolyMesh read_obj(const std::filesystem::path& path, const MeshLimit& limit = {});

/// The one-line reason a mesh of more than `limit` triangles is refused.
std::string mesh_limit_message(const MeshLimit& limit);

}  // namespace hair
