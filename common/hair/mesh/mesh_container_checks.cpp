#include "hair/mesh/mesh_container_checks.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "hair/core/error.h"

namespace hair {

namespace {

constexpr size_t kPlyHeaderLimit = 64 * 1024;

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool is_ply_type(const std::string& word) {
  static const std::array<const char*, 16> kTypes = {
      "char", "uchar", "short", "ushort", "int", "uint", "float", "double",
      "int8", "uint8", "int16", "uint16", "int32", "uint32", "float32", "float64"};
  return std::any_of(kTypes.begin(), kTypes.end(), [&](const char* type) { return word == type; });
}

/// The words of a header line.
std::vector<std::string> words_of(const std::string& line) {
  std::istringstream stream(line);
  std::vector<std::string> words;
  for (std::string word; stream >> word;) words.push_back(word);
  return words;
}

void check_ply_header(const std::filesystem::path& path, uintmax_t file_size) {
  std::ifstream in(path, std::ios::binary);
  std::string header(kPlyHeaderLimit, '\0');
  in.read(header.data(), static_cast<std::streamsize>(header.size()));
  header.resize(static_cast<size_t>(in.gcount()));
  const auto refuse = [&](int line, const std::string& reason) {
    throw Error::bad_input(path.string(), "PLY header, line " + std::to_string(line) + ": " + reason);
  };
  std::istringstream lines(header);
  std::string line;
  int number = 0;
  bool any_element = false;
  while (std::getline(lines, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::vector<std::string> words = words_of(line);
    if (number == 1) {
      if (words.size() != 1 || words[0] != "ply") refuse(1, "expected 'ply'");
      continue;
    }
    if (words.empty()) refuse(number, "empty line");
    const std::string& keyword = words[0];
    if (keyword == "end_header") {
      if (!any_element) refuse(number, "no element before end_header");
      return;
    }
    if (keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "format") {
      if (words.size() != 3 || (words[1] != "ascii" && words[1] != "binary_little_endian" &&
                                words[1] != "binary_big_endian"))
        refuse(number, "expected 'format ascii|binary_little_endian|binary_big_endian VERSION'");
      continue;
    }
    if (keyword == "element") {
      // Every element takes at least a byte of the file.
      if (words.size() != 3 || words[2].empty() ||
          !std::all_of(words[2].begin(), words[2].end(),
                       [](unsigned char c) { return std::isdigit(c) != 0; }) ||
          words[2].size() > 19 || std::stoull(words[2]) > file_size)
        refuse(number, "expected 'element NAME COUNT' with a count the file can hold");
      any_element = true;
      continue;
    }
    if (keyword == "property") {
      const bool scalar = words.size() == 3 && is_ply_type(lowercase(words[1]));
      const bool list = words.size() == 5 && words[1] == "list" && is_ply_type(lowercase(words[2])) &&
                        is_ply_type(lowercase(words[3]));
      if (!any_element || !(scalar || list))
        refuse(number, "expected 'property TYPE NAME' or 'property list TYPE TYPE NAME' after an element");
      continue;
    }
    refuse(number, "unknown keyword '" + keyword.substr(0, 32) + "'");
  }
  refuse(number, "no end_header in the first " + std::to_string(kPlyHeaderLimit / 1024) + " KiB");
}

uint32_t little_endian_u32(const unsigned char* bytes) {
  return static_cast<uint32_t>(bytes[0]) | (static_cast<uint32_t>(bytes[1]) << 8) |
         (static_cast<uint32_t>(bytes[2]) << 16) | (static_cast<uint32_t>(bytes[3]) << 24);
}

void check_glb_container(const std::filesystem::path& path, uintmax_t file_size) {
  std::ifstream in(path, std::ios::binary);
  unsigned char header[12] = {};
  in.read(reinterpret_cast<char*>(header), sizeof header);
  if (in.gcount() < 12 || std::memcmp(header, "glTF", 4) != 0) return;  // not GLB: the reader says
  const uint32_t declared = little_endian_u32(header + 8);
  if (declared > file_size)
    throw Error::bad_input(path.string(), "GLB header declares " + std::to_string(declared) +
                                              " bytes; the file has " + std::to_string(file_size));
  for (uint64_t offset = 12; offset + 8 <= declared;) {
    unsigned char chunk[8] = {};
    in.seekg(static_cast<std::streamoff>(offset));
    in.read(reinterpret_cast<char*>(chunk), sizeof chunk);
    if (in.gcount() < 8) break;
    const uint64_t length = little_endian_u32(chunk);
    if (offset + 8 + length > declared)
      throw Error::bad_input(path.string(), "GLB chunk at byte " + std::to_string(offset) + " (" +
                                                std::to_string(length) +
                                                " bytes) runs past the end of the file");
    offset += 8 + length;
  }
}

}  // namespace

void check_mesh_container(const std::filesystem::path& path) {
  std::error_code error;
  const uintmax_t file_size = std::filesystem::file_size(path, error);
  if (error) return;  // the reader names what is wrong
  const std::string extension = lowercase(path.extension().string());
  if (extension == ".ply") check_ply_header(path, file_size);
  if (extension == ".glb") check_glb_container(path, file_size);
}

}  // namespace hair
