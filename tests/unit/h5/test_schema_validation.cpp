#include <limits>

#include "hair/core/error.h"
#include "hair/h5/attribute.h"
#include "hair/h5/dataset.h"
#include "hair/h5/enum_dataset.h"
#include "hair/h5/schema_validation.h"
#include "unit/test_h5_support.h"
#include "unit/test_schema_extract_fixture.h"

namespace hair::h5 {
namespace {

using testing::remove_object;

/// A schema with every kind of rule, fixed here so these tests do not follow the
/// changes of the pipeline's own schemas.
const Schema& test_schema() {
  static const Schema schema = Schema::parse(R"({
    "name": "test.hair", "version": 1, "description": "Strands, groups and a body.",
    "history": [{"version": 1, "changes": "First version."}],
    "dimensions": {"n_points": "points", "n_strands": "strands", "n_groups": "groups",
                   "n_body_vertices": "body vertices", "n_body_triangles": "body triangles"},
    "attributes": [
      {"name": "unit", "dtype": "string", "equals": "m", "description": "Unit."},
      {"name": "head_height_m", "dtype": "float64", "exclusive_min": 0, "description": "H."},
      {"name": "neck_y_m", "dtype": "float64", "description": "Neck height."},
      {"name": "parameters", "dtype": "string", "format": "json", "description": "Parameters."},
      {"name": "wall_time_s", "dtype": "float64", "min": 0, "required": false, "description": "Time."}
    ],
    "datasets": [
      {"path": "/strands/points", "dtype": "float32", "shape": ["n_points", 3], "unit": "m",
       "description": "Points."},
      {"path": "/strands/offsets", "dtype": "int64", "shape": ["n_strands+1"],
       "constraints": {"csr_offsets_of": "n_points"}, "description": "Offsets."},
      {"path": "/strands/group", "dtype": "int32", "shape": ["n_strands"],
       "constraints": {"index_into": "n_groups"}, "description": "Group of each strand."},
      {"path": "/strands/rail", "dtype": "int32", "shape": ["n_strands"],
       "constraints": {"min": 0}, "description": "Rail."},
      {"path": "/strands/source_vertex", "dtype": "int32", "shape": ["n_points"],
       "constraints": {"index_into": "n_body_vertices", "allow_none": true},
       "description": "Source vertex or -1."},
      {"path": "/groups/kind", "dtype": "enum", "enum": {"strip": 0, "grid": 1, "tube": 2},
       "shape": ["n_groups"], "description": "Kind."},
      {"path": "/groups/confidence", "dtype": "float32", "shape": ["n_groups"],
       "constraints": {"min": 0, "max": 1}, "description": "Confidence."},
      {"path": "/groups/first_strand", "dtype": "int32", "shape": ["n_groups+1"],
       "constraints": {"csr_offsets_of": "n_strands"}, "description": "First strand."},
      {"path": "/groups/uv", "dtype": "float32", "shape": ["n_groups", 2], "required": false,
       "description": "Optional."},
      {"path": "/body/vertices", "dtype": "float32", "shape": ["n_body_vertices", 3],
       "description": "Body vertices."},
      {"path": "/body/triangles", "dtype": "int32", "shape": ["n_body_triangles", 3],
       "constraints": {"index_into": "n_body_vertices"}, "description": "Triangles."},
      {"path": "/body/scalp_triangle", "dtype": "uint8", "shape": ["n_body_triangles"],
       "constraints": {"min": 0, "max": 1}, "description": "Scalp flags."}
    ]})",
                                             "test_hair.json");
  return schema;
}

const EnumMembers kKinds = {{"strip", 0}, {"grid", 1}, {"tube", 2}};

