// Corrupted intermediates are refused before they are trusted (issue 30): files are
// written with checksummed metadata and checksummed chunks, so flipped bytes, a cut
// file or a file from a writer without checksums give a bad_input error naming the
// file, never a crash or a wrong read.

#include <gtest/gtest.h>
#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <vector>

#include "unit/file_test.h"
#include "fuzz/fuzz_readers.h"
#include "support/run_command.h"
#include "hair/h5/attribute.h"
#include "hair/h5/dataset.h"
#include "hair/h5/schema.h"
#include "hair/h5/schema_validation.h"
#include "unit/test_schema_extract_fixture.h"

namespace {

namespace fs = std::filesystem;
using hair::Error;
using hair::ErrorKind;

void write_bytes(const fs::path& path, const std::vector<uint8_t>& bytes, size_t size) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(size));
}

/// The first error opening `path` and reading it as a stage reads extract.h5 gives, or
/// nothing if it reads.
std::optional<Error> extract_read_error(const fs::path& path) {
  try {
    const hair::h5::File file = hair::h5::File::open_read_only(path, "extract.h5");
    hair::h5::require_schema(file, "hairstyle.extract");
    hair::fuzz::read_as_stages_do(file, "hairstyle.extract");
  } catch (const Error& error) {
    return error;
  }
  return std::nullopt;
}

class H5Corruption : public hair::test::FileTest {
 protected:
  fs::path valid_extract() {
    const fs::path path = directory_.path() / "valid.h5";
    hair::testing::write_extract_file(path);
    return path;
  }
};

TEST_F(H5Corruption, WrittenFilesChecksumTheirMetadataAndEveryChunk) {
  const fs::path path = valid_extract();
  const hair::h5::File file = hair::h5::File::open_read_only(path);
  EXPECT_TRUE(file.has_checksummed_metadata());
  EXPECT_FALSE(file.unchecked_metadata().has_value());
  H5F_info2_t file_info{};
  ASSERT_GE(H5Fget_info2(file.id(), &file_info), 0);
  EXPECT_EQ(file_info.super.version, hair::h5::kWrittenSuperblockVersion);
  for (const char* dataset : {"/strands/points", "/strands/offsets", "/body/vertices"}) {
    const hair::h5::DatasetInfo info = hair::h5::dataset_info(file, dataset);
    EXPECT_EQ(info.filters, std::vector<std::string>{"fletcher32"}) << dataset;
  }
  // The string attributes stay out of the global heap, which has no checksum.
  const hair::h5::Handle attribute(H5Aopen(file.id(), "schema", H5P_DEFAULT), H5Aclose);
  const hair::h5::Handle type(H5Aget_type(attribute.get()), H5Tclose);
  EXPECT_EQ(H5Tis_variable_str(type.get()), 0);
  EXPECT_EQ(hair::h5::read_string_attribute(file, "/", "schema"), "hairstyle.extract");
}

TEST_F(H5Corruption, LinksAndAttributesStayInTheObjectHeadersHoweverMany) {
  // More than HDF5's default of 8 go to "dense" fractal heaps, whose blocks carry no
  // checksum; hairstyle keeps them in the (checksummed) object headers.
  const fs::path path = directory_.path() / "many.h5";
  {
    hair::h5::File file = hair::h5::File::create(path);
    for (int k = 0; k < 20; ++k) {
      const std::string name = "member" + std::to_string(k);
      hair::h5::write_int64_attribute(file, "/", name, k);
      hair::h5::write_vector<float>(file, "/group/" + name, {1.0f, 2.0f});
      hair::h5::write_int64_attribute(file, "/group/" + name, "index", k);
    }
    file.close();
  }
  const hair::h5::File file = hair::h5::File::open_read_only(path);
  for (const char* object : {"/", "/group", "/group/member7"}) {
    H5O_info_t header{};
    ASSERT_GE(H5Oget_info_by_name2(file.id(), object, &header, H5O_INFO_META_SIZE, H5P_DEFAULT), 0);
    EXPECT_EQ(header.meta_size.attr.heap_size, 0u) << object;
  }
  for (const char* group : {"/", "/group"}) {
    H5G_info_t links{};
    ASSERT_GE(H5Gget_info_by_name(file.id(), group, &links, H5P_DEFAULT), 0) << group;
    EXPECT_EQ(links.storage_type, H5G_STORAGE_TYPE_COMPACT) << group;
  }
  H5G_info_t group{};
  ASSERT_GE(H5Gget_info_by_name(file.id(), "/group", &group, H5P_DEFAULT), 0);
  EXPECT_EQ(group.nlinks, 20u);
}

