#pragma once
// A test fixture with a temporary directory of its own, removed afterwards.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/run_command.h"

namespace hair::test {

class FileTest : public ::testing::Test {
 protected:
  /// Writes `text` to a file `name` in the test's directory and returns its path.
  std::filesystem::path write_file(const std::string& name, const std::string& text) {
    std::filesystem::path path = directory_ / name;
    write_text_file(path, text);
    return path;
  }

  TemporaryDirectory directory_{::testing::UnitTest::GetInstance()->current_test_info()->name()};
};

}  // namespace hair::test
