#include <chrono>
#include <fstream>
#include <iterator>
#include <thread>

#include "hair/core/error.h"
#include "hair/h5/attribute.h"
#include "hair/h5/dataset.h"
#include "hair/h5/file.h"
#include "unit/test_h5_support.h"

namespace hair::h5 {
namespace {

using H5FileTest = testing::TemporaryDirectoryTest;

TEST_F(H5FileTest, CreatesNestedGroupsAndReportsWhatPathsName) {
  File file = File::create(path("groups.h5"));
  file.create_group("/a/b/c");
  file.create_group("/a/b");  // existing: kept
  write_vector<int32_t>(file, "/a/values", {1, 2, 3});
  EXPECT_EQ(file.kind_of("/"), ObjectKind::group);
  EXPECT_EQ(file.kind_of("/a/b/c"), ObjectKind::group);
  EXPECT_EQ(file.kind_of("/a/values"), ObjectKind::dataset);
  EXPECT_EQ(file.kind_of("/a/missing"), ObjectKind::missing);
  EXPECT_EQ(file.kind_of("/x/y/z"), ObjectKind::missing);
  EXPECT_TRUE(file.exists("/a/b"));
  EXPECT_FALSE(file.exists("/a/values/inside"));
  EXPECT_EQ(file.member_names("/a"), (std::vector<std::string>{"b", "values"}));
}

TEST_F(H5FileTest, GroupWhereADatasetIsIsARuntimeError) {
  File file = File::create(path("clash.h5"));
  write_vector<int32_t>(file, "/a", {1});
  try {
    file.create_group("/a/b");
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::runtime);
    EXPECT_EQ(error.dataset(), "/a");
  }
}

TEST_F(H5FileTest, OpeningAMissingFileNamesIt) {
  try {
    File::open_read_only(path("absent.h5"));
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::bad_input);
    EXPECT_EQ(error.file(), path("absent.h5").string());
    EXPECT_EQ(error.reason(), "no such file");
  }
}

TEST_F(H5FileTest, OpeningATextFileSaysItIsNotHdf5) {
  std::ofstream(path("notes.h5")) << "not hdf5\n";
  try {
    File::open_read_only(path("notes.h5"));
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::bad_input);
    EXPECT_EQ(error.reason(), "not an HDF5 file");
  }
}

TEST_F(H5FileTest, CreatingInAMissingDirectoryIsARuntimeErrorNamingTheDisplayName) {
  try {
    File::create(path("no/such/dir/out.h5"), "out.h5");
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::runtime);
    EXPECT_EQ(error.file(), "out.h5");
    EXPECT_NE(std::string(error.what()).find("cannot create HDF5 file"), std::string::npos);
  }
}

TEST_F(H5FileTest, ReadOnlyFileRefusesWrites) {
  {
    File file = File::create(path("ro.h5"));
    file.close();
  }
  File file = File::open_read_only(path("ro.h5"));
  EXPECT_FALSE(file.writable());
  EXPECT_THROW(write_vector<int32_t>(file, "/x", {1}), Error);
}

TEST_F(H5FileTest, MissingDatasetErrorNamesFileAndDataset) {
  File file = File::create(path("empty.h5"), "empty.h5");
  try {
    read_vector<float>(file, "/strands/points");
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_STREQ(error.what(), "empty.h5:/strands/points: missing dataset");
  }
}

TEST_F(H5FileTest, PathHelpers) {
  EXPECT_EQ(parent_path("/a/b"), "/a");
  EXPECT_EQ(parent_path("/a"), "/");
  EXPECT_EQ(child_path("/", "b"), "/b");
  EXPECT_EQ(child_path("/a", "b"), "/a/b");
}

}  // namespace
}  // namespace hair::h5

namespace hair::h5 {
namespace {

/// The bytes of a small file with a group, a dataset and attributes, written at `path`.
std::string written_bytes(const std::filesystem::path& path) {
  {
    File file = File::create(path);
    write_string_attribute(file, "/", "schema", "hairstyle.test");
    write_vector<float>(file, "/a/values", {1.0f, 2.0f, 3.0f});
    file.close();
  }
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST_F(H5FileTest, TheSameContentWrittenSecondsApartIsTheSameBytes) {
  // The checksummed format would keep each object's times, the root group's included;
  // every object is created without them, so reproducible runs stay byte-identical.
  const std::string first = written_bytes(path("first.h5"));
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  const std::string second = written_bytes(path("second.h5"));
  EXPECT_TRUE(first == second);
  EXPECT_TRUE(File::open_read_only(path("first.h5")).has_checksummed_metadata());
}

}  // namespace
}  // namespace hair::h5
