// The hairstyle_io add-on's panel operators in Debian's Blender, headless
// (tests/blender/check_addon.py): ponytail01's cards and the body opened from their OBJ
// files and converted by the build's binaries into 10,000 strands with styles; a pinned
// cluster reruns classify alone; 11 frames baked under an animated object's motion play on
// the curves; a Cancel during grow leaves no output and no temporary file; a missing
// binary and a stage's failure give one report line. Skipped where /usr/bin/blender is
// missing.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "stage/sample_pipeline.h"
#include "support/run_command.h"

namespace {

namespace fs = std::filesystem;
using hair::test::kBin;
using hair::test::kSamples;
using hair::test::run_command;
using hair::test::TemporaryDirectory;

TEST(BlenderAddon, ConvertsFixesAndBakesFromThePanelsOperators) {
  const fs::path blender = "/usr/bin/blender";
  if (!fs::exists(blender))
    GTEST_SKIP() << "blender is not installed (Debian: apt install blender python3-h5py; "
                    ".ci/run installs it)";
  TemporaryDirectory work("blender_addon");
  const fs::path source(HAIR_SOURCE_DIR);
  auto result = run_command(
      blender, {"-b", "--factory-startup", "--python-exit-code", "1", "--python",
                (source / "tests" / "blender" / "check_addon.py").string(), "--",
                (source / "blender").string(), kBin.string(), kSamples.string(),
                work.path().string()});
  EXPECT_EQ(result.exit_code, 0) << result.out << result.err;
  EXPECT_NE(result.out.find("check: all passed"), std::string::npos) << result.out << result.err;
  EXPECT_NE(result.out.find("check: 10,000 strands as hair curves"), std::string::npos)
      << result.out;
  EXPECT_NE(result.out.find("check: no output: the folder it was writing is gone"),
            std::string::npos)
      << result.out;
  // What the script left is its work folder's alone: the stages wrote nowhere else.
  EXPECT_EQ(work.entries(), (std::vector<std::string>{"ponytail01"}));
}

}  // namespace
