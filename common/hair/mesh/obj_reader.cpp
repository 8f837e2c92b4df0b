// Native Wavefront OBJ reader that keeps the file's vertex order (see mesh_io.h).
#include <charconv>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "hair/core/error.h"
#include "hair/mesh/mesh_io.h"

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
  explicit ObjParser(std::string file) : file_(std::move(file)) {}

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
        mesh.append_face(face);
      }
    }
    if (input.bad()) throw Error::bad_input(file_, "read error");

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
  std::string file_;
  long line_number_ = 0;
};

}  // namespace

PolyMesh read_obj(const std::filesystem::path& path) {
  std::ifstream input(path);
  if (!input) throw Error::bad_input(path.string(), "cannot open file");
  return ObjParser(path.string()).parse(input);
}

}  // namespace hair
