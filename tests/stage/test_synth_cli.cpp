// Stage tests of hair-synth as a subprocess: one model (OBJ + truth that validates),
// byte-identical reruns with --reproducible, the corpus and its manifest, the
// generated mesh through the extract binary, and bad usage.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "support/run_command.h"

namespace {

namespace fs = std::filesystem;
using hair::test::CommandResult;
using hair::test::read_file_bytes;
using hair::test::run_command;
using hair::test::TemporaryDirectory;
using hair::test::text_lines;

const fs::path kSynth = fs::path(HAIR_BIN_DIR) / "hair-synth";
const fs::path kExtract = fs::path(HAIR_BIN_DIR) / "extract";
const fs::path kInspect = fs::path(HAIR_BIN_DIR) / "hair-inspect";
const fs::path kBody = fs::path(HAIR_SOURCE_DIR) / "data" / "samples" / "body.obj";
const fs::path kExtractParams =
    fs::path(HAIR_SOURCE_DIR) / "pipelines" / "default" / "extract.toml";

std::string describe(const CommandResult& result) {
  return "exit " + std::to_string(result.exit_code) + ", stderr:\n" + result.err;
}

TEST(HairSynthCli, WritesAMeshAndAValidTruthThatExtractReads) {
  TemporaryDirectory directory("synth_model");
  CommandResult run = run_command(kSynth, {"--preset", "ponytail", "--seed", "3", "--body",
                                           kBody.string(), "-o", directory.path().string()});
  ASSERT_EQ(run.exit_code, 0) << describe(run);
  ASSERT_TRUE(fs::exists(directory / "ponytail.obj"));
  CommandResult inspect = run_command(kInspect, {(directory / "ponytail.truth.h5").string()});
  EXPECT_EQ(inspect.exit_code, 0) << describe(inspect) << inspect.out;
  CommandResult extract = run_command(
      kExtract, {(directory / "ponytail.obj").string(), "--body", kBody.string(), "--params",
                 kExtractParams.string(), "-o", (directory / "extract.h5").string()});
  EXPECT_EQ(extract.exit_code, 0) << describe(extract);
}

TEST(HairSynthCli, SameSeedGivesIdenticalFiles) {
  TemporaryDirectory directory("synth_same_seed");
  for (const char* folder : {"a", "b", "c"}) {
    std::string seed = std::string(folder) == "c" ? "6" : "5";
    CommandResult run =
        run_command(kSynth, {"--preset", "normal_braid", "--seed", seed, "--vary", "--reproducible",
                             "--body", kBody.string(), "-o", (directory / folder).string()});
    ASSERT_EQ(run.exit_code, 0) << describe(run);
  }
  for (const char* name : {"normal_braid.obj", "normal_braid.truth.h5"}) {
    EXPECT_EQ(read_file_bytes(directory / "a" / name), read_file_bytes(directory / "b" / name))
        << name;
    EXPECT_NE(read_file_bytes(directory / "a" / name), read_file_bytes(directory / "c" / name))
        << name;
  }
}

TEST(HairSynthCli, CorpusWritesEveryModelAndAManifest) {
  TemporaryDirectory directory("synth_corpus");
  CommandResult run = run_command(kSynth, {"corpus", "--count", "12", "--body", kBody.string(),
                                           "-o", directory.path().string()});
  ASSERT_EQ(run.exit_code, 0) << describe(run);
  std::vector<std::string> lines = text_lines(read_file_bytes(directory / "manifest.tsv"));
  ASSERT_EQ(lines.size(), 13u);
  EXPECT_EQ(lines[0].substr(0, 12), "name\tpreset\t");
  for (size_t i = 1; i < lines.size(); ++i) {
    std::string name = lines[i].substr(0, lines[i].find('\t'));
    EXPECT_TRUE(fs::exists(directory / (name + ".obj"))) << name;
    EXPECT_TRUE(fs::exists(directory / (name + ".truth.h5"))) << name;
  }
  EXPECT_NE(run.out.find("12 models"), std::string::npos) << run.out;
}

TEST(HairSynthCli, UnknownPresetIsAUsageError) {
  TemporaryDirectory directory("synth_bad");
  CommandResult run = run_command(
      kSynth, {"--preset", "beehive", "--body", kBody.string(), "-o", directory.path().string()});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("unknown preset 'beehive'"), std::string::npos) << run.err;
  EXPECT_TRUE(directory.entries().empty());
}

TEST(HairSynthCli, PrintedSpecGivesThePresetsFilesAndBadSpecsAreRefused) {
  TemporaryDirectory directory("synth_spec");
  CommandResult printed = run_command(kSynth, {"--preset", "braid", "--print-spec"});
  ASSERT_EQ(printed.exit_code, 0) << describe(printed);
  hair::test::write_text_file(directory / "braid.json", printed.out);
  CommandResult from_spec = run_command(
      kSynth, {"--spec", (directory / "braid.json").string(), "--seed", "4", "--reproducible",
               "--body", kBody.string(), "-o", (directory / "spec").string()});
  ASSERT_EQ(from_spec.exit_code, 0) << describe(from_spec);
  CommandResult from_preset =
      run_command(kSynth, {"--preset", "braid", "--seed", "4", "--reproducible", "--body",
                           kBody.string(), "-o", (directory / "preset").string()});
  ASSERT_EQ(from_preset.exit_code, 0) << describe(from_preset);
  EXPECT_EQ(read_file_bytes(directory / "spec" / "braid.obj"),
            read_file_bytes(directory / "preset" / "braid.obj"));
  EXPECT_EQ(read_file_bytes(directory / "spec" / "braid.truth.h5"),
            read_file_bytes(directory / "preset" / "braid.truth.h5"));

  std::string bad = printed.out;
  bad.replace(bad.find("\"jitter_m\""), 10, "\"jiter_m\"");
  hair::test::write_text_file(directory / "bad.json", bad);
  CommandResult refused = run_command(
      kSynth, {"--spec", (directory / "bad.json").string(), "-o", (directory / "bad").string()});
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("unknown key 'defects.jiter_m'"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(directory / "bad"));
}

}  // namespace