TEST_F(H5Corruption, ByteFlippedFilesAreReadOrRefusedNeverTrustedWrong) {
  const std::vector<uint8_t> valid = hair::test::read_file_octets(valid_extract());
  std::mt19937_64 random(30);  // fixed: the same 400 variants on every run
  int refused = 0, read_back = 0;
  const fs::path variant = directory_.path() / "variant.h5";
  for (int v = 0; v < 400; ++v) {
    std::vector<uint8_t> bytes = valid;
    const int flips = 1 + static_cast<int>(random() % 3);
    for (int f = 0; f < flips; ++f)
      bytes[random() % bytes.size()] ^= static_cast<uint8_t>(1 + random() % 255);
    write_bytes(variant, bytes, bytes.size());
    const std::optional<Error> error = extract_read_error(variant);
    if (!error) {
      ++read_back;
      continue;
    }
    ++refused;
    EXPECT_EQ(error->kind(), ErrorKind::bad_input) << "variant " << v << ": " << error->what();
    EXPECT_NE(std::string(error->what()).find("extract.h5"), std::string::npos) << error->what();
    EXPECT_EQ(std::string(error->what()).find('\n'), std::string::npos) << error->what();
  }
  // A flipped byte that the read still takes fell where the file holds nothing (padding,
  // unused header space); everything with meaning is checksummed.
  EXPECT_GE(refused, 300) << read_back << " variants read back";
}

TEST_F(H5Corruption, AFileCutAtAnyByteIsRefusedByName) {
  const std::vector<uint8_t> valid = hair::test::read_file_octets(valid_extract());
  const fs::path cut = directory_.path() / "cut.h5";
  for (size_t size = 0; size < valid.size(); size += (size < 4096 ? 1 : 7)) {
    write_bytes(cut, valid, size);
    const std::optional<Error> error = extract_read_error(cut);
    ASSERT_TRUE(error.has_value()) << "cut at " << size << " of " << valid.size();
    EXPECT_EQ(error->kind(), ErrorKind::bad_input) << size << ": " << error->what();
    EXPECT_TRUE(std::string(error->what()).starts_with("extract.h5")) << error->what();
  }
}

TEST_F(H5Corruption, AFileWithoutMetadataChecksumsIsRefused) {
  // Written as HDF5 writes by default (superblock version 0: nothing checksummed): a
  // file of an older hairstyle or of another writer.
  const fs::path path = directory_.path() / "unchecked.h5";
  const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  H5Fclose(file);
  const std::optional<Error> error = extract_read_error(path);
  ASSERT_TRUE(error.has_value());
  EXPECT_EQ(error->kind(), ErrorKind::bad_input);
  EXPECT_EQ(std::string(error->what()),
            "extract.h5: written without metadata checksums (HDF5 superblock version 0; "
            "hairstyle writes version 3), not by this hairstyle: rerun the stage that wrote it");
}

TEST_F(H5Corruption, AHardLinkBackToAnAncestorIsWalkedOnce) {
  // The walk that looks for unchecked storage visits each object once: a group linked
  // into itself does not loop.
  const fs::path path = directory_.path() / "loop.h5";
  {
    hair::h5::File file = hair::h5::File::create(path);
    file.create_group("/a");
    ASSERT_GE(H5Lcreate_hard(file.id(), "/", file.id(), "/a/loop", H5P_DEFAULT, H5P_DEFAULT), 0);
    file.close();
  }
  const hair::h5::File file = hair::h5::File::open_read_only(path);
  EXPECT_FALSE(file.unchecked_metadata().has_value());
}

TEST_F(H5Corruption, AFileKeepingAttributesOrLinksInDenseStorageIsRefused) {
  // The checksummed format, but with HDF5's default of at most 8 links or attributes
  // kept in an object's header: more go to fractal heap blocks without checksums, where
  // a corrupted link crashed libhdf5 under the fuzzer.
  for (const bool links : {false, true}) {
    const fs::path path = directory_.path() / (links ? "dense_links.h5" : "dense_attributes.h5");
    const hid_t access = H5Pcreate(H5P_FILE_ACCESS);
    H5Pset_libver_bounds(access, H5F_LIBVER_V110, H5F_LIBVER_V110);
    const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access);
    H5Pclose(access);
    const hid_t group = H5Gcreate2(file, "/many", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    const hid_t space = H5Screate(H5S_SCALAR);
    for (int k = 0; k < 12; ++k) {
      const std::string name = "member" + std::to_string(k);
      const hid_t object = links ? H5Gcreate2(group, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT)
                                 : H5Acreate2(group, name.c_str(), H5T_NATIVE_INT, space, H5P_DEFAULT, H5P_DEFAULT);
      links ? H5Gclose(object) : H5Aclose(object);
    }
    H5Sclose(space);
    H5Gclose(group);
    H5Fclose(file);
    const std::optional<Error> error = extract_read_error(path);
    ASSERT_TRUE(error.has_value());
    EXPECT_EQ(error->kind(), ErrorKind::bad_input);
    EXPECT_TRUE(std::string(error->what())
                    .starts_with(std::string("extract.h5:/many: ") +
                                 (links ? "links" : "attributes") + " in dense storage"))
        << error->what();
  }
}

}  // namespace
