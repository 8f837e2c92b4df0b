#include "hair/core/atomic_file.h"

#include <fmt/format.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <string>
#include <system_error>
#include <utility>

#include "hair/core/error.h"

namespace hair {
namespace {

/// Removes ".<name>.tmp.<pid>" files beside `final_path` whose process no longer runs on
/// this machine: what a stage killed while writing left behind.
void remove_stale_temporaries(const std::filesystem::path& directory,
                              const std::filesystem::path& final_path) {
  const std::string prefix = fmt::format(".{}.tmp.", final_path.filename().string());
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(directory, error)) {
    const std::string name = entry.path().filename().string();
    if (!name.starts_with(prefix)) continue;
    long long pid = 0;
    const char* first = name.data() + prefix.size();
    const char* last = name.data() + name.size();
    const auto [end, status] = std::from_chars(first, last, pid);
    if (status != std::errc() || end != last || pid <= 0 || pid == ::getpid()) continue;
    if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;  // still runs
    std::error_code ignored;
    std::filesystem::remove(entry.path(), ignored);
  }
}

}  // namespace

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
  remove_stale_temporaries(directory, final_path_);
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
