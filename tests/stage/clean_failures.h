#pragma once
// Bad input to a stage: exit 2, one error line, no output, an existing output untouched
// (DESIGN.md, contract 1).

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "support/run_command.h"

namespace hair::test {

/// A command line that must fail, and a text its error line must hold.
struct FailureCase {
  std::vector<std::string> arguments;  ///< without -o
  std::string expected;
};

/// Runs `binary` (the stage `stage`) with every case's arguments and `-o OUTPUT` twice:
/// to a new output in an empty `folder` (nothing may appear) and over a copy of
/// `existing_source` (left as it was). Expects exit 2 and one line on stderr,
/// "<stage>: error: ..." holding the case's text.
inline void expect_clean_failures(const std::filesystem::path& binary, const std::string& stage,
                                  const std::vector<FailureCase>& cases,
                                  const std::filesystem::path& folder,
                                  const std::filesystem::path& existing_source) {
  namespace fs = std::filesystem;
  fs::create_directories(folder);
  const fs::path existing = folder / "existing.h5";
  fs::copy_file(existing_source, existing, fs::copy_options::overwrite_existing);
  const std::string existing_bytes = read_file_bytes(existing);
  for (const FailureCase& bad : cases) {
    for (const fs::path& output : {folder / "new.h5", existing}) {
      std::vector<std::string> arguments = bad.arguments;
      arguments.insert(arguments.end(), {"-o", output.string()});
      auto result = run_command(binary, arguments);
      EXPECT_EQ(result.exit_code, 2) << bad.expected << ": " << result.err;
      std::vector<std::string> lines = text_lines(result.err);
      ASSERT_EQ(lines.size(), 1u) << result.err;
      EXPECT_TRUE(lines[0].starts_with(stage + ": error: ")) << lines[0];
      EXPECT_NE(lines[0].find(bad.expected), std::string::npos) << lines[0];
      std::vector<std::string> left;
      for (const auto& entry : fs::directory_iterator(folder))
        left.push_back(entry.path().filename().string());
      std::sort(left.begin(), left.end());
      EXPECT_EQ(left, std::vector<std::string>{"existing.h5"}) << bad.expected;
      EXPECT_TRUE(read_file_bytes(existing) == existing_bytes) << bad.expected;
    }
  }
}

}  // namespace hair::test
