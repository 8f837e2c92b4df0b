#include <gtest/gtest.h>
#include <omp.h>
#include <spdlog/spdlog.h>

#include <cstdlib>
#include <filesystem>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "unit/file_test.h"
#include "hair/core/error.h"
#include "hair/core/stage_app.h"

namespace {

namespace fs = std::filesystem;

/// A stage with one input, two parameters and a body the test chooses.
struct FakeStage {
  hair::StageApp app{"fake", "A stage for testing the shell"};
  std::string input_path;
  double k1 = 0.5;
  int iterations = 3;
  bool body_ran = false;

  FakeStage() {
    app.cli().add_option("input", input_path, "Input file")->required();
    app.params().add("k1", k1, "Weight of the first term", hair::ParamRange::closed(0, 1));
    app.params().add("iterations", iterations, "Solver iterations", hair::ParamRange::at_least(1));
  }
};

/// What a run of the fake stage returned and printed.
struct RunResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

RunResult run_stage(
    FakeStage& stage, const std::vector<std::string>& arguments,
    const std::function<void()>& body = [] {}) {
  std::vector<const char*> argv{"fake"};
  for (const auto& argument : arguments) argv.push_back(argument.c_str());
  RunResult result;
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  result.exit_code = stage.app.run(static_cast<int>(argv.size()), argv.data(), [&] {
    stage.body_ran = true;
    body();
  });
  result.err = ::testing::internal::GetCapturedStderr();
  result.out = ::testing::internal::GetCapturedStdout();
  return result;
}

class StageAppTest : public hair::test::FileTest {};

TEST_F(StageAppTest, RunsTheBodyWithParsedOptions) {
  FakeStage stage;
  const RunResult result =
      run_stage(stage, {"in.h5", "-o", "out.h5", "--k1", "0.25", "--reproducible"});
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(stage.body_ran);
  EXPECT_EQ(stage.input_path, "in.h5");
  EXPECT_EQ(stage.app.output_path(), "out.h5");
  EXPECT_EQ(stage.app.params_path(), "");
  EXPECT_TRUE(stage.app.reproducible());
  EXPECT_EQ(stage.app.stage_name(), "fake");
  EXPECT_EQ(stage.k1, 0.25);
  EXPECT_GE(stage.app.elapsed_s(), 0.0);
  EXPECT_EQ(result.err, "");
}

TEST_F(StageAppTest, ParameterFileWithCommentsAndCommandLineOverride) {
  const std::string path = write_file("fake.toml", R"(# fake stage
# weight of the first term
k1 = 0.75  # three quarters
iterations = 9
)");
  FakeStage stage;
  const RunResult result =
      run_stage(stage, {"in.h5", "-o", "out.h5", "--params", path, "--iterations", "2"});
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(stage.app.params_path(), path);
  EXPECT_EQ(stage.k1, 0.75);
  EXPECT_EQ(stage.iterations, 2);
}

TEST_F(StageAppTest, UnknownKeyIsRejectedByName) {
  const std::string path = write_file("fake.toml", "k1 = 0.5\nfoo = 1\n");
  FakeStage stage;
  const RunResult result = run_stage(stage, {"in.h5", "-o", "out.h5", "--params", path});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_FALSE(stage.body_ran);
  EXPECT_EQ(result.err, "fake: error: unknown parameter 'foo' in " + path + "\n");
}

TEST_F(StageAppTest, CommandLineOptionInParameterFileIsRejected) {
  const std::string path = write_file("fake.toml", "output = \"other.h5\"\n");
  FakeStage stage;
  const RunResult result = run_stage(stage, {"in.h5", "-o", "out.h5", "--params", path});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err,
            "fake: error: 'output' in " + path + " is a command-line option, not a parameter\n");
}

TEST_F(StageAppTest, OutOfRangeValueInFileIsRejected) {
  const std::string path = write_file("fake.toml", "k1 = 1.5\n");
  FakeStage stage;
  const RunResult result = run_stage(stage, {"in.h5", "-o", "out.h5", "--params", path});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err, "fake: error: parameter k1 = 1.5 is out of range [0, 1]\n");
}

TEST_F(StageAppTest, MissingParameterFileIsAnError) {
  FakeStage stage;
  const std::string path = (directory_ / "absent.toml").string();
  const RunResult result = run_stage(stage, {"in.h5", "-o", "out.h5", "--params", path});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err, "fake: error: cannot read parameter file " + path + "\n");
}

