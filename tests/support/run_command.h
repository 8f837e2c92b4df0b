#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace hair::test {

/// What a finished command left behind.
struct CommandResult {
  int exit_code = -1;  ///< exit status; 128 + signal number if a signal ended it
  std::string out;     ///< everything written to stdout
  std::string err;     ///< everything written to stderr
};

/// Runs `program` with `arguments` (no shell, so nothing is expanded or quoted) in
/// `working_directory` (the caller's own if empty), with stdin from /dev/null, and waits
/// for it. Throws std::runtime_error if the command cannot be started.
CommandResult run_command(const std::filesystem::path& program,
                          const std::vector<std::string>& arguments,
                          const std::filesystem::path& working_directory = {});

/// The lines of `text`, without their line ends; a last line without one counts too.
std::vector<std::string> text_lines(const std::string& text);

/// A fresh, empty directory under std::filesystem::temp_directory_path(), removed with
/// everything in it when the TemporaryDirectory is destroyed.
class TemporaryDirectory {
 public:
  /// `name_hint` goes into the directory's name (e.g. the test's name).
  explicit TemporaryDirectory(const std::string& name_hint = "test");
  ~TemporaryDirectory();
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;

  const std::filesystem::path& path() const { return path_; }
  /// path() / name.
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

  /// Names of every entry in the directory, hidden ones included, sorted.
  std::vector<std::string> entries() const;

 private:
  std::filesystem::path path_;
};

/// Writes `text` to `path`, replacing the file; throws std::runtime_error on failure.
void write_text_file(const std::filesystem::path& path, const std::string& text);

/// The whole content of the file `path`; throws std::runtime_error if it cannot be read.
std::string read_file_bytes(const std::filesystem::path& path);

/// The same as bytes (for the readers and fuzz targets that take uint8_t data).
std::vector<uint8_t> read_file_octets(const std::filesystem::path& path);

}  // namespace hair::test