class SchemaValidationTest : public testing::TemporaryDirectoryTest {
 protected:
  /// The first violation of test.hair by a conforming file (2 groups, 3 strands of 2, 3
  /// and 2 points, a body of 4 vertices and 2 triangles) changed by `tamper`, or "valid".
  std::string violation_of(const std::function<void(File&)>& tamper) {
    File file = File::create(path("test.h5"), "test.h5");
    write_schema_attributes(file, test_schema());
    write_string_attribute(file, "/", "unit", "m");
    write_double_attribute(file, "/", "head_height_m", 0.25);
    write_double_attribute(file, "/", "neck_y_m", 1.5);
    write_string_attribute(file, "/", "parameters", R"({"k": 1})");
    write_double_attribute(file, "/", "wall_time_s", 0.5);
    write_dataset<float>(file, "/strands/points", std::vector<float>(21, 0.5f), {7, 3});
    write_vector<int64_t>(file, "/strands/offsets", {0, 2, 5, 7});
    write_vector<int32_t>(file, "/strands/group", {0, 0, 1});
    write_vector<int32_t>(file, "/strands/rail", {0, 1, 0});
    write_vector<int32_t>(file, "/strands/source_vertex", {0, 1, 2, 3, -1, -1, 0});
    write_enum_dataset(file, "/groups/kind", {1, 0}, kKinds);
    write_vector<float>(file, "/groups/confidence", {1.0f, 0.5f});
    write_vector<int32_t>(file, "/groups/first_strand", {0, 2, 3});
    write_dataset<float>(file, "/body/vertices", std::vector<float>(12, 0.25f), {4, 3});
    write_dataset<int32_t>(file, "/body/triangles", {0, 1, 2, 0, 2, 3}, {2, 3});
    write_vector<uint8_t>(file, "/body/scalp_triangle", {1, 0});
    if (tamper) tamper(file);
    const std::optional<Error> violation = first_violation(file, test_schema());
    return violation ? violation->what() : "valid";
  }
};

TEST_F(SchemaValidationTest, ConformingFileIsValid) { EXPECT_EQ(violation_of({}), "valid"); }

TEST_F(SchemaValidationTest, OptionalDatasetMayBeAbsentButMustFitWhenPresent) {
  EXPECT_EQ(violation_of([](File& file) {
              write_dataset<float>(file, "/groups/uv", {0, 0, 1, 1}, {2, 2});
            }),
            "valid");
  EXPECT_EQ(violation_of([](File& file) {
              write_dataset<float>(file, "/groups/uv", {0, 0, 1, 1, 2, 2}, {3, 2});
            }),
            "test.h5:/groups/uv: expected shape [n_groups, 2] = [2, 2] "
            "(n_groups = 2 from /groups/kind), found [3, 2]");
}

TEST_F(SchemaValidationTest, WrongDtype) {
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/strands/points");
              write_dataset<double>(file, "/strands/points", std::vector<double>(21, 0.0), {7, 3});
            }),
            "test.h5:/strands/points: expected float32, found float64");
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/strands/group");
              write_vector<int64_t>(file, "/strands/group", {0, 0, 1});
            }),
            "test.h5:/strands/group: expected int32, found int64");
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/groups/kind");
              write_vector<int8_t>(file, "/groups/kind", {0, 1});
            }),
            "test.h5:/groups/kind: expected enum {strip=0, grid=1, tube=2}, found int8");
}

TEST_F(SchemaValidationTest, WrongShape) {
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/strands/points");
              write_dataset<float>(file, "/strands/points", std::vector<float>(28, 0.0f), {7, 4});
            }),
            "test.h5:/strands/points: expected shape [n_points, 3] = [7, 3] "
            "(n_points = 7 from /strands/points), found [7, 4]");
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/body/scalp_triangle");
              write_dataset<uint8_t>(file, "/body/scalp_triangle", {1, 0}, {2, 1});
            }),
            "test.h5:/body/scalp_triangle: expected shape [n_body_triangles] = [2] "
            "(n_body_triangles = 2 from /body/triangles), found [2, 1]");
}

