#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

namespace hair::testing {

/// Gives each test its own empty directory under the system's temporary directory and
/// removes it afterwards; tests never write into the source tree.
class TemporaryDirectoryTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    directory_ = std::filesystem::temp_directory_path() /
                 ("hair_" + std::string(test->test_suite_name()) + "_" + test->name() + "_" +
                  std::to_string(::getpid()));
    std::filesystem::remove_all(directory_);
    std::filesystem::create_directories(directory_);
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }

  /// A path inside the test's directory.
  std::filesystem::path path(const std::string& name) const { return directory_ / name; }

  std::filesystem::path directory_;
};

}  // namespace hair::testing
