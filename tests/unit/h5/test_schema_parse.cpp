#include <gtest/gtest.h>

#include "hair/core/error.h"
#include "hair/h5/embedded_schemas.h"
#include "hair/h5/schema.h"
#include "hair/h5/schema_text.h"

namespace hair::h5 {
namespace {

/// A valid schema with one dataset whose JSON the test chooses.
std::string schema_json(const std::string& dataset_json, const std::string& extra = "") {
  return R"({"name": "test.parse", "version": 2, "description": "Test.",
    "history": [{"version": 1, "changes": "First."}, {"version": 2, "changes": "Second."}],
    "dimensions": {"n": "things", "m": "others"},
    "attributes": [{"name": "unit", "dtype": "string", "equals": "m", "description": "Unit."}],
    "datasets": [)" +
         dataset_json + "]" + extra + "}";
}

/// The reason Schema::parse gives for `json`, or "parsed".
std::string parse_error(const std::string& json) {
  try {
    Schema::parse(json, "test.json");
    return "parsed";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::runtime);
    EXPECT_EQ(error.file(), "test.json");
    return error.reason();
  }
}

TEST(SchemaParse, ReadsEveryField) {
  const Schema schema =
      Schema::parse(schema_json(R"({"path": "/a/offsets", "dtype": "int64", "shape": ["n+1"],
          "description": "Offsets.", "constraints": {"csr_offsets_of": "m"}},
        {"path": "/a/kind", "dtype": "enum", "enum": {"strip": 0, "fan": 5},
          "shape": ["n"], "description": "Kinds.", "required": false},
        {"path": "/a/x", "dtype": "float32", "shape": ["n", 3, "m-1"], "unit": "m",
          "description": "X.", "constraints": {"min": -1, "exclusive_max": 2.5}})"),
                    "test.json");
  EXPECT_EQ(schema.name, "test.parse");
  EXPECT_EQ(schema.version, 2);
  ASSERT_EQ(schema.history.size(), 2u);
  EXPECT_EQ(schema.history[1].changes, "Second.");
  ASSERT_EQ(schema.dimensions.size(), 2u);
  EXPECT_EQ(schema.dimensions[0].first, "n");  // declared order is kept
  ASSERT_EQ(schema.attributes.size(), 1u);
  EXPECT_EQ(std::get<std::string>(*schema.attributes[0].equals), "m");
  ASSERT_EQ(schema.datasets.size(), 3u);

  const DatasetSpec& offsets = schema.dataset("/a/offsets");
  EXPECT_EQ(offsets.dtype, Dtype::int64);
  EXPECT_EQ(offsets.shape_text(), "[n+1]");
  EXPECT_EQ(offsets.constraints.csr_offsets_of, "m");
  EXPECT_TRUE(offsets.required);

  const DatasetSpec& kind = schema.dataset("/a/kind");
  EXPECT_TRUE(kind.is_enum());
  EXPECT_EQ(kind.enum_members, (EnumMembers{{"strip", 0}, {"fan", 5}}));
  EXPECT_FALSE(kind.required);
  EXPECT_EQ(kind.dtype_text(), "enum {strip=0, fan=5}");

  const DatasetSpec& x = schema.dataset("/a/x");
  EXPECT_EQ(x.shape_text(), "[n, 3, m-1]");
  EXPECT_EQ(x.shape[2].offset, -1);
  EXPECT_EQ(x.unit, "m");
  EXPECT_TRUE(x.constraints.finite);  // default for floats
  EXPECT_EQ(x.constraints.min, -1.0);
  EXPECT_EQ(x.constraints.exclusive_max, 2.5);
  EXPECT_FALSE(x.constraints.max.has_value());
  EXPECT_THROW(schema.dataset("/a/none"), Error);
}

