#include "hair/mesh/mesh_io.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cctype>
#include <map>
#include <tuple>

#include "hair/core/error.h"

namespace hair {
namespace {

std::string lowercase_extension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

/// Merges every polygon of an assimp scene into one mesh, welding vertices that
/// share a position exactly (assimp splits them at texture seams).
PolyMesh mesh_from_scene(const aiScene& scene) {
  PolyMesh mesh;
  std::map<std::tuple<float, float, float>, int32_t> vertex_at_position;
  std::vector<float> positions;
  std::vector<float> corner_uv;
  bool every_mesh_has_uv = true;
  std::vector<int32_t> face;
  for (unsigned mesh_index = 0; mesh_index < scene.mNumMeshes; ++mesh_index) {
    const aiMesh& source = *scene.mMeshes[mesh_index];
    every_mesh_has_uv &= source.HasTextureCoords(0);
    std::vector<int32_t> welded(source.mNumVertices);
    for (unsigned v = 0; v < source.mNumVertices; ++v) {
      const aiVector3D& p = source.mVertices[v];
      auto [it, inserted] = vertex_at_position.try_emplace(
          {p.x, p.y, p.z}, static_cast<int32_t>(positions.size() / 3));
      if (inserted) positions.insert(positions.end(), {p.x, p.y, p.z});
      welded[v] = it->second;
    }
    for (unsigned f = 0; f < source.mNumFaces; ++f) {
      const aiFace& source_face = source.mFaces[f];
      if (source_face.mNumIndices < 3) continue;  // points and lines are not surface
      face.clear();
      for (unsigned c = 0; c < source_face.mNumIndices; ++c) {
        unsigned v = source_face.mIndices[c];
        face.push_back(welded[v]);
        if (source.HasTextureCoords(0)) {
          corner_uv.push_back(source.mTextureCoords[0][v].x);
          corner_uv.push_back(source.mTextureCoords[0][v].y);
        }
      }
      mesh.append_face(face);
    }
  }
  mesh.vertices = Eigen::Map<const Points3f>(positions.data(),
                                             static_cast<Eigen::Index>(positions.size() / 3), 3);
  if (every_mesh_has_uv && !corner_uv.empty())
    mesh.corner_uv = Eigen::Map<const Uv2f>(corner_uv.data(),
                                            static_cast<Eigen::Index>(corner_uv.size() / 2), 2);
  return mesh;
}

PolyMesh read_with_assimp(const std::filesystem::path& path) {
  Assimp::Importer importer;
  std::string extension = lowercase_extension(path);
  if (extension.empty() || !importer.IsExtensionSupported(extension))
    throw Error::bad_input(path.string(), "unsupported mesh format '" + extension + "'");
  // No triangulation: quads are kept so their rails can be read (section 4.1).
  const aiScene* scene = importer.ReadFile(path.string(), aiProcess_PreTransformVertices);
  if (scene == nullptr)
    throw Error::bad_input(path.string(),
                           std::string("cannot read mesh: ") + importer.GetErrorString());
  return mesh_from_scene(*scene);
}

}  // namespace

PolyMesh read_mesh(const std::filesystem::path& path, MeshReader reader) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw Error::bad_input(path.string(), std::filesystem::exists(path, error)
                                              ? "not a regular file"
                                              : "no such file");
  if (reader == MeshReader::automatic && lowercase_extension(path) == ".obj") return read_obj(path);
  return read_with_assimp(path);
}

}  // namespace hair
