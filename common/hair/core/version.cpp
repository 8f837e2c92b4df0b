#include "hair/core/version.h"

#include <filesystem>
#include <fstream>

namespace hair {
namespace {

std::string read_version() {
  std::error_code error;
  std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) {
    std::filesystem::path directory = executable.parent_path();
    for (const auto& candidate : {directory / "hairstyle-version.txt",
                                  directory.parent_path() / "bin" / "hairstyle-version.txt"}) {
      std::ifstream file(candidate);
      std::string version;
      if (file && std::getline(file, version) && !version.empty()) return version;
    }
  }
  return std::string(HAIR_PROJECT_VERSION) + "+unknown";
}

}  // namespace

const std::string& project_version() {
  static const std::string version = read_version();
  return version;
}

}  // namespace hair
