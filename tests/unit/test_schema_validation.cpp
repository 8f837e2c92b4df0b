#include <limits>

#include "hair/error.h"
#include "hair/h5/schema_validation.h"
#include "test_h5_support.h"
#include "test_schema_extract_fixture.h"

namespace hair::h5 {
namespace {

using testing::remove_object;
using testing::write_extract_file;

class SchemaValidationTest : public testing::TemporaryDirectoryTest {
 protected:
  /// The first violation of a hairstyle.extract file changed by `tamper`, or "valid".
  std::string violation_of(const std::function<void(File&)>& tamper) {
    write_extract_file(path("extract.h5"), tamper);
    const std::optional<std::string> violation =
        validate_file(File::open_read_only(path("extract.h5"), "extract.h5"));
    return violation.value_or("valid");
  }
};

TEST_F(SchemaValidationTest, TheFixtureConforms) {
  EXPECT_EQ(violation_of({}), "valid");
  write_extract_file(path("extract.h5"));
  const File file = File::open_read_only(path("extract.h5"));
  EXPECT_NO_THROW(require_schema(file, "hairstyle.extract"));
  EXPECT_NO_THROW(require_valid_output(file, "hairstyle.extract"));
}

TEST_F(SchemaValidationTest, OptionalDatasetMayBeAbsentButMustFitWhenPresent) {
  EXPECT_EQ(violation_of([](File& file) {
              write_dataset<float>(file, "/mesh/uv", std::vector<float>(16, 0.5f), {8, 2});
            }),
            "valid");
  EXPECT_EQ(violation_of([](File& file) {
              write_dataset<float>(file, "/mesh/uv", std::vector<float>(14, 0.5f), {7, 2});
            }),
            "extract.h5:/mesh/uv: expected shape [n_mesh_vertices, 2] = [8, 2] "
            "(n_mesh_vertices = 8 from /mesh/vertices), found [7, 2]");
}

TEST_F(SchemaValidationTest, WrongDtype) {
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/strands/points");
              write_dataset<double>(file, "/strands/points", std::vector<double>(21, 0.0), {7, 3});
            }),
            "extract.h5:/strands/points: expected float32, found float64");
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/strands/strand_attributes/group");
              write_vector<int64_t>(file, "/strands/strand_attributes/group", {0, 0, 1});
            }),
            "extract.h5:/strands/strand_attributes/group: expected int32, found int64");
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/groups/patch_kind");
              write_vector<int8_t>(file, "/groups/patch_kind", {0, 1});
            }),
            "extract.h5:/groups/patch_kind: expected enum {strip=0, grid=1, tube=2, cap=3, "
            "triangle_soup=4, fan=5}, found int8");
}

TEST_F(SchemaValidationTest, WrongShape) {
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/strands/points");
              write_dataset<float>(file, "/strands/points", std::vector<float>(28, 0.0f), {7, 4});
            }),
            "extract.h5:/strands/points: expected shape [n_points, 3] = [7, 3] "
            "(n_points = 7 from /strands/points), found [7, 4]");
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/body/scalp_triangle");
              write_dataset<uint8_t>(file, "/body/scalp_triangle", {1, 0}, {2, 1});
            }),
            "extract.h5:/body/scalp_triangle: expected shape [n_body_triangles] = [2] "
            "(n_body_triangles = 2 from /body/triangles), found [2, 1]");
}

TEST_F(SchemaValidationTest, DimensionsDisagree) {
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/strands/point_attributes/source_vertex");
              write_vector<int32_t>(file, "/strands/point_attributes/source_vertex", {0, 1, 2});
            }),
            "extract.h5:/strands/point_attributes/source_vertex: expected shape [n_points] = [7] "
            "(n_points = 7 from /strands/points), found [3]");
  // n_strands+1: offsets bind n_strands = 3, so the group column must have 3 entries.
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/strands/strand_attributes/rail");
              write_vector<int32_t>(file, "/strands/strand_attributes/rail", {0, 1, 0, 2});
            }),
            "extract.h5:/strands/strand_attributes/rail: expected shape [n_strands] = [3] "
            "(n_strands = 3 from /strands/offsets), found [4]");
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/groups/first_strand");
              write_vector<int32_t>(file, "/groups/first_strand", {0, 3});
            }),
            "extract.h5:/groups/first_strand: expected shape [n_groups+1] = [3] "
            "(n_groups = 2 from /groups/patch_kind), found [2]");
}

