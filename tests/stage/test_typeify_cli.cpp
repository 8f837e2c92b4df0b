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

// The rooted-on-the-scalp rule, off by default: on braid01 it turns the braid strips that
// start at the nape, under the cap's ends, into roots (docs/typeify.md), and nothing else.
TEST(TypeifyCli, TheRootedRuleTurnsStripsStartingOnTheScalpIntoRoots) {
  TemporaryDirectory directory("typeify_rooted");
  fs::path extract = extract_braid(directory);
  const auto types_with = [&](const std::vector<std::string>& extra) {
    fs::path types = directory / ("types" + std::to_string(extra.size()) + ".h5");
    std::vector<std::string> arguments = {extract.string(), "-o", types.string(), "--quiet"};
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    auto result = run_command(kBin / "typeify", arguments);
    EXPECT_EQ(result.exit_code, 0) << result.err;
    hair::h5::File file = hair::h5::File::open_read_only(types);
    return hair::h5::read_enum_dataset(file, "/groups/type", hair::group_type_members());
  };
  std::vector<int8_t> paper = types_with({});
  std::vector<int8_t> rooted = types_with({"--root_scalp_distance_h", "0.05"});
  ASSERT_EQ(paper.size(), rooted.size());
  const auto is_root = [](int8_t type) {
    return type == static_cast<int8_t>(hair::GroupType::root_free) ||
           type == static_cast<int8_t>(hair::GroupType::root_connected);
  };
  int became_roots = 0, other_changes = 0;
  for (size_t g = 0; g < paper.size(); ++g) {
    if (paper[g] == rooted[g]) continue;
    bool middle_to_root =
        paper[g] == static_cast<int8_t>(hair::GroupType::middle) && is_root(rooted[g]);
    became_roots += middle_to_root ? 1 : 0;
    // A root may change between free and connected (the angle threshold moves).
    other_changes += !middle_to_root && !(is_root(paper[g]) && is_root(rooted[g]));
  }
  EXPECT_EQ(became_roots, 4);
  EXPECT_EQ(other_changes, 0);
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
      {{extract.string(), "--root_scalp_distance_h", "-0.1"}, "root_scalp_distance_h"},
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