TEST_F(SchemaValidationTest, DimensionsDisagree) {
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/strands/source_vertex");
              write_vector<int32_t>(file, "/strands/source_vertex", {0, 1, 2});
            }),
            "test.h5:/strands/source_vertex: expected shape [n_points] = [7] "
            "(n_points = 7 from /strands/points), found [3]");
  // n_strands+1: the offsets bind n_strands = 3.
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/strands/rail");
              write_vector<int32_t>(file, "/strands/rail", {0, 1, 0, 2});
            }),
            "test.h5:/strands/rail: expected shape [n_strands] = [3] "
            "(n_strands = 3 from /strands/offsets), found [4]");
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/groups/first_strand");
              write_vector<int32_t>(file, "/groups/first_strand", {0, 3});
            }),
            "test.h5:/groups/first_strand: expected shape [n_groups+1] = [3] "
            "(n_groups = 2 from /groups/kind), found [2]");
}

TEST_F(SchemaValidationTest, NonFiniteValue) {
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/strands/points");
              std::vector<float> points(21, 0.0f);
              points[5] = std::numeric_limits<float>::quiet_NaN();
              write_dataset<float>(file, "/strands/points", points, {7, 3});
            }),
            "test.h5:/strands/points: expected finite values, found nan at [1, 2]");
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/groups/confidence");
              write_vector<float>(file, "/groups/confidence",
                                  {1.0f, -std::numeric_limits<float>::infinity()});
            }),
            "test.h5:/groups/confidence: expected finite values, found -inf at [1]");
}

TEST_F(SchemaValidationTest, ValueOutOfRange) {
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/body/scalp_triangle");
              write_vector<uint8_t>(file, "/body/scalp_triangle", {1, 2});
            }),
            "test.h5:/body/scalp_triangle: expected values <= 1, found 2 at [1]");
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/groups/confidence");
              write_vector<float>(file, "/groups/confidence", {1.5f, 0.5f});
            }),
            "test.h5:/groups/confidence: expected values <= 1, found 1.5 at [0]");
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/strands/rail");
              write_vector<int32_t>(file, "/strands/rail", {0, -1, 0});
            }),
            "test.h5:/strands/rail: expected values >= 0, found -1 at [1]");
}

TEST_F(SchemaValidationTest, BadCsrOffsets) {
  const auto with_offsets = [&](std::vector<int64_t> offsets) {
    return violation_of([&](File& file) {
      remove_object(file, "/strands/offsets");
      write_vector<int64_t>(file, "/strands/offsets", offsets);
    });
  };
  EXPECT_EQ(with_offsets({1, 2, 5, 7}),
            "test.h5:/strands/offsets: expected CSR offsets starting at 0, found 1");
  EXPECT_EQ(with_offsets({0, 5, 2, 7}),
            "test.h5:/strands/offsets: expected non-decreasing CSR offsets, found 2 after 5 "
            "at [2]");
  EXPECT_EQ(with_offsets({0, 2, 5, 6}),
            "test.h5:/strands/offsets: expected CSR offsets ending at n_points = 7 "
            "(from /strands/points), found 6");
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/groups/first_strand");
              write_vector<int32_t>(file, "/groups/first_strand", {0, 2, 4});
            }),
            "test.h5:/groups/first_strand: expected CSR offsets ending at n_strands = 3 "
            "(from /strands/offsets), found 4");
}

TEST_F(SchemaValidationTest, IndexOutOfRange) {
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/strands/group");
              write_vector<int32_t>(file, "/strands/group", {0, 0, 2});
            }),
            "test.h5:/strands/group: expected indices into n_groups (0 <= i < 2), found 2 at [2]");
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/body/triangles");
              write_dataset<int32_t>(file, "/body/triangles", {0, 1, 2, 0, -1, 3}, {2, 3});
            }),
            "test.h5:/body/triangles: expected indices into n_body_vertices (0 <= i < 4), "
            "found -1 at [1, 1]");
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/strands/source_vertex");
              write_vector<int32_t>(file, "/strands/source_vertex", {0, 1, 2, 3, -1, -2, 0});
            }),
            "test.h5:/strands/source_vertex: expected indices into n_body_vertices "
            "(0 <= i < 4, or -1), found -2 at [5]");
}

