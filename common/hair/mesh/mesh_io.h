#pragma once

#include <filesystem>
#include <string>

#include "hair/mesh/poly_mesh.h"

namespace hair {

/// How a mesh file is read.
enum class MeshReader {
  automatic,  ///< the native OBJ reader for .obj, assimp for everything else
  assimp,     ///< assimp for every format (its OBJ import renumbers vertices)
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
/// file, an unsupported format, a parse error (with the line for OBJ).
PolyMesh read_mesh(const std::filesystem::path& path, MeshReader reader = MeshReader::automatic);

/// Reads a Wavefront OBJ file keeping the file's vertex order: `v`, `vt` and `f`
/// records (v, v/vt, v//vn, v/vt/vn, negative indices); other records are ignored.
PolyMesh read_obj(const std::filesystem::path& path);

}  // namespace hair
