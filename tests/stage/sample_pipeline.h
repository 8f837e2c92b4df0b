#pragma once
// The pipeline's stages run as subprocesses on the shipped samples (data/samples), for
// the stage tests of the later stages.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "shared_outputs.h"
#include "support/run_command.h"

namespace hair::test {

inline const std::filesystem::path kBin = std::filesystem::path(HAIR_BIN_DIR);
inline const std::filesystem::path kSamples =
    std::filesystem::path(HAIR_SOURCE_DIR) / "data" / "samples";

/// Runs a stage (quiet, reproducible) and expects it to succeed.
inline void run_stage(const std::string& stage, std::vector<std::string> arguments) {
  arguments.insert(arguments.end(), {"--quiet", "--reproducible"});
  auto result = run_command(kBin / stage, arguments);
  ASSERT_EQ(result.exit_code, 0) << stage << ": " << result.err;
}

/// The pipeline's files for one model.
struct SampleOutputs {
  std::filesystem::path extract, types, middle, clusters, strands;
  std::vector<std::string> grow_inputs() const {
    return {extract.string(), types.string(), clusters.string()};
  }
};

/// Runs extract to cluster-all on `mesh` in `folder` (each file only if missing), then grow
/// with `strand_count` strands if that is positive and strands.h5 is missing.
inline SampleOutputs make_sample_pipeline(const std::filesystem::path& folder,
                                          const std::filesystem::path& mesh, int strand_count) {
  std::filesystem::create_directories(folder);
  SampleOutputs out{folder / "extract.h5", folder / "types.h5", folder / "middle.h5",
                    folder / "clusters.h5", folder / "strands.h5"};
  if (!std::filesystem::exists(out.clusters)) {
    run_stage("extract", {mesh.string(), "--body", (kSamples / "body.obj").string(), "--unit_scale",
                          "0.1", "-o", out.extract.string()});
    run_stage("typeify", {out.extract.string(), "-o", out.types.string()});
    run_stage("cluster-middle", {out.types.string(), "-o", out.middle.string()});
    run_stage("cluster-all",
              {out.types.string(), out.middle.string(), "-o", out.clusters.string()});
  }
  if (strand_count > 0 && !std::filesystem::exists(out.strands)) {
    std::vector<std::string> arguments = out.grow_inputs();
    arguments.insert(arguments.end(),
                     {"--strand_count", std::to_string(strand_count), "-o", out.strands.string()});
    run_stage("grow", arguments);
  }
  return out;
}

/// make_sample_pipeline, whose files for a shipped sample (data/samples/hair) are made
/// once per build and shared by the stage-test processes (shared_outputs).
inline SampleOutputs run_sample_pipeline(const std::filesystem::path& folder,
                                         const std::filesystem::path& mesh, int strand_count) {
  if (mesh.parent_path() == kSamples / "hair") {
    std::vector<std::string> names = {"extract.h5", "types.h5", "middle.h5", "clusters.h5"};
    if (strand_count > 0) names.push_back("strands.h5");
    shared_outputs("sample_" + mesh.stem().string() + "_" + std::to_string(strand_count), folder,
                   names, [&](const std::filesystem::path& shared) {
                     make_sample_pipeline(shared, mesh, strand_count);
                   });
  }
  return make_sample_pipeline(folder, mesh, strand_count);
}

}  // namespace hair::test