TEST_F(StageAppTest, MissingOutputIsAUsageError) {
  FakeStage stage;
  const RunResult result = run_stage(stage, {"in.h5"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_FALSE(stage.body_ran);
  EXPECT_EQ(result.err, "fake: error: --output is required\n");
}

TEST_F(StageAppTest, QuietAndVerboseExcludeEachOther) {
  FakeStage stage;
  const RunResult result = run_stage(stage, {"in.h5", "-o", "out.h5", "--quiet", "--verbose"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err.rfind("fake: error: ", 0), 0u) << result.err;
}

TEST_F(StageAppTest, HelpExitsZeroAndListsParameters) {
  FakeStage stage;
  const RunResult result = run_stage(stage, {"--help"});
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_FALSE(stage.body_ran);
  EXPECT_NE(result.out.find("Parameters"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("--k1"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("--print-params"), std::string::npos) << result.out;
}

TEST_F(StageAppTest, PrintParamsNeedsNoInputsAndReadsBack) {
  FakeStage printer;
  const RunResult printed = run_stage(printer, {"--print-params", "--k1", "0.125"});
  EXPECT_EQ(printed.exit_code, 0) << printed.err;
  EXPECT_FALSE(printer.body_ran);
  EXPECT_NE(printed.out.find("k1 = 0.125\n"), std::string::npos) << printed.out;

  const std::string path = write_file("printed.toml", printed.out);
  FakeStage reader;
  const RunResult read = run_stage(reader, {"in.h5", "-o", "out.h5", "--params", path});
  EXPECT_EQ(read.exit_code, 0) << read.err;
  EXPECT_EQ(reader.k1, 0.125);
  EXPECT_EQ(reader.iterations, 3);
}

TEST_F(StageAppTest, ErrorsMapToExitCodes) {
  {
    FakeStage stage;
    const RunResult result = run_stage(stage, {"in.h5", "-o", "out.h5"}, [] {
      throw hair::Error::bad_dataset("in.h5", "/points", "expected [n,3] float32");
    });
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_EQ(result.err, "fake: error: in.h5:/points: expected [n,3] float32\n");
  }
  {
    FakeStage stage;
    const RunResult result = run_stage(stage, {"in.h5", "-o", "out.h5"},
                                       [] { throw hair::Error::runtime("out.h5", "disk full"); });
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_EQ(result.err, "fake: error: out.h5: disk full\n");
  }
  {
    FakeStage stage;
    const RunResult result =
        run_stage(stage, {"in.h5", "-o", "out.h5"}, [] { throw std::runtime_error("two\nlines"); });
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_EQ(result.err, "fake: error: two lines\n");
  }
  {
    FakeStage stage;
    const RunResult result =
        run_stage(stage, {"in.h5", "-o", "out.h5"}, [] { throw std::bad_alloc(); });
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_EQ(result.err, "fake: error: out of memory\n");
  }
}

TEST_F(StageAppTest, CrossCheckFailureIsAUsageError) {
  FakeStage stage;
  stage.app.params().add_check([&]() -> std::optional<std::string> {
    if (stage.k1 * stage.iterations > 2.0) return "k1 * iterations must be at most 2";
    return std::nullopt;
  });
  const RunResult result = run_stage(stage, {"in.h5", "-o", "out.h5", "--k1", "1"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err, "fake: error: k1 * iterations must be at most 2\n");
}

TEST_F(StageAppTest, LoggingFollowsVerbosity) {
  const auto body = [] {
    spdlog::debug("detail");
    spdlog::info("news");
    spdlog::warn("careful");
  };
  {
    FakeStage stage;
    const RunResult result = run_stage(stage, {"in.h5", "-o", "out.h5"}, body);
    EXPECT_EQ(result.err, "fake: info: news\nfake: warning: careful\n");
  }
  {
    FakeStage stage;
    const RunResult result = run_stage(stage, {"in.h5", "-o", "out.h5", "--quiet"}, body);
    EXPECT_EQ(result.err, "fake: warning: careful\n");
  }
  {
    FakeStage stage;
    const RunResult result = run_stage(stage, {"in.h5", "-o", "out.h5", "--verbose"}, body);
    EXPECT_NE(result.err.find("fake: debug: detail\n"), std::string::npos) << result.err;
  }
}

TEST_F(StageAppTest, ThreadsOptionSetsOpenMpThreads) {
  const int threads_before = omp_get_max_threads();
  FakeStage stage;
  int threads_in_body = 0;
  const RunResult result = run_stage(stage, {"in.h5", "-o", "out.h5", "--threads", "2"},
                                     [&] { threads_in_body = omp_get_max_threads(); });
  omp_set_num_threads(threads_before);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(threads_in_body, 2);

  FakeStage negative;
  EXPECT_EQ(run_stage(negative, {"in.h5", "-o", "out.h5", "--threads", "-1"}).exit_code, 2);
}

TEST_F(StageAppTest, InsideASlurmJobAllCoresMeansTheCpusItWasGiven) {
  const int threads_before = omp_get_max_threads();
  ::setenv("SLURM_CPUS_PER_TASK", "3", 1);
  EXPECT_EQ(hair::slurm_cpus_per_task(), 3);
  FakeStage stage;
  int threads_in_body = 0;
  EXPECT_EQ(run_stage(stage, {"in.h5", "-o", "out.h5", "--threads", "0"},
                      [&] { threads_in_body = omp_get_max_threads(); })
                .exit_code,
            0);
  EXPECT_EQ(threads_in_body, 3);
  // --threads N wins over Slurm's count; a value that is not a count is ignored.
  FakeStage explicit_count;
  EXPECT_EQ(run_stage(explicit_count, {"in.h5", "-o", "out.h5", "--threads", "2"},
                      [&] { threads_in_body = omp_get_max_threads(); })
                .exit_code,
            0);
  EXPECT_EQ(threads_in_body, 2);
  for (const char* bad : {"", "0", "-2", "2x", "many"}) {
    ::setenv("SLURM_CPUS_PER_TASK", bad, 1);
    EXPECT_EQ(hair::slurm_cpus_per_task(), 0) << bad;
  }
  ::unsetenv("SLURM_CPUS_PER_TASK");
  EXPECT_EQ(hair::slurm_cpus_per_task(), 0);
  omp_set_num_threads(threads_before);
}

}  // namespace