TEST_F(SchemaValidationTest, NonFiniteValue) {
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/strands/points");
              std::vector<float> points(21, 0.0f);
              points[5] = std::numeric_limits<float>::quiet_NaN();
              write_dataset<float>(file, "/strands/points", points, {7, 3});
            }),
            "extract.h5:/strands/points: expected finite values, found nan at [1, 2]");
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/groups/orientation_confidence");
              write_vector<float>(file, "/groups/orientation_confidence",
                                  {1.0f, -std::numeric_limits<float>::infinity()});
            }),
            "extract.h5:/groups/orientation_confidence: expected finite values, found -inf at [1]");
}

TEST_F(SchemaValidationTest, ValueOutOfRange) {
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/body/scalp_triangle");
              write_vector<uint8_t>(file, "/body/scalp_triangle", {1, 2});
            }),
            "extract.h5:/body/scalp_triangle: expected values <= 1, found 2 at [1]");
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/groups/orientation_confidence");
              write_vector<float>(file, "/groups/orientation_confidence", {1.5f, 0.5f});
            }),
            "extract.h5:/groups/orientation_confidence: expected values <= 1, found 1.5 at [0]");
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/strands/strand_attributes/rail");
              write_vector<int32_t>(file, "/strands/strand_attributes/rail", {0, -1, 0});
            }),
            "extract.h5:/strands/strand_attributes/rail: expected values >= 0, found -1 at [1]");
}

TEST_F(SchemaValidationTest, BadCsrOffsets) {
  const auto with_offsets = [&](std::vector<int64_t> offsets) {
    return violation_of([&](File& file) {
      remove_object(file, "/strands/offsets");
      write_vector<int64_t>(file, "/strands/offsets", offsets);
    });
  };
  EXPECT_EQ(with_offsets({1, 2, 5, 7}),
            "extract.h5:/strands/offsets: expected CSR offsets starting at 0, found 1");
  EXPECT_EQ(with_offsets({0, 5, 2, 7}),
            "extract.h5:/strands/offsets: expected non-decreasing CSR offsets, found 2 after 5 "
            "at [2]");
  EXPECT_EQ(with_offsets({0, 2, 5, 6}),
            "extract.h5:/strands/offsets: expected CSR offsets ending at n_points = 7 "
            "(from /strands/points), found 6");
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/groups/first_strand");
              write_vector<int32_t>(file, "/groups/first_strand", {0, 2, 4});
            }),
            "extract.h5:/groups/first_strand: expected CSR offsets ending at n_strands = 3 "
            "(from /strands/offsets), found 4");
}

TEST_F(SchemaValidationTest, IndexOutOfRange) {
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/strands/strand_attributes/group");
              write_vector<int32_t>(file, "/strands/strand_attributes/group", {0, 0, 2});
            }),
            "extract.h5:/strands/strand_attributes/group: expected indices into n_groups "
            "(0 <= i < 2), found 2 at [2]");
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/body/triangles");
              write_dataset<int32_t>(file, "/body/triangles", {0, 1, 2, 0, -1, 3}, {2, 3});
            }),
            "extract.h5:/body/triangles: expected indices into n_body_vertices (0 <= i < 4), "
            "found -1 at [1, 1]");
}

TEST_F(SchemaValidationTest, EnumMembersAndValues) {
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/groups/orientation_rule");
              write_enum_dataset(file, "/groups/orientation_rule", {0, 1},
                                 {{"vertex_order", 0}, {"scalp_distance", 1}, {"uv", 2}});
            }),
            "extract.h5:/groups/orientation_rule: enum member 'height' missing");
  EXPECT_EQ(violation_of([](File& file) {
              // A value outside the members, as a careless writer could store it.
              remove_object(file, "/groups/patch_kind");
              const hid_t type = H5Tenum_create(H5T_STD_I8LE);
              for (const EnumMember& member :
                   Schema::find("hairstyle.extract").dataset("/groups/patch_kind").enum_members) {
                H5Tenum_insert(type, member.name.c_str(), &member.value);
              }
              const std::vector<int8_t> values = {1, 9};
              write_raw_dataset(file, "/groups/patch_kind", type, type, values.data(), {2}, {});
              H5Tclose(type);
            }),
            "extract.h5:/groups/patch_kind: expected a member of {strip=0, grid=1, tube=2, cap=3, "
            "triangle_soup=4, fan=5}, found value 9 at [1]");
}

TEST_F(SchemaValidationTest, MissingRequiredDataset) {
  EXPECT_EQ(violation_of([](File& file) { remove_object(file, "/body/triangles"); }),
            "extract.h5:/body/triangles: missing required dataset");
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/mesh/face_group");
              file.create_group("/mesh/face_group");
            }),
            "extract.h5:/mesh/face_group: expected a dataset, found a group");
}

