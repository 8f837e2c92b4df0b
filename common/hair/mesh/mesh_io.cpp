#include "hair/mesh/mesh_io.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cctype>
#include <map>
#include <tuple>

#include <opencv2/imgcodecs.hpp>

#include "hair/core/error.h"
#include "hair/mesh/mesh_container_checks.h"

namespace hair {
namespace {

std::string lowercase_extension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

/// A material's first texture of `type`: an image embedded in the scene (its encoded
/// bytes; raw texels are encoded as PNG), or a file resolved against `folder`.
MaterialImage material_image(const aiScene& scene, const aiMaterial& material, aiTextureType type,
                             const std::filesystem::path& folder) {
  MaterialImage image;
  aiString name;
  if (material.GetTextureCount(type) == 0 || material.GetTexture(type, 0, &name) != AI_SUCCESS ||
      name.length == 0)
    return image;
  if (const aiTexture* embedded = scene.GetEmbeddedTexture(name.C_Str())) {
    image.path = folder / ("embedded:" + std::string(name.C_Str()));
    if (embedded->mHeight == 0) {  // compressed (PNG, JPEG, ...): mWidth bytes
      const auto* bytes = reinterpret_cast<const uint8_t*>(embedded->pcData);
      image.encoded.assign(bytes, bytes + embedded->mWidth);
    } else {  // raw BGRA texels
      cv::Mat texels(static_cast<int>(embedded->mHeight), static_cast<int>(embedded->mWidth),
                     CV_8UC4, const_cast<aiTexel*>(embedded->pcData));
      cv::imencode(".png", texels, image.encoded);
    }
    return image;
  }
  std::string file = name.C_Str();
  for (char& c : file)
    if (c == '\\') c = '/';
  image.path = std::filesystem::path(file).is_absolute() ? std::filesystem::path(file) : folder / file;
  return image;
}

/// The scene's materials: name, diffuse (or base colour) and opacity images.
std::vector<MeshMaterial> materials_of(const aiScene& scene, const std::filesystem::path& folder) {
  std::vector<MeshMaterial> materials;
  for (unsigned m = 0; m < scene.mNumMaterials; ++m) {
    const aiMaterial& source = *scene.mMaterials[m];
    MeshMaterial material;
    aiString name;
    if (source.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) material.name = name.C_Str();
    material.diffuse = material_image(scene, source, aiTextureType_DIFFUSE, folder);
    if (!material.diffuse.present())
      material.diffuse = material_image(scene, source, aiTextureType_BASE_COLOR, folder);
    material.alpha = material_image(scene, source, aiTextureType_OPACITY, folder);
    materials.push_back(std::move(material));
  }
  return materials;
}

/// Merges every polygon of an assimp scene into one mesh, welding vertices that
/// share a position exactly (assimp splits them at texture seams), with each face's
/// material; image paths resolve against `folder`.
PolyMesh mesh_from_scene(const aiScene& scene, const std::filesystem::path& folder) {
  PolyMesh mesh;
  mesh.materials = materials_of(scene, folder);
  bool any_image = false;
  for (const MeshMaterial& material : mesh.materials)
    any_image |= material.diffuse.present() || material.alpha.present();
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
      mesh.face_material.push_back(static_cast<int32_t>(source.mMaterialIndex));
    }
  }
  if (!any_image) {  // assimp gives every mesh a default material: none is named here
    mesh.materials.clear();
    mesh.face_material.clear();
  }
  mesh.vertices = Eigen::Map<const Points3f>(positions.data(),
                                             static_cast<Eigen::Index>(positions.size() / 3), 3);
  if (every_mesh_has_uv && !corner_uv.empty())
    mesh.corner_uv = Eigen::Map<const Uv2f>(corner_uv.data(),
                                            static_cast<Eigen::Index>(corner_uv.size() / 2), 2);
  return mesh;
}

PolyMesh read_with_assimp(const std::filesystem::path& path, const MeshLimit& limit) {
  Assimp::Importer importer;
  std::string extension = lowercase_extension(path);
  if (extension.empty() || !importer.IsExtensionSupported(extension))
    throw Error::bad_input(path.string(), "unsupported mesh format '" + extension + "'");
  check_mesh_container(path);
  // No triangulation: quads are kept so their rails can be read (section 4.1).
  const aiScene* scene = importer.ReadFile(path.string(), aiProcess_PreTransformVertices);
  if (scene == nullptr)
    throw Error::bad_input(path.string(),
                           std::string("cannot read mesh: ") + importer.GetErrorString());
  if (limit.max_triangles > 0) {
    int64_t triangles = 0;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m)
      for (unsigned f = 0; f < scene->mMeshes[m]->mNumFaces; ++f)
        triangles += std::max<int64_t>(0, int64_t{scene->mMeshes[m]->mFaces[f].mNumIndices} - 2);
    if (triangles > limit.max_triangles)
      throw Error::bad_input(path.string(), mesh_limit_message(limit) + ": it has " +
                                                std::to_string(triangles));
  }
  return mesh_from_scene(*scene, path.parent_path());
}

}  // namespace

std::string mesh_limit_message(const MeshLimit& limit) {
  return "more triangles than the limit of " + std::to_string(limit.max_triangles) + " (" +
         limit.name + ")";
}

PolyMesh read_mesh(const std::filesystem::path& path, MeshReader reader, const MeshLimit& limit) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw Error::bad_input(path.string(), std::filesystem::exists(path, error)
                                              ? "not a regular file"
                                              : "no such file");
  if (reader == MeshReader::automatic && lowercase_extension(path) == ".obj")
    return read_obj(path, limit);
  return read_with_assimp(path, limit);
}

}  // namespace hair