TEST_F(SchemaValidationTest, EnumMembersAndValues) {
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/groups/kind");
              write_enum_dataset(file, "/groups/kind", {0, 1}, {{"strip", 0}, {"grid", 1}});
            }),
            "test.h5:/groups/kind: enum member 'tube' missing");
  EXPECT_EQ(
      violation_of([](File& file) {
        remove_object(file, "/groups/kind");
        write_enum_dataset(file, "/groups/kind", {0, 1}, {{"strip", 0}, {"grid", 2}, {"tube", 1}});
      }),
      "test.h5:/groups/kind: enum member 'grid' has value 2, expected 1");
  EXPECT_EQ(violation_of([](File& file) {
              // A value outside the members, as a careless writer could store it.
              remove_object(file, "/groups/kind");
              const hid_t type = H5Tenum_create(H5T_STD_I8LE);
              for (const EnumMember& member : kKinds) {
                H5Tenum_insert(type, member.name.c_str(), &member.value);
              }
              const std::vector<int8_t> values = {1, 9};
              write_raw_dataset(file, "/groups/kind", type, type, values.data(), {2}, {});
              H5Tclose(type);
            }),
            "test.h5:/groups/kind: expected a member of {strip=0, grid=1, tube=2}, found value 9 "
            "at [1]");
}

TEST_F(SchemaValidationTest, MissingRequiredDataset) {
  EXPECT_EQ(violation_of([](File& file) { remove_object(file, "/body/triangles"); }),
            "test.h5:/body/triangles: missing required dataset");
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/strands/rail");
              file.create_group("/strands/rail");
            }),
            "test.h5:/strands/rail: expected a dataset, found a group");
}

TEST_F(SchemaValidationTest, RootAttributes) {
  EXPECT_EQ(violation_of([](File& file) { write_string_attribute(file, "/", "unit", "cm"); }),
            "test.h5:/@unit: expected \"m\", found \"cm\"");
  EXPECT_EQ(violation_of([](File& file) { write_double_attribute(file, "/", "head_height_m", 0); }),
            "test.h5:/@head_height_m: expected a value > 0, found 0");
  EXPECT_EQ(violation_of([](File& file) {
              write_double_attribute(file, "/", "neck_y_m",
                                     std::numeric_limits<double>::quiet_NaN());
            }),
            "test.h5:/@neck_y_m: expected a finite value, found nan");
  EXPECT_EQ(violation_of([](File& file) { write_int64_attribute(file, "/", "neck_y_m", 1); }),
            "test.h5:/@neck_y_m: expected float64, found int64");
  EXPECT_EQ(
      violation_of([](File& file) { write_string_attribute(file, "/", "parameters", "k = 1"); }),
      "test.h5:/@parameters: expected JSON text, found \"k = 1\"");
  EXPECT_EQ(violation_of([](File& file) { H5Adelete(file.id(), "unit"); }),
            "test.h5:/@unit: missing root attribute");
  EXPECT_EQ(violation_of([](File& file) { H5Adelete(file.id(), "wall_time_s"); }), "valid");
  EXPECT_EQ(violation_of([](File& file) { write_double_attribute(file, "/", "wall_time_s", -1); }),
            "test.h5:/@wall_time_s: expected a value >= 0, found -1");
}

