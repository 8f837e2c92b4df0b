// cluster-middle and cluster-all as subprocesses: on the braid sample after extract
// and typeify, on a model without middle groups (cluster-middle skips), determinism,
// and bad input (exit 2, one line, nothing written).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <tuple>

#include "hair/cluster/clustering_io.h"
#include "hair/core/strand_set.h"
#include "hair/h5/attribute.h"
#include "hair/h5/dataset.h"
#include "hair/h5/file.h"
#include "stage/clean_failures.h"
#include "support/run_command.h"

namespace {

namespace fs = std::filesystem;
using hair::Points3f;
using hair::test::run_command;
using hair::test::TemporaryDirectory;
using hair::test::text_lines;

const fs::path kBin = fs::path(HAIR_BIN_DIR);
const fs::path kSamples = fs::path(HAIR_SOURCE_DIR) / "data" / "samples";

/// Runs a stage and expects it to succeed.
void run_stage(const std::string& stage, std::vector<std::string> arguments) {
  arguments.insert(arguments.end(), {"--quiet", "--reproducible"});
  auto result = run_command(kBin / stage, arguments);
  ASSERT_EQ(result.exit_code, 0) << stage << ": " << result.err;
}

/// extract.h5, types.h5, middle.h5 and clusters.h5 of a mesh in `directory`.
struct Outputs {
  fs::path extract, types, middle, clusters;
};

Outputs run_pipeline(const TemporaryDirectory& directory, const fs::path& mesh,
                     const std::string& subfolder = "") {
  fs::path folder = directory / subfolder;
  fs::create_directories(folder);
  Outputs out{folder / "extract.h5", folder / "types.h5", folder / "middle.h5",
              folder / "clusters.h5"};
  run_stage("extract", {mesh.string(), "--body", (kSamples / "body.obj").string(), "--unit_scale",
                        "0.1", "-o", out.extract.string()});
  run_stage("typeify", {out.extract.string(), "-o", out.types.string()});
  run_stage("cluster-middle", {out.types.string(), "-o", out.middle.string()});
  run_stage("cluster-all", {out.types.string(), out.middle.string(), "-o", out.clusters.string()});
  return out;
}

std::string file_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(ClusterCli, ClustersTheBraidSample) {
  TemporaryDirectory directory("cluster_braid");
  Outputs out = run_pipeline(directory, kSamples / "hair" / "braid01.obj");
  for (const fs::path& file : {out.middle, out.clusters})
    EXPECT_EQ(run_command(kBin / "hair-inspect", {file.string()}).exit_code, 0) << file;

  hair::h5::File middle = hair::h5::File::open_read_only(out.middle);
  std::vector<int32_t> middle_cluster = hair::read_middle_clusters(middle, 87);
  int64_t middle_count = hair::h5::read_int64_attribute(middle, "/", "cluster_count");
  EXPECT_GE(middle_count, 2);  // the braid's pieces do not all connect into one
  EXPECT_EQ(hair::h5::read_string_attribute(middle, "/", "cluster_count_source"), "eigengap");

  hair::GroupClusters clusters =
      hair::read_group_clusters(hair::h5::File::open_read_only(out.clusters));
  ASSERT_EQ(clusters.cluster.size(), 87u);
  // The groups of one middle cluster stay together in the final clustering.
  for (size_t g = 0; g < 87; ++g) {
    for (size_t h = 0; h < 87; ++h) {
      if (middle_cluster[g] >= 0 && middle_cluster[g] == middle_cluster[h]) {
        EXPECT_EQ(clusters.cluster_before_split[g], clusters.cluster_before_split[h]);
      }
    }
  }
  // The cap (root-type groups) is apart from the braid after the division.
  EXPECT_NE(std::count(clusters.starts_at_root.begin(), clusters.starts_at_root.end(), 1), 0);
  EXPECT_NE(std::count(clusters.starts_at_root.begin(), clusters.starts_at_root.end(), 0), 0);

  // Determinism: a second run on the same input writes the same bytes.
  for (const auto& [stage, output, arguments] :
       std::vector<std::tuple<std::string, fs::path, std::vector<std::string>>>{
           {"cluster-middle", out.middle, {out.types.string()}},
           {"cluster-all", out.clusters, {out.types.string(), out.middle.string()}}}) {
    fs::path again = directory / ("again_" + output.filename().string());
    std::vector<std::string> rerun = arguments;
    rerun.insert(rerun.end(), {"-o", again.string()});
    run_stage(stage, rerun);
    EXPECT_TRUE(file_bytes(output) == file_bytes(again)) << stage << " is not deterministic";
  }
}

TEST(ClusterCli, NoMiddleGroupsIsAnEmptyMiddleClustering) {
  // short02 is one patch: one root group, no middle groups.
  fs::path mesh = fs::path(HAIR_SHARED_DATA_DIR) / "makehuman" / "hair" / "short02.obj";
  if (!fs::exists(mesh)) GTEST_SKIP() << mesh << " not found";
  TemporaryDirectory directory("cluster_short02");
  Outputs out = run_pipeline(directory, mesh);
  hair::h5::File middle = hair::h5::File::open_read_only(out.middle);
  EXPECT_EQ(hair::h5::read_string_attribute(middle, "/", "cluster_count_source"), "skipped");
  EXPECT_EQ(hair::h5::read_int64_attribute(middle, "/", "cluster_count"), 0);
  hair::GroupClusters clusters =
      hair::read_group_clusters(hair::h5::File::open_read_only(out.clusters));
  EXPECT_EQ(clusters.cluster, std::vector<int32_t>{0});
}

TEST(ClusterCli, WrongInputsFailCleanly) {
  TemporaryDirectory directory("cluster_bad");
  Outputs out = run_pipeline(directory, kSamples / "hair" / "braid01.obj");
  Outputs other = run_pipeline(directory, kSamples / "hair" / "ponytail01.obj", "ponytail");
  hair::test::write_text_file(directory / "text.h5", "not HDF5\n");
  struct Case {
    std::string stage;
    std::vector<std::string> arguments;
    std::string expected;
  };
  std::vector<Case> cases = {
      {"cluster-middle", {(directory / "missing.h5").string()}, "missing.h5"},
      {"cluster-middle", {(directory / "text.h5").string()}, "text.h5"},
      {"cluster-middle", {out.extract.string()}, "hairstyle.types"},
      {"cluster-middle",
       {hair::test::copy_with_nan(out.types, directory / "nan_types.h5", "/centre_strands/points")
            .string()},
       "expected finite values"},
      {"cluster-middle", {out.types.string(), "--k1", "0.5"}, "k1 + k2 + k3"},
      {"cluster-middle", {out.types.string(), "--f3_max", "2"}, "f3_max"},
      {"cluster-all", {out.types.string(), out.types.string()}, "hairstyle.middle"},
      {"cluster-all", {out.middle.string(), out.middle.string()}, "hairstyle.types"},
      {"cluster-all", {out.types.string(), other.middle.string()}, "another model"},
      {"cluster-all", {out.types.string()}, "MIDDLE_H5"},
  };
  for (const Case& bad : cases) {
    std::vector<std::string> arguments = bad.arguments;
    arguments.insert(arguments.end(), {"-o", (directory / "out.h5").string()});
    auto result = run_command(kBin / bad.stage, arguments);
    EXPECT_EQ(result.exit_code, 2) << bad.expected << ": " << result.err;
    ASSERT_EQ(text_lines(result.err).size(), 1u) << result.err;
    EXPECT_NE(result.err.find(bad.expected), std::string::npos) << result.err;
    EXPECT_FALSE(fs::exists(directory / "out.h5"));
  }
}

}  // namespace