TEST(SchemaParse, RejectsMistakesNamingWhere) {
  const std::string plain =
      R"({"path": "/x", "dtype": "float32", "shape": ["n"], "description": "X."})";
  EXPECT_EQ(parse_error(schema_json(plain)), "parsed");
  EXPECT_EQ(parse_error("{"), parse_error("{"));  // stable message
  EXPECT_NE(parse_error("{").find("not valid JSON"), std::string::npos);
  EXPECT_EQ(parse_error(schema_json(plain, R"(, "extra": 1)")), "unknown key 'extra'");
  EXPECT_EQ(
      parse_error(schema_json(
          R"({"path": "/x", "dtype": "float32", "shape": ["n"], "description": "X.", "constrains": {}})")),
      "datasets[0] (/x): unknown key 'constrains'");
  EXPECT_EQ(parse_error(schema_json(
                R"({"path": "/x", "dtype": "float16", "shape": ["n"], "description": "X."})")),
            "datasets[0] (/x): unknown dtype 'float16'");
  EXPECT_EQ(parse_error(schema_json(
                R"({"path": "/x", "dtype": "float32", "shape": ["k"], "description": "X."})")),
            "datasets[0] (/x): undeclared dimension 'k'");
  EXPECT_EQ(parse_error(schema_json(
                R"({"path": "/x", "dtype": "float32", "shape": ["n*2"], "description": "X."})")),
            "datasets[0] (/x): bad shape entry n*2 (expected a size, a dimension or dimension+k)");
  EXPECT_EQ(parse_error(schema_json(
                R"({"path": "/x", "dtype": "int32", "shape": ["n"], "description": "X.",
                    "constraints": {"finite": true}})")),
            "datasets[0] (/x) constraints: 'finite' applies to float datasets only");
  EXPECT_EQ(parse_error(schema_json(
                R"({"path": "/x", "dtype": "float32", "shape": ["n"], "description": "X.",
                    "constraints": {"index_into": "n"}})")),
            "datasets[0] (/x) constraints: 'csr_offsets_of' and 'index_into' apply to integer "
            "datasets only");
  EXPECT_EQ(parse_error(schema_json(
                R"({"path": "/x", "dtype": "int32", "shape": ["n"], "description": "X.",
                    "constraints": {"allow_none": true}})")),
            "datasets[0] (/x) constraints: 'allow_none' needs 'index_into'");
  EXPECT_EQ(
      parse_error(schema_json(
          R"({"path": "/x", "dtype": "enum", "enum": {"a": 300}, "shape": ["n"], "description": "X."})")),
      "datasets[0] (/x): enum value of 'a' must be an int8");
  EXPECT_EQ(parse_error(schema_json(plain + "," + plain)), "datasets: path /x appears twice");
  EXPECT_EQ(parse_error(schema_json(
                R"({"path": "x", "dtype": "float32", "shape": ["n"], "description": "X."})")),
            "datasets[0] (x): path must be absolute");
  EXPECT_EQ(parse_error(R"({"name": "t", "version": 2, "description": "T.",
      "history": [{"version": 1, "changes": "First."}], "dimensions": {},
      "attributes": [], "datasets": []})"),
            "history: no entry for version 2");
  EXPECT_EQ(parse_error(R"({"name": "t", "version": "1", "description": "T.",
      "history": [], "dimensions": {}, "attributes": [], "datasets": []})"),
            "'version' must be an integer");
  EXPECT_EQ(parse_error(R"({"name": "t", "version": 1, "description": "T.",
      "history": [{"version": 1, "changes": "First."}], "dimensions": {},
      "attributes": [{"name": "schema_version", "dtype": "int64", "description": "V."}],
      "datasets": []})"),
            "attributes[0] (schema_version): every file carries this attribute; do not list it");
  EXPECT_EQ(parse_error(R"({"name": "t", "version": 1, "description": "T.",
      "history": [{"version": 1, "changes": "First."}], "dimensions": {},
      "attributes": [{"name": "unit", "dtype": "string", "equals": 1, "description": "U."}],
      "datasets": []})"),
            "attributes[0] (unit): 'equals' must be a value of the attribute's dtype");
}

