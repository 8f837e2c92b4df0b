#include "hair/mesh/mesh_material.h"

#include <cstdlib>
#include <fstream>

#include "hair/core/error.h"

namespace hair {
namespace {

std::string trim(const std::string& text) {
  size_t begin = text.find_first_not_of(" \t\r");
  if (begin == std::string::npos) return {};
  size_t end = text.find_last_not_of(" \t\r");
  return text.substr(begin, end - begin + 1);
}

bool is_number(const std::string& word) {
  char* end = nullptr;
  std::strtod(word.c_str(), &end);
  return end != word.c_str() && *end == '\0';
}

/// The file name of a map statement's arguments: what follows its options. An option is
/// a word starting with '-' and takes the numbers after it (`-bm 1`, `-s 1 1 1`) or one
/// word (`-imfchan m`, `-type sphere`, `-clamp on`).
std::string map_file_name(const std::string& arguments) {
  std::vector<std::string> words;
  std::vector<size_t> starts;
  for (size_t at = arguments.find_first_not_of(" \t"); at != std::string::npos;) {
    size_t end = arguments.find_first_of(" \t", at);
    words.push_back(arguments.substr(at, end == std::string::npos ? end : end - at));
    starts.push_back(at);
    at = end == std::string::npos ? end : arguments.find_first_not_of(" \t", end);
  }
  size_t i = 0;
  while (i < words.size() && words[i].size() > 1 && words[i][0] == '-' && !is_number(words[i])) {
    const std::string& option = words[i++];
    if (option == "-imfchan" || option == "-type" || option == "-clamp" || option == "-blendu" ||
        option == "-blendv" || option == "-cc") {
      ++i;
      continue;
    }
    while (i + 1 < words.size() && is_number(words[i])) ++i;  // keep a last word as the file
  }
  if (i >= words.size()) return {};
  return trim(arguments.substr(starts[i]));
}

}  // namespace

std::vector<MeshMaterial> read_mtl(const std::filesystem::path& path) {
  std::ifstream input(path);
  if (!input) throw Error::bad_input(path.string(), "cannot open material library");
  const std::filesystem::path folder = path.parent_path();
  std::vector<MeshMaterial> materials;
  std::string line;
  while (std::getline(input, line)) {
    line = trim(line);
    if (line.empty() || line[0] == '#') continue;
    size_t space = line.find_first_of(" \t");
    std::string keyword = line.substr(0, space);
    std::string arguments = space == std::string::npos ? "" : trim(line.substr(space));
    if (keyword == "newmtl") {
      materials.push_back(MeshMaterial{arguments, {}, {}});
      continue;
    }
    if (materials.empty() || (keyword != "map_Kd" && keyword != "map_d")) continue;
    std::string file = map_file_name(arguments);
    if (file.empty()) continue;
    for (char& c : file)
      if (c == '\\') c = '/';  // written on Windows
    MaterialImage& image = keyword == "map_Kd" ? materials.back().diffuse : materials.back().alpha;
    image.path = std::filesystem::path(file).is_absolute() ? std::filesystem::path(file)
                                                           : folder / file;
  }
  if (input.bad()) throw Error::bad_input(path.string(), "read error");
  return materials;
}

}  // namespace hair