TEST_F(SchemaValidationTest, RootAttributes) {
  EXPECT_EQ(violation_of([](File& file) { write_string_attribute(file, "/", "unit", "cm"); }),
            "extract.h5:/@unit: expected \"m\", found \"cm\"");
  EXPECT_EQ(violation_of([](File& file) { write_double_attribute(file, "/", "head_height_m", 0); }),
            "extract.h5:/@head_height_m: expected a value > 0, found 0");
  EXPECT_EQ(violation_of([](File& file) {
              write_double_attribute(file, "/", "neck_y_m",
                                     std::numeric_limits<double>::quiet_NaN());
            }),
            "extract.h5:/@neck_y_m: expected a finite value, found nan");
  EXPECT_EQ(violation_of([](File& file) { write_int64_attribute(file, "/", "unit_scale", 1); }),
            "extract.h5:/@unit_scale: expected float64, found int64");
  EXPECT_EQ(violation_of([](File& file) {
              write_string_attribute(file, "/", "parameters", "min_points = 2");
            }),
            "extract.h5:/@parameters: expected JSON text, found \"min_points = 2\"");
  EXPECT_EQ(violation_of([](File& file) { H5Adelete(file.id(), "up_axis"); }),
            "extract.h5:/@up_axis: missing root attribute");
  // Reproducible runs leave out the optional wall time and date.
  EXPECT_EQ(violation_of([](File& file) {
              H5Adelete(file.id(), "wall_time_s");
              H5Adelete(file.id(), "created_utc");
            }),
            "valid");
}

TEST_F(SchemaValidationTest, SchemaNameAndVersion) {
  EXPECT_EQ(violation_of([](File& file) { write_int64_attribute(file, "/", "schema_version", 0); }),
            "extract.h5:/@schema_version: schema version 0 is older than supported 1; no upgrade "
            "path");
  EXPECT_EQ(violation_of([](File& file) { write_int64_attribute(file, "/", "schema_version", 2); }),
            "extract.h5:/@schema_version: schema version 2 is newer than supported 1; use a newer "
            "hairstyle");
  EXPECT_EQ(violation_of(
                [](File& file) { write_string_attribute(file, "/", "schema", "hairstyle.nope"); }),
            "extract.h5:/@schema: unknown schema 'hairstyle.nope' (known: hairstyle.extract)");
  EXPECT_EQ(violation_of([](File& file) { H5Adelete(file.id(), "schema"); }),
            "extract.h5:/@schema: missing root attribute: not a hairstyle intermediate file");
  EXPECT_EQ(
      violation_of([](File& file) { write_string_attribute(file, "/", "schema_version", "1"); }),
      "extract.h5:/@schema_version: expected int64, found string");
}

TEST_F(SchemaValidationTest, TheFirstViolationIsReported) {
  // Attributes come before layouts, layouts before values.
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/strands/strand_attributes/group");
              write_vector<int32_t>(file, "/strands/strand_attributes/group", {0, 0, 7});
              remove_object(file, "/body/vertices");
              write_string_attribute(file, "/", "up_axis", "+Z");
            }),
            "extract.h5:/@up_axis: expected \"+Y\", found \"+Z\"");
  EXPECT_EQ(violation_of([](File& file) {
              remove_object(file, "/strands/strand_attributes/group");
              write_vector<int32_t>(file, "/strands/strand_attributes/group", {0, 0, 7});
              remove_object(file, "/body/vertices");
            }),
            "extract.h5:/body/vertices: missing required dataset");
}

TEST_F(SchemaValidationTest, RequireSchemaThrowsBadInputAndOutputCheckThrowsRuntime) {
  write_extract_file(path("extract.h5"),
                     [](File& file) { write_string_attribute(file, "/", "unit", "mm"); });
  const File file = File::open_read_only(path("extract.h5"), "extract.h5");
  try {
    require_schema(file, "hairstyle.extract");
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::bad_input);
    EXPECT_EQ(error.exit_code(), 2);
    EXPECT_EQ(error.dataset(), "/@unit");
  }
  try {
    require_valid_output(file, "hairstyle.extract");
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::runtime);
    EXPECT_EQ(error.exit_code(), 1);
  }
  write_extract_file(path("other.h5"), [](File& other) {
    write_string_attribute(other, "/", "schema", "hairstyle.types");
  });
  try {
    require_schema(File::open_read_only(path("other.h5"), "other.h5"), "hairstyle.extract");
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_STREQ(error.what(),
                 "other.h5:/@schema: expected hairstyle.extract, found hairstyle.types");
  }
  EXPECT_THROW(require_schema(file, "hairstyle.unknown"), Error);
}

/// A one-dataset schema for rules the extract schema does not use.
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
