#pragma once
// Shared by the fuzz targets and their regression test: each input is written to a file
// of its own kind (the readers under test take paths, as the stages do), and a reader's
// outcome is judged as a stage would judge it.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <exception>
#include <string>
#include <system_error>

#include "hair/core/error.h"

namespace hair::fuzz {

/// A folder of this process's own under $TMPDIR (or /tmp), made once and reused, so that
/// every input lands at the same path and nothing piles up between runs.
/// Removed with everything in it when the process ends normally.
inline const std::filesystem::path& scratch_folder() {
  struct Folder {
    std::filesystem::path path;
    Folder() {
      const char* tmp = std::getenv("TMPDIR");
      path = std::filesystem::path(tmp != nullptr ? tmp : "/tmp") /
             ("hair-fuzz-" + std::to_string(::getpid()));
      std::filesystem::create_directories(path);
    }
    ~Folder() {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const Folder folder;
  return folder.path;
}

/// Writes `size` bytes at `data` to the file `name` in scratch_folder() and returns its path.
inline std::filesystem::path write_input(const std::string& name, const uint8_t* data,
                                         size_t size) {
  const std::filesystem::path path = scratch_folder() / name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

/// Runs `read`, which may refuse its input as a stage would (hair::Error of kind
/// bad_input: exit 2 and one line). Returns what else escaped it (a runtime error,
/// another exception), which is a finding; empty if none did. Crashes and sanitizer
/// reports are findings too, caught by the fuzzer itself.
template <typename Read>
std::string finding_of(Read&& read) {
  try {
    read();
  } catch (const Error& error) {
    if (error.kind() != ErrorKind::bad_input)
      return std::string("not refused as bad input: ") + error.what();
  } catch (const std::exception& exception) {
    return std::string("exception: ") + exception.what();
  }
  return {};
}

/// Aborts with `finding` on stderr, so that the fuzzer records the input, unless it is empty.
inline void abort_on(const std::string& finding) {
  if (finding.empty()) return;
  std::fprintf(stderr, "finding: %s\n", finding.c_str());
  std::abort();
}

}  // namespace hair::fuzz
