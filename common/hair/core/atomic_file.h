#pragma once

#include <filesystem>

namespace hair {

/// An output file written under a temporary name in the same directory and renamed over
/// the final name on commit() (DESIGN.md, contract 1). If the AtomicFile is destroyed
/// without commit() (an error was thrown), the temporary file is deleted and an existing
/// file at the final path is left untouched.
///
///   AtomicFile output(out_path);
///   auto file = h5::File::create(output.temporary_path(), out_path.string());
///   ... write, file.close() ...
///   output.commit();
class AtomicFile {
 public:
  /// Picks the temporary path ".<name>.tmp.<pid>" next to `final_path`, and removes the
  /// temporary files of the same output left by processes of this machine that no longer
  /// run (a stage killed with SIGKILL cannot remove its own). A missing output directory,
  /// or a final path that is a directory, is a usage error.
  explicit AtomicFile(std::filesystem::path final_path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::filesystem::path& final_path() const { return final_path_; }
  const std::filesystem::path& temporary_path() const { return temporary_path_; }

  /// Renames the temporary file over the final path; a runtime error naming the final
  /// path if the temporary file is missing or the rename fails.
  void commit();

 private:
  std::filesystem::path final_path_;
  std::filesystem::path temporary_path_;
  bool committed_ = false;
};

}  // namespace hair