TEST(SchemaParse, DimensionExpressionText) {
  EXPECT_EQ((DimensionExpression{"", 3}.text()), "3");
  EXPECT_EQ((DimensionExpression{"n", 0}.text()), "n");
  EXPECT_EQ((DimensionExpression{"n", 1}.text()), "n+1");
  EXPECT_EQ((DimensionExpression{"n", -2}.text()), "n-2");
}

TEST(SchemaRegistry, EveryEmbeddedSchemaParsesAndIsFoundByName) {
  ASSERT_FALSE(embedded_schemas().empty());
  EXPECT_EQ(Schema::all().size(), embedded_schemas().size());
  for (const Schema& schema : Schema::all()) {
    EXPECT_EQ(&Schema::find(schema.name), &schema);
    EXPECT_GE(schema.version, 1);
  }
  try {
    Schema::find("hairstyle.nope");
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::usage);
    EXPECT_NE(error.reason().find("hairstyle.extract"), std::string::npos);
  }
}

TEST(SchemaRegistry, ExtractSchemaHasTheContractedDatasets) {
  const Schema& schema = Schema::find("hairstyle.extract");
  EXPECT_EQ(schema.version, 3);
  EXPECT_EQ(schema.dataset("/strands/points").shape_text(), "[n_points, 3]");
  EXPECT_EQ(schema.dataset("/strands/points").unit, "m");
  EXPECT_EQ(schema.dataset("/strands/offsets").constraints.csr_offsets_of, "n_points");
  EXPECT_EQ(schema.dataset("/groups/first_strand").shape_text(), "[n_groups+1]");
  EXPECT_EQ(schema.dataset("/groups/first_strand").constraints.csr_offsets_of, "n_strands");
  EXPECT_TRUE(schema.dataset("/groups/patch_kind").is_enum());
  EXPECT_TRUE(schema.dataset("/groups/orientation_rule").is_enum());
  EXPECT_EQ(schema.dataset("/body/scalp_triangle").constraints.max, 1.0);
  EXPECT_EQ(schema.dataset("/mesh/face_flow").shape_text(), "[n_faces, 3]");
  EXPECT_EQ(schema.dataset("/mesh/face_flow_coherence").constraints.max, 1.0);
}

TEST(SchemaText, NamesEverythingAReaderNeeds) {
  const Schema schema =
      Schema::parse(schema_json(R"({"path": "/a/offsets", "dtype": "int64", "shape": ["n+1"],
          "description": "Offsets of m.", "constraints": {"csr_offsets_of": "m"}},
        {"path": "/a/ids", "dtype": "int32", "shape": ["n"], "description": "Ids.",
          "constraints": {"index_into": "m", "allow_none": true}},
        {"path": "/a/kind", "dtype": "enum", "enum": {"strip": 0, "fan": 5},
          "shape": ["n"], "description": "Kinds."},
        {"path": "/a/x", "dtype": "float32", "shape": ["n", 2], "unit": "m", "required": false,
          "description": "X.", "constraints": {"exclusive_min": 0}})"),
                    "test.json");
  const std::string text = format_schema(schema);
  EXPECT_EQ(text.rfind("test.parse v2\n  Test.\n", 0), 0u) << text;
  for (const char* expected :
       {"  v1  First.\n  v2  Second.\n", "  n  things\n", "schema (string) = \"test.parse\"",
        "schema_version (int64) = 2", "unit (string)  = \"m\"\n      Unit.",
        "/a/offsets  int64 [n+1]  CSR offsets of m\n      Offsets of m.",
        "/a/ids  int32 [n]  indices into m or -1", "/a/kind  enum {strip=0, fan=5} [n]\n",
        "/a/x  float32 [n, 2]  finite, > 0, unit m, optional\n      X."}) {
    EXPECT_NE(text.find(expected), std::string::npos) << expected << "\n" << text;
  }
  EXPECT_EQ(format_schema(Schema::find("hairstyle.extract")).rfind("hairstyle.extract v3\n", 0),
            0u);
}

}  // namespace
}  // namespace hair::h5
