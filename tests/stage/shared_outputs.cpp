#include "shared_outputs.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "sample_pipeline.h"

namespace hair::test {

namespace fs = std::filesystem;

namespace {

/// "name size mtime" of every regular file under `root`, sorted by name.
void stamp_files(const fs::path& root, bool recursive, std::vector<std::string>& lines) {
  if (!fs::is_directory(root)) return;
  const auto add = [&](const fs::directory_entry& entry) {
    if (!entry.is_regular_file()) return;
    std::ostringstream line;
    line << entry.path().string() << ' ' << entry.file_size() << ' '
         << entry.last_write_time().time_since_epoch().count();
    lines.push_back(line.str());
  };
  if (recursive) {
    for (const auto& entry : fs::recursive_directory_iterator(root)) add(entry);
  } else {
    for (const auto& entry : fs::directory_iterator(root)) add(entry);
  }
}

/// An exclusive lock on `path` (flock), released when the object goes.
class FileLock {
 public:
  explicit FileLock(const fs::path& path) : descriptor_(::open(path.c_str(), O_RDWR | O_CREAT, 0644)) {
    if (descriptor_ < 0 || ::flock(descriptor_, LOCK_EX) != 0)
      throw std::runtime_error("cannot lock " + path.string());
  }
  ~FileLock() {
    ::flock(descriptor_, LOCK_UN);
    ::close(descriptor_);
  }
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  int descriptor_;
};

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

std::string build_stamp() {
  std::vector<std::string> lines;
  stamp_files(kBin, false, lines);
  stamp_files(fs::path(HAIR_SOURCE_DIR) / "models", false, lines);
  stamp_files(kSamples, true, lines);
  std::sort(lines.begin(), lines.end());
  std::string stamp;
  for (const std::string& line : lines) stamp += line + '\n';
  return stamp;
}

void shared_outputs(const std::string& key, const fs::path& folder,
                    const std::vector<std::string>& names,
                    const std::function<void(const fs::path&)>& make) {
  const fs::path root = kBin.parent_path() / "tests" / "shared_outputs";
  fs::create_directories(root);
  const fs::path shared = root / key;
  {
    FileLock lock(root / (key + ".lock"));
    const std::string stamp = build_stamp();
    const fs::path stamp_path = shared / "STAMP";
    if (!fs::exists(stamp_path) || read_text(stamp_path) != stamp) {
      fs::remove_all(shared);
      fs::create_directories(shared);
      const bool failed_before = ::testing::Test::HasFailure();
      make(shared);
      if (!failed_before && ::testing::Test::HasFailure()) return;
      for (const std::string& name : names)
        ASSERT_TRUE(fs::exists(shared / name)) << key << ": " << name << " was not made";
      std::ofstream(stamp_path) << stamp;
    }
    fs::create_directories(folder);
    for (const std::string& name : names)
      if (!fs::exists(folder / name)) fs::copy_file(shared / name, folder / name);
  }
}

}  // namespace hair::test
