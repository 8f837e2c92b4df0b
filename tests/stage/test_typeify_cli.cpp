// typeify as a subprocess: on a sample after extract, and on bad input (exit 2, one
// line, nothing written).
#include <gtest/gtest.h>

#include <filesystem>

#include "hair/cluster/typeify_io.h"
#include "hair/h5/enum_dataset.h"
#include "hair/h5/file.h"
#include "support/run_command.h"

namespace {

namespace fs = std::filesystem;
using hair::test::run_command;
using hair::test::TemporaryDirectory;
using hair::test::text_lines;

const fs::path kBin = fs::path(HAIR_BIN_DIR);
const fs::path kSamples = fs::path(HAIR_SOURCE_DIR) / "data" / "samples";

/// extract.h5 of the braid01 sample in `directory`.
fs::path extract_braid(const TemporaryDirectory& directory) {
  fs::path out = directory / "extract.h5";
  auto result =
      run_command(kBin / "extract", {(kSamples / "hair" / "braid01.obj").string(), "--body",
                                     (kSamples / "body.obj").string(), "--unit_scale", "0.1", "-o",
                                     out.string(), "--quiet"});
  EXPECT_EQ(result.exit_code, 0) << result.err;
  return out;
}

TEST(TypeifyCli, TypesEveryGroupOfTheBraidSample) {
  TemporaryDirectory directory("typeify_braid");
  fs::path extract = extract_braid(directory);
  fs::path types = directory / "types.h5";
  auto result = run_command(kBin / "typeify", {extract.string(), "-o", types.string(), "--quiet"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(run_command(kBin / "hair-inspect", {types.string()}).exit_code, 0);
  hair::h5::File file = hair::h5::File::open_read_only(types);
  std::vector<int8_t> type =
      hair::h5::read_enum_dataset(file, "/groups/type", hair::group_type_members());
  EXPECT_EQ(type.size(), 87u);
  // A braid of disjoint pieces has middle pieces (section 4.1).
  EXPECT_GT(std::count(type.begin(), type.end(), static_cast<int8_t>(hair::GroupType::middle)), 10);
}

TEST(TypeifyCli, WrongInputsFailCleanly) {
  TemporaryDirectory directory("typeify_bad");
  fs::path extract = extract_braid(directory);
  fs::path types = directory / "types.h5";
  ASSERT_EQ(
      run_command(kBin / "typeify", {extract.string(), "-o", types.string(), "--quiet"}).exit_code,
      0);
  hair::test::write_text_file(directory / "text.h5", "not HDF5\n");
  struct Case {
    std::vector<std::string> arguments;
    std::string expected;
  };
  std::vector<Case> cases = {
      {{(directory / "missing.h5").string()}, "missing.h5"},
      {{(directory / "text.h5").string()}, "text.h5"},
      {{types.string()}, "hairstyle.extract"},  // a types.h5 is not an extract.h5
      {{extract.string(), "--neighbour_distance_h", "-1"}, "neighbour_distance_h"},
  };
  for (const Case& bad : cases) {
    std::vector<std::string> arguments = bad.arguments;
    arguments.insert(arguments.end(), {"-o", (directory / "out.h5").string()});
    auto result = run_command(kBin / "typeify", arguments);
    EXPECT_EQ(result.exit_code, 2) << bad.expected << ": " << result.err;
    ASSERT_EQ(text_lines(result.err).size(), 1u) << result.err;
    EXPECT_NE(result.err.find(bad.expected), std::string::npos) << result.err;
    EXPECT_FALSE(fs::exists(directory / "out.h5"));
  }
}

}  // namespace
