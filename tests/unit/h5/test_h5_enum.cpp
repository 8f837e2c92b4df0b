#include "hair/core/error.h"
#include "hair/h5/enum_dataset.h"
#include "hair/h5/file.h"
#include "unit/test_h5_support.h"

namespace hair::h5 {
namespace {

using H5EnumTest = testing::TemporaryDirectoryTest;

const EnumMembers kStrandTypes = {
    {"root_free", 0}, {"root_connected", 1}, {"middle", 2}, {"tip", 3}};

TEST_F(H5EnumTest, ValuesAndMembersRoundTrip) {
  const std::vector<int8_t> values = {0, 2, 2, 3, 1, 0};
  {
    File file = File::create(path("enum.h5"));
    write_enum_dataset(file, "/groups/type", values, kStrandTypes);
    file.close();
  }
  const File file = File::open_read_only(path("enum.h5"));
  EXPECT_EQ(read_enum_dataset(file, "/groups/type", kStrandTypes), values);
  EXPECT_EQ(read_enum_members(file, "/groups/type"), kStrandTypes);
  // The stored type is a real HDF5 enum over int8, as h5py and h5dump show it.
  const hid_t dataset = H5Dopen2(file.id(), "/groups/type", H5P_DEFAULT);
  const hid_t type = H5Dget_type(dataset);
  EXPECT_EQ(H5Tget_class(type), H5T_ENUM);
  char name[32] = {0};
  const int8_t middle = 2;
  ASSERT_GE(H5Tenum_nameof(type, &middle, name, sizeof(name)), 0);
  EXPECT_STREQ(name, "middle");
  H5Tclose(type);
  H5Dclose(dataset);
}

TEST_F(H5EnumTest, MemberOrderDoesNotMatterButNamesAndValuesDo) {
  File file = File::create(path("enum.h5"), "enum.h5");
  write_enum_dataset(file, "/t", {1, 0}, kStrandTypes);
  const EnumMembers reordered = {
      {"tip", 3}, {"middle", 2}, {"root_connected", 1}, {"root_free", 0}};
  EXPECT_EQ(read_enum_dataset(file, "/t", reordered), (std::vector<int8_t>{1, 0}));

  EnumMembers renumbered = kStrandTypes;
  renumbered[2].value = 5;
  try {
    read_enum_dataset(file, "/t", renumbered);
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::bad_input);
    EXPECT_EQ(error.dataset(), "/t");
    EXPECT_EQ(error.reason().rfind("enum member 'middle' has value 2, expected 5", 0), 0u)
        << error.reason();
  }
  EnumMembers extra = kStrandTypes;
  extra.push_back({"braided", 4});
  EXPECT_EQ(enum_members_difference(kStrandTypes, extra), "enum member 'braided' missing");
  EXPECT_EQ(enum_members_difference(extra, kStrandTypes), "unexpected enum member 'braided'");
  EXPECT_EQ(enum_members_difference(kStrandTypes, reordered), "");
}

TEST_F(H5EnumTest, ReadingAPlainIntegerDatasetAsEnumFails) {
  File file = File::create(path("plain.h5"), "plain.h5");
  write_vector<int8_t>(file, "/t", {0, 1});
  try {
    read_enum_dataset(file, "/t", kStrandTypes);
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_STREQ(error.what(), "plain.h5:/t: expected enum int8, found int8");
  }
}

TEST_F(H5EnumTest, WritingANonMemberValueOrRepeatedMembersFails) {
  File file = File::create(path("bad.h5"));
  EXPECT_THROW(write_enum_dataset(file, "/t", {0, 9}, kStrandTypes), Error);
  EXPECT_THROW(write_enum_dataset(file, "/u", {0}, {{"a", 0}, {"b", 0}}), Error);
  EXPECT_THROW(write_enum_dataset(file, "/w", {0}, {{"a", 0}, {"a", 1}}), Error);
  EXPECT_FALSE(file.exists("/t"));
}

TEST(H5EnumFormat, ListsMembers) {
  EXPECT_EQ(format_enum_members({{"strip", 0}, {"grid", 1}}), "{strip=0, grid=1}");
}

}  // namespace
}  // namespace hair::h5
