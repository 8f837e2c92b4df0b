#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include "hair/core/atomic_file.h"
#include "hair/core/error.h"
#include "hair/h5/attribute.h"
#include "hair/h5/file.h"
#include "unit/test_h5_support.h"

namespace hair {
namespace {

using AtomicFileTest = testing::TemporaryDirectoryTest;

std::string read_text(const std::filesystem::path& path) {
  std::ifstream stream(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(stream), {});
}

TEST_F(AtomicFileTest, TemporaryNameIsHiddenInTheSameDirectory) {
  const AtomicFile output(path("extract.h5"));
  EXPECT_EQ(output.final_path(), path("extract.h5"));
  EXPECT_EQ(output.temporary_path().parent_path(), directory_);
  EXPECT_EQ(output.temporary_path().filename().string(),
            ".extract.h5.tmp." + std::to_string(::getpid()));
}

TEST_F(AtomicFileTest, CommitRenamesOverTheFinalPath) {
  std::ofstream(path("out.h5")) << "old";
  {
    AtomicFile output(path("out.h5"));
    h5::File file = h5::File::create(output.temporary_path(), "out.h5");
    h5::write_string_attribute(file, "/", "stage", "test");
    file.close();
    EXPECT_EQ(read_text(path("out.h5")), "old");  // untouched until the commit
    output.commit();
    EXPECT_FALSE(std::filesystem::exists(output.temporary_path()));
  }
  const h5::File file = h5::File::open_read_only(path("out.h5"));
  EXPECT_EQ(h5::read_string_attribute(file, "/", "stage"), "test");
}

TEST_F(AtomicFileTest, FailureLeavesNoFileAndKeepsAnExistingOne) {
  std::filesystem::path temporary;
  try {
    AtomicFile output(path("new.h5"));
    temporary = output.temporary_path();
    std::ofstream(output.temporary_path()) << "half written";
    throw std::runtime_error("stage failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_FALSE(std::filesystem::exists(path("new.h5")));
  EXPECT_FALSE(std::filesystem::exists(temporary));

  std::ofstream(path("kept.h5")) << "previous result";
  {
    AtomicFile output(path("kept.h5"));
    std::ofstream(output.temporary_path()) << "half written";
  }
  EXPECT_EQ(read_text(path("kept.h5")), "previous result");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(directory_),
                          std::filesystem::directory_iterator()),
            1);
}

TEST_F(AtomicFileTest, MissingOutputDirectoryIsAUsageError) {
  try {
    AtomicFile output(path("no_such_dir/out.h5"));
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::usage);
    EXPECT_NE(error.reason().find("no_such_dir"), std::string::npos) << error.reason();
  }
  EXPECT_THROW(AtomicFile{directory_}, Error);  // a directory is no output file
}

TEST_F(AtomicFileTest, CommitWithoutATemporaryFileIsARuntimeError) {
  AtomicFile output(path("nothing.h5"));
  try {
    output.commit();
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::runtime);
    EXPECT_EQ(error.file(), path("nothing.h5").string());
  }
  EXPECT_FALSE(std::filesystem::exists(path("nothing.h5")));
}

}  // namespace
}  // namespace hair

namespace hair {
namespace {

/// A pid that runs no process: a child that has exited and been waited for.
pid_t finished_pid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

TEST_F(AtomicFileTest, TemporariesOfKilledProcessesAreRemovedThoseOfLiveOnesKept) {
  // A stage killed while writing leaves ".<name>.tmp.<pid>"; the next writer of that
  // output removes it. A live process's temporary, another output's, and a name that only
  // looks alike stay.
  const std::string dead = std::to_string(finished_pid());
  const std::string live = std::to_string(::getppid());
  for (const std::string& name : {".types.h5.tmp." + dead, ".types.h5.tmp." + live,
                                 ".strands.h5.tmp." + dead, ".types.h5.tmp.x" + dead})
    std::ofstream(path(name)) << "partial";
  const AtomicFile output(path("types.h5"));
  EXPECT_FALSE(std::filesystem::exists(path(".types.h5.tmp." + dead)));
  EXPECT_TRUE(std::filesystem::exists(path(".types.h5.tmp." + live)));
  EXPECT_TRUE(std::filesystem::exists(path(".strands.h5.tmp." + dead)));
  EXPECT_TRUE(std::filesystem::exists(path(".types.h5.tmp.x" + dead)));
}

}  // namespace
}  // namespace hair