TEST_F(SchemaValidationTest, SchemaNameAndVersion) {
  EXPECT_EQ(
      violation_of([](File& file) { write_int64_attribute(file, "/", "schema_version", 0); }),
      "test.h5:/@schema_version: schema version 0 is older than supported 1; no upgrade path");
  EXPECT_EQ(violation_of([](File& file) { write_int64_attribute(file, "/", "schema_version", 2); }),
            "test.h5:/@schema_version: schema version 2 is newer than supported 1; use a newer "
            "hairstyle");
  EXPECT_EQ(
      violation_of([](File& file) { write_string_attribute(file, "/", "schema_version", "1"); }),
      "test.h5:/@schema_version: expected int64, found string");
  EXPECT_EQ(
      violation_of([](File& file) { write_string_attribute(file, "/", "schema", "test.other"); }),
      "test.h5:/@schema: expected test.hair, found test.other");
  EXPECT_EQ(violation_of([](File& file) { H5Adelete(file.id(), "schema"); }),
            "test.h5:/@schema: missing root attribute: not a hairstyle intermediate file");
}

TEST_F(SchemaValidationTest, TheFirstViolationIsReported) {
  // Attributes come before layouts, layouts before values, datasets in schema order.
  const auto break_group_and_body = [](File& file) {
    remove_object(file, "/strands/group");
    write_vector<int32_t>(file, "/strands/group", {0, 0, 7});
    remove_object(file, "/body/vertices");
  };
  EXPECT_EQ(violation_of([&](File& file) {
              break_group_and_body(file);
              write_string_attribute(file, "/", "unit", "mm");
            }),
            "test.h5:/@unit: expected \"m\", found \"mm\"");
  EXPECT_EQ(violation_of(break_group_and_body), "test.h5:/body/vertices: missing required dataset");
}

class RegisteredSchemaTest : public testing::TemporaryDirectoryTest {};

TEST_F(RegisteredSchemaTest, UnknownOrMissingSchemaNameIsAViolation) {
  File file = File::create(path("other.h5"), "other.h5");
  EXPECT_EQ(validate_file(file),
            "other.h5:/@schema: missing root attribute: not a hairstyle intermediate file");
  write_string_attribute(file, "/", "schema", "hairstyle.nope");
  const std::optional<std::string> violation = validate_file(file);
  ASSERT_TRUE(violation.has_value());
  EXPECT_EQ(violation->rfind("other.h5:/@schema: unknown schema 'hairstyle.nope' (known: ", 0), 0u)
      << *violation;
  EXPECT_NE(violation->find("hairstyle.extract"), std::string::npos) << *violation;
  try {
    require_schema(file, "hairstyle.extract");
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::bad_input);
    EXPECT_EQ(error.exit_code(), 2);
    EXPECT_STREQ(error.what(),
                 "other.h5:/@schema: expected hairstyle.extract, found hairstyle.nope");
  }
  EXPECT_THROW(require_schema(file, "hairstyle.nope"), Error);  // a usage error: no such schema
}

TEST_F(RegisteredSchemaTest, ExtractFixtureConformsAndOutputCheckThrowsRuntime) {
  testing::write_extract_file(path("extract.h5"));
  const File file = File::open_read_only(path("extract.h5"), "extract.h5");
  EXPECT_EQ(validate_file(file), std::nullopt);
  EXPECT_EQ(validate_file(file, "hairstyle.extract"), std::nullopt);
  EXPECT_NO_THROW(require_schema(file, "hairstyle.extract"));
  EXPECT_NO_THROW(require_valid_output(file, "hairstyle.extract"));

  testing::write_extract_file(
      path("broken.h5"), [](File& broken) { write_string_attribute(broken, "/", "unit", "mm"); });
  const File broken = File::open_read_only(path("broken.h5"), "broken.h5");
  try {
    require_valid_output(broken, "hairstyle.extract");
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::runtime);
    EXPECT_EQ(error.exit_code(), 1);
    EXPECT_EQ(error.dataset(), "/@unit");
  }
}

/// A one-dataset schema for rules the schema above does not use.
Schema values_schema(const std::string& dataset_json) {
  return Schema::parse(R"({
    "name": "test.values", "version": 3, "description": "Test.",
    "history": [{"version": 3, "changes": "Third."}],
    "dimensions": {"n": "values", "n_targets": "targets"},
    "attributes": [],
    "datasets": [)" + dataset_json +
                           "]}",
                       "values.json");
}

