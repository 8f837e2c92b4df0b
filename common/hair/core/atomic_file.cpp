#include "hair/core/atomic_file.h"

#include <fmt/format.h>
#include <unistd.h>

#include <string>
#include <system_error>
#include <utility>

#include "hair/core/error.h"

namespace hair {

AtomicFile::AtomicFile(std::filesystem::path final_path) : final_path_(std::move(final_path)) {
  std::error_code error;
  const std::filesystem::path directory =
      final_path_.has_parent_path() ? final_path_.parent_path() : std::filesystem::path(".");
  if (final_path_.filename().empty()) {
    throw Error::usage("output path " + final_path_.string() + " names no file");
  }
  if (!std::filesystem::is_directory(directory, error)) {
    throw Error::usage("output directory " + directory.string() + " does not exist (for " +
                       final_path_.string() + ")");
  }
  if (std::filesystem::is_directory(final_path_, error)) {
    throw Error::usage("output path " + final_path_.string() + " is a directory");
  }
  temporary_path_ = directory / fmt::format(".{}.tmp.{}", final_path_.filename().string(),
                                            static_cast<long long>(::getpid()));
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  std::error_code ignored;
  std::filesystem::remove(temporary_path_, ignored);
}

void AtomicFile::commit() {
  std::error_code error;
  if (!std::filesystem::is_regular_file(temporary_path_, error)) {
    throw Error::runtime(final_path_.string(), "cannot commit: temporary file " +
                                                   temporary_path_.string() + " is missing");
  }
  std::filesystem::rename(temporary_path_, final_path_, error);
  if (error) {
    throw Error::runtime(final_path_.string(), "cannot rename " + temporary_path_.string() +
                                                   " into place: " + error.message());
  }
  committed_ = true;
}

}  // namespace hair
