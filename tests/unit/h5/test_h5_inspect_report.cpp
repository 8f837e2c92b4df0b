#include "hair/core/error.h"
#include "hair/h5/inspect_report.h"
#include "unit/test_h5_support.h"
#include "unit/test_schema_extract_fixture.h"

namespace hair::h5 {
namespace {

using H5InspectReportTest = testing::TemporaryDirectoryTest;

TEST_F(H5InspectReportTest, ConformingFileEndsWithValid) {
  testing::write_extract_file(path("extract.h5"));
  const InspectReport report =
      inspect_report(File::open_read_only(path("extract.h5"), "extract.h5"), true);
  EXPECT_FALSE(report.violation.has_value());
  for (const char* expected :
       {"/strands/points",
        "float32 [7, 3]  chunked [7, 3] fletcher32  range [0, 1.7]  by column [0, 0.2] [1.5, 1.7] [0, 0]",
        "/groups/patch_kind", "strip 1, grid 1", "\nprovenance\n", "stage            extract",
        "\"min_points\": 2"}) {
    EXPECT_NE(report.text.find(expected), std::string::npos) << expected << "\n" << report.text;
  }
  EXPECT_TRUE(report.text.ends_with("\nvalid: hairstyle.extract v3\n")) << report.text;
}

TEST_F(H5InspectReportTest, ViolationIsTheLastLine) {
  testing::write_extract_file(
      path("extract.h5"), [](File& file) { testing::remove_object(file, "/body/scalp_triangle"); });
  const File file = File::open_read_only(path("extract.h5"), "extract.h5");
  const InspectReport report = inspect_report(file, true);
  ASSERT_TRUE(report.violation.has_value());
  EXPECT_EQ(*report.violation, "extract.h5:/body/scalp_triangle: missing required dataset");
  EXPECT_TRUE(report.text.ends_with("\ninvalid: " + *report.violation + "\n")) << report.text;

  const InspectReport unchecked = inspect_report(file, false);
  EXPECT_FALSE(unchecked.violation.has_value());
  EXPECT_EQ(unchecked.text.find("valid"), std::string::npos);
}

TEST_F(H5InspectReportTest, NamedSchemaMustBeTheFilesAndKnown) {
  File file = File::create(path("plain.h5"), "plain.h5");
  write_string_attribute(file, "/", "schema", "hairstyle.other");
  const InspectReport report = inspect_report(file, true, "hairstyle.extract");
  ASSERT_TRUE(report.violation.has_value());
  EXPECT_EQ(*report.violation,
            "plain.h5:/@schema: expected hairstyle.extract, found hairstyle.other");
  EXPECT_THROW(inspect_report(file, true, "hairstyle.nope"), Error);
  const InspectReport by_file = inspect_report(file, true);
  // The known schemas are listed in name order; the list grows with schemas/.
  const std::string expected_start =
      "plain.h5:/@schema: unknown schema 'hairstyle.other' (known: hairstyle.";
  EXPECT_EQ(by_file.violation->substr(0, expected_start.size()), expected_start);
  EXPECT_NE(by_file.violation->find("hairstyle.extract"), std::string::npos);
  EXPECT_EQ(by_file.violation->back(), ')');
}

}  // namespace
}  // namespace hair::h5