class CustomSchemaTest : public testing::TemporaryDirectoryTest {
 protected:
  /// Writes `values` as /values in a test.values v3 file; returns the first violation.
  template <typename T>
  std::string violation_of(const Schema& schema, const std::vector<T>& values) {
    File file = File::create(path("values.h5"), "values.h5");
    write_schema_attributes(file, schema);
    write_vector(file, "/values", values);
    const std::optional<Error> violation = first_violation(file, schema);
    return violation ? violation->what() : "valid";
  }
};

TEST_F(CustomSchemaTest, AllowNoneAcceptsMinusOneOnly) {
  const Schema schema = values_schema(R"(
    {"path": "/values", "dtype": "int32", "shape": ["n"], "description": "Ids.",
     "constraints": {"index_into": "n", "allow_none": true}})");
  EXPECT_EQ(violation_of<int32_t>(schema, {-1, 0, 2}), "valid");
  EXPECT_EQ(violation_of<int32_t>(schema, {-1, -2, 2}),
            "values.h5:/values: expected indices into n (0 <= i < 3, or -1), found -2 at [1]");
  EXPECT_EQ(violation_of<int32_t>(schema, {0, 3, 2}),
            "values.h5:/values: expected indices into n (0 <= i < 3, or -1), found 3 at [1]");
}

TEST_F(CustomSchemaTest, OffsetsBindADimensionNoDatasetBinds) {
  const Schema schema = values_schema(R"(
    {"path": "/values", "dtype": "int64", "shape": ["n+1"], "description": "Offsets.",
     "constraints": {"csr_offsets_of": "n_targets"}})");
  EXPECT_EQ(violation_of<int64_t>(schema, {0, 4, 9}), "valid");
  EXPECT_EQ(violation_of<int64_t>(schema, {}),
            "values.h5:/values: expected shape [n+1], found [0] (n would be -1)");
}

TEST_F(CustomSchemaTest, NonFiniteValuesDeepInALargeChunkedArrayAreFound) {
  const Schema schema = values_schema(R"(
    {"path": "/values", "dtype": "float64", "shape": ["n"], "description": "Values.",
     "constraints": {"exclusive_min": -1}})");
  std::vector<double> values(3'000'000, 0.5);
  EXPECT_EQ(violation_of(schema, values), "valid");
  values[2'999'998] = std::numeric_limits<double>::infinity();
  EXPECT_EQ(violation_of(schema, values),
            "values.h5:/values: expected finite values, found inf at [2999998]");
  values[2'999'998] = -1;
  EXPECT_EQ(violation_of(schema, values),
            "values.h5:/values: expected values > -1, found -1 at [2999998]");
}

TEST_F(CustomSchemaTest, FiniteFalseAllowsNan) {
  const Schema schema = values_schema(R"(
    {"path": "/values", "dtype": "float32", "shape": ["n"], "description": "Values.",
     "constraints": {"finite": false, "max": 1}})");
  EXPECT_EQ(violation_of<float>(schema, {0.5f, std::numeric_limits<float>::quiet_NaN()}), "valid");
  EXPECT_EQ(violation_of<float>(schema, {0.5f, 2.0f}),
            "values.h5:/values: expected values <= 1, found 2 at [1]");
}

TEST_F(CustomSchemaTest, FixedExtentsAndOffsetDimensions) {
  const Schema schema = values_schema(R"(
    {"path": "/values", "dtype": "uint8", "shape": [4], "description": "Four values."})");
  EXPECT_EQ(violation_of<uint8_t>(schema, {1, 2, 3, 4}), "valid");
  EXPECT_EQ(violation_of<uint8_t>(schema, {1, 2, 3}),
            "values.h5:/values: expected shape [4], found [3]");
}

}  // namespace
}  // namespace hair::h5
