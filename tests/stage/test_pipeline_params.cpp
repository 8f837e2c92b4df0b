// The default pipeline's parameter files (pipelines/default/<stage>.toml) are what each
// stage prints with --print-params for their values: every parameter present, with the
// stage's own description, range and spelling, so that the files cannot drift from the
// code. A file's own header (before "# Parameters of stage") is its own.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "sample_pipeline.h"

namespace {

namespace fs = std::filesystem;
using hair::test::kBin;
using hair::test::run_command;

std::string file_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(PipelineParams, EveryDefaultFileIsWhatItsStagePrints) {
  const fs::path folder = fs::path(HAIR_SOURCE_DIR) / "pipelines" / "default";
  int files = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
    if (entry.path().extension() != ".toml") continue;
    const std::string stage = entry.path().stem().string();
    SCOPED_TRACE(entry.path().string());
    ++files;
    ASSERT_TRUE(fs::exists(kBin / stage)) << "no stage named " << stage;
    const std::string text = file_text(entry.path());
    const size_t body = text.find("# Parameters of stage " + stage + ":");
    ASSERT_NE(body, std::string::npos) << "no '# Parameters of stage' line";
    const auto printed =
        run_command(kBin / stage, {"--print-params", "--params", entry.path().string()});
    ASSERT_EQ(printed.exit_code, 0) << printed.err;
    EXPECT_EQ(text.substr(body), printed.out)
        << "regenerate it: build/bin/" << stage << " --print-params --params " << entry.path();
  }
  EXPECT_EQ(files, 8);  // extract, typeify, cluster-middle, cluster-all, grow, classify,
                        // simulate, interpolate
}

}  // namespace
