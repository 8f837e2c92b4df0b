#include <cmath>

#include "hair/core/error.h"
#include "hair/h5/attribute.h"
#include "hair/h5/dataset.h"
#include "hair/h5/file.h"
#include "unit/test_h5_support.h"

namespace hair::h5 {
namespace {

using H5AttributeTest = testing::TemporaryDirectoryTest;

TEST_F(H5AttributeTest, EveryKindRoundTripsOnGroupsAndDatasets) {
  {
    File file = File::create(path("attrs.h5"));
    write_vector<float>(file, "/strands/points", {1, 2, 3});
    write_string_attribute(file, "/", "schema", "hairstyle.extract");
    write_string_attribute(file, "/", "note", "Größe: 1.7 m, ω");  // UTF-8
    write_int64_attribute(file, "/", "schema_version", 1);
    write_int64_attribute(file, "/strands", "big", int64_t{1} << 40);
    write_double_attribute(file, "/strands/points", "scale", 0.1);
    write_double_array_attribute(file, "/strands", "bounds", {-1.5, 2.25, 1e-9});
    write_string_attribute(file, "/", "empty", "");
    file.close();
  }
  const File file = File::open_read_only(path("attrs.h5"));
  EXPECT_EQ(read_string_attribute(file, "/", "schema"), "hairstyle.extract");
  EXPECT_EQ(read_string_attribute(file, "/", "note"), "Größe: 1.7 m, ω");
  EXPECT_EQ(read_string_attribute(file, "/", "empty"), "");
  EXPECT_EQ(read_int64_attribute(file, "/", "schema_version"), 1);
  EXPECT_EQ(read_int64_attribute(file, "/strands", "big"), int64_t{1} << 40);
  EXPECT_EQ(read_double_attribute(file, "/strands/points", "scale"), 0.1);
  EXPECT_EQ(read_double_array_attribute(file, "/strands", "bounds"),
            (std::vector<double>{-1.5, 2.25, 1e-9}));
  EXPECT_TRUE(has_attribute(file, "/", "schema"));
  EXPECT_FALSE(has_attribute(file, "/", "absent"));
  EXPECT_FALSE(has_attribute(file, "/no/such/group", "schema"));
  EXPECT_EQ(attribute_names(file, "/"),
            (std::vector<std::string>{"empty", "note", "schema", "schema_version"}));
}

TEST_F(H5AttributeTest, StringsAreFixedLengthUtf8InTheObjectHeader) {
  {
    File file = File::create(path("string.h5"));
    write_string_attribute(file, "/", "unit", "m");
    write_string_attribute(file, "/", "empty", "");
    file.close();
  }
  const hid_t file = H5Fopen(path("string.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t attribute = H5Aopen(file, "unit", H5P_DEFAULT);
  const hid_t type = H5Aget_type(attribute);
  EXPECT_EQ(H5Tget_class(type), H5T_STRING);
  // Not variable-length: that would put the text in the global heap, outside checksums.
  EXPECT_EQ(H5Tis_variable_str(type), 0);
  EXPECT_EQ(H5Tget_size(type), 1u);
  EXPECT_EQ(H5Tget_cset(type), H5T_CSET_UTF8);
  H5Tclose(type);
  H5Aclose(attribute);
  H5Fclose(file);
  const File reopened = File::open_read_only(path("string.h5"));
  EXPECT_EQ(read_string_attribute(reopened, "/", "unit"), "m");
  EXPECT_EQ(read_string_attribute(reopened, "/", "empty"), "");
}

/// Writes a variable-length UTF-8 string attribute `unit` = "metre" at the root of a new
/// file at `path`, with the library's default format or the checksummed one.
void write_variable_length_unit(const std::filesystem::path& path, bool checksummed) {
  const hid_t access = H5Pcreate(H5P_FILE_ACCESS);
  if (checksummed) H5Pset_libver_bounds(access, H5F_LIBVER_V110, H5F_LIBVER_V110);
  const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access);
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attribute = H5Acreate2(file, "unit", type, space, H5P_DEFAULT, H5P_DEFAULT);
  const char* value = "metre";
  H5Awrite(attribute, type, &value);
  H5Aclose(attribute);
  H5Sclose(space);
  H5Tclose(type);
  H5Fclose(file);
  H5Pclose(access);
}

TEST_F(H5AttributeTest, VariableLengthStringsAreReadWhereTheFileIsChecksummed) {
  write_variable_length_unit(path("checked.h5"), true);
  EXPECT_EQ(read_string_attribute(File::open_read_only(path("checked.h5")), "/", "unit"), "metre");
  // In a file without checksums the global heap, where their text is, would be followed
  // unchecked (a corrupted one crashed libhdf5): such a file is refused when opened.
  write_variable_length_unit(path("unchecked.h5"), false);
  try {
    File::open_read_only(path("unchecked.h5"), "unchecked.h5");
    ADD_FAILURE() << "opened a file without checksums";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::bad_input);
    EXPECT_TRUE(std::string(error.what()).starts_with("unchecked.h5: written without metadata checksums"))
        << error.what();
  }
}

TEST_F(H5AttributeTest, FixedLengthStringsAsOtherToolsWriteThemAreRead) {
  File file = File::create(path("fixed.h5"));
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, 8);
  H5Tset_strpad(type, H5T_STR_NULLPAD);
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attribute = H5Acreate2(file.id(), "unit", type, space, H5P_DEFAULT, H5P_DEFAULT);
  const char value[8] = {'m', 'e', 't', 'r', 'e', 0, 0, 0};
  H5Awrite(attribute, type, value);
  H5Aclose(attribute);
  H5Sclose(space);
  H5Tclose(type);
  EXPECT_EQ(read_string_attribute(file, "/", "unit"), "metre");
}

TEST_F(H5AttributeTest, WritingAgainReplacesTheValueAndType) {
  File file = File::create(path("replace.h5"));
  write_double_attribute(file, "/", "x", 1.0);
  write_int64_attribute(file, "/", "x", 2);
  EXPECT_EQ(read_int64_attribute(file, "/", "x"), 2);
  EXPECT_THROW(read_double_attribute(file, "/", "x"), Error);
}

TEST_F(H5AttributeTest, TypeMismatchNamesObjectAttributeAndTypes) {
  File file = File::create(path("types.h5"), "types.h5");
  write_double_attribute(file, "/", "schema_version", 1.0);
  write_int64_attribute(file, "/", "count", 3);
  write_double_array_attribute(file, "/", "bounds", {1.0, 2.0});
  try {
    read_int64_attribute(file, "/", "schema_version");
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::bad_input);
    EXPECT_STREQ(error.what(), "types.h5:/@schema_version: expected int64, found float64");
  }
  EXPECT_THROW(read_string_attribute(file, "/", "count"), Error);
  EXPECT_THROW(read_double_attribute(file, "/", "bounds"), Error);  // an array, not a scalar
  EXPECT_THROW(read_double_array_attribute(file, "/", "schema_version"), Error);  // a scalar
  try {
    read_string_attribute(file, "/", "absent");
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_STREQ(error.what(), "types.h5:/@absent: missing attribute");
  }
}

TEST_F(H5AttributeTest, AttributeOnAMissingObjectIsARuntimeError) {
  File file = File::create(path("missing.h5"));
  try {
    write_string_attribute(file, "/nowhere", "x", "y");
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::runtime);
  }
}

TEST_F(H5AttributeTest, TextAndTypeNamesForListings) {
  File file = File::create(path("text.h5"));
  write_string_attribute(file, "/", "s", "hello");
  write_int64_attribute(file, "/", "i", -4);
  write_double_attribute(file, "/", "d", 0.1);
  write_double_array_attribute(file, "/", "a", {1.0, 2.5});
  EXPECT_EQ(attribute_text(file, "/", "s"), "hello");
  EXPECT_EQ(attribute_text(file, "/", "i"), "-4");
  EXPECT_EQ(attribute_text(file, "/", "d"), "0.1");
  EXPECT_EQ(attribute_text(file, "/", "a"), "[1, 2.5]");
  EXPECT_EQ(attribute_type_name(file, "/", "a"), "float64[2]");
  EXPECT_EQ(attribute_type_name(file, "/", "s"), "string");
}

}  // namespace
}  // namespace hair::h5
