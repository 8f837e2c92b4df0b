// Native Wavefront OBJ reader that keeps the file's vertex order (see mesh_io.h).
#include <spdlog/spdlog.h>

#include <charconv>
#include <fstream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "hair/core/error.h"
#include "hair/mesh/mesh_io.h"
#include "hair/mesh/mesh_material.h"

namespace hair {
namespace {

std::string_view next_token(std::string_view& rest) {
  size_t begin = rest.find_first_not_of(" \t\r");
  if (begin == std::string_view::npos) {
    rest = {};
    return {};
  }
  size_t end = rest.find_first_of(" \t\r", begin);
  if (end == std::string_view::npos) end = rest.size();
  std::string_view token = rest.substr(begin, end - begin);
  rest.remove_prefix(end);
  return token;
}

class ObjParser {
 public:
  ObjParser(const std::filesystem::path& path, const MeshLimit& limit)
      : file_(path.string()), folder_(path.parent_path()), limit_(limit) {}

  [[noreturn]] void fail(const std::string& reason) const {
    throw Error::bad_input(file_, "line " + std::to_string(line_number_) + ": " + reason);
  }

  float parse_float(std::string_view token) const {
    float value = 0;
    auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size())
      fail("expected a number, found '" + std::string(token) + "'");
    return value;
  }

  /// Resolves a 1-based or negative (relative) OBJ index to 0-based; -1 if empty.
  int32_t parse_index(std::string_view token, size_t count, const char* what) const {
    if (token.empty()) return -1;
    long long index = 0;
    auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), index);
    if (error != std::errc() || end != token.data() + token.size() || index == 0)
      fail(std::string("bad ") + what + " index '" + std::string(token) + "'");
    long long resolved = index > 0 ? index - 1 : static_cast<long long>(count) + index;
    if (resolved < 0 || resolved >= static_cast<long long>(count))
      fail(std::string("face refers to ") + what + " " + std::string(token) + " of " +
           std::to_string(count));
    return static_cast<int32_t>(resolved);
  }

  PolyMesh parse(std::istream& input) {
    std::vector<float> positions;
    std::vector<float> texcoords;
    std::vector<int32_t> corner_texcoord;
    PolyMesh mesh;
    std::string line;
    std::vector<int32_t> face;
    std::vector<int32_t> face_material;
    while (std::getline(input, line)) {
      ++line_number_;
      std::string_view rest = line;
      std::string_view keyword = next_token(rest);
      if (keyword == "v") {
        for (int axis = 0; axis < 3; ++axis) {
          std::string_view token = next_token(rest);
          if (token.empty()) fail("vertex with fewer than 3 coordinates");
          positions.push_back(parse_float(token));
        }
      } else if (keyword == "vt") {
        for (int axis = 0; axis < 2; ++axis) {
          std::string_view token = next_token(rest);
          texcoords.push_back(token.empty() ? 0.0f : parse_float(token));
        }
      } else if (keyword == "mtllib") {
        read_material_library(rest, mesh);
      } else if (keyword == "usemtl") {
        std::string name = trimmed(rest);
        current_material_ = -1;
        for (size_t m = 0; m < mesh.materials.size(); ++m)
          if (mesh.materials[m].name == name) current_material_ = static_cast<int32_t>(m);
        if (current_material_ < 0 && !name.empty()) {
          // Named in no library read (or the library is missing): a material without images.
          mesh.materials.push_back(MeshMaterial{name, {}, {}});
          current_material_ = static_cast<int32_t>(mesh.materials.size() - 1);
        }
        any_material_ = true;
      } else if (keyword == "f") {
        face.clear();
        for (std::string_view token = next_token(rest); !token.empty(); token = next_token(rest)) {
          size_t slash = token.find('/');
          face.push_back(parse_index(token.substr(0, slash), positions.size() / 3, "vertex"));
          int32_t texcoord = -1;
          if (slash != std::string_view::npos) {
            std::string_view after = token.substr(slash + 1);
            texcoord = parse_index(after.substr(0, after.find('/')), texcoords.size() / 2,
                                   "texture coordinate");
          }
          corner_texcoord.push_back(texcoord);
        }
        if (face.size() < 3) fail("face with fewer than 3 vertices");
        triangles_ += static_cast<int64_t>(face.size()) - 2;
        if (limit_.max_triangles > 0 && triangles_ > limit_.max_triangles)
          fail(mesh_limit_message(limit_));
        mesh.append_face(face);
        face_material.push_back(current_material_);
      }
    }
    if (input.bad()) throw Error::bad_input(file_, "read error");
    if (any_material_) mesh.face_material = std::move(face_material);

    mesh.vertices = Eigen::Map<const Points3f>(positions.data(),
                                               static_cast<Eigen::Index>(positions.size() / 3), 3);
    bool every_corner_has_uv = !corner_texcoord.empty();
    for (int32_t texcoord : corner_texcoord) every_corner_has_uv &= texcoord >= 0;
    if (every_corner_has_uv) {
      mesh.corner_uv.resize(static_cast<Eigen::Index>(corner_texcoord.size()), 2);
      for (size_t corner = 0; corner < corner_texcoord.size(); ++corner) {
        mesh.corner_uv(static_cast<Eigen::Index>(corner), 0) =
            texcoords[2 * corner_texcoord[corner]];
        mesh.corner_uv(static_cast<Eigen::Index>(corner), 1) =
            texcoords[2 * corner_texcoord[corner] + 1];
      }
    }
    return mesh;
  }

 private:
  static std::string trimmed(std::string_view text) {
    size_t begin = text.find_first_not_of(" \t\r");
    if (begin == std::string_view::npos) return {};
    size_t end = text.find_last_not_of(" \t\r");
    return std::string(text.substr(begin, end - begin + 1));
  }

  /// `mtllib` names one or more MTL files, relative to the OBJ's folder; a name with
  /// spaces is taken whole when that file exists. A missing or unreadable library is a
  /// warning: the mesh is read without its images.
  void read_material_library(std::string_view arguments, PolyMesh& mesh) {
    std::vector<std::string> names;
    std::string whole = trimmed(arguments);
    std::error_code status;  // a name the file system refuses (too long, say) is no file
    if (std::filesystem::is_regular_file(folder_ / whole, status)) {
      names.push_back(whole);
    } else {
      std::string_view rest = arguments;
      for (std::string_view token = next_token(rest); !token.empty(); token = next_token(rest))
        names.emplace_back(token);
    }
    for (const std::string& name : names) {
      std::filesystem::path library = folder_ / name;
      try {
        for (MeshMaterial& material : read_mtl(library)) mesh.materials.push_back(std::move(material));
      } catch (const Error& error) {
        spdlog::warn("{}: line {}: {}: the mesh is read without its painted images", file_,
                     line_number_, error.what());
      }
    }
  }

  std::string file_;
  std::filesystem::path folder_;
  MeshLimit limit_;
  int64_t triangles_ = 0;
  long line_number_ = 0;
  int32_t current_material_ = -1;
  bool any_material_ = false;
};

}  // namespace

PolyMesh read_obj(const std::filesystem::path& path, const MeshLimit& limit) {
  std::ifstream input(path);
  if (!input) throw Error::bad_input(path.string(), "cannot open file");
  return ObjParser(path, limit).parse(input);
}

}  // namespace hair
