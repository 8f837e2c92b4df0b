#pragma once
// Bad input to a stage: exit 2, one error line, no output, an existing output untouched
// (DESIGN.md, contract 1).

#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "hair/h5/dataset.h"
#include "hair/h5/file.h"
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

/// A copy of the HDF5 file `source` at `copy` with one coordinate of its float32 n x 3
/// dataset `path` (row 1, y) set to NaN: bad input the stages must refuse.
inline std::filesystem::path copy_with_nan(const std::filesystem::path& source,
                                           const std::filesystem::path& copy, const char* path) {
  std::filesystem::copy_file(source, copy, std::filesystem::copy_options::overwrite_existing);
  auto points = hair::h5::read_matrix<float, 3>(hair::h5::File::open_read_only(source), path);
  points(1, 1) = std::numeric_limits<float>::quiet_NaN();
  hid_t file = H5Fopen(copy.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  hid_t dataset = H5Dopen2(file, path, H5P_DEFAULT);
  EXPECT_GE(H5Dwrite(dataset, H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, points.data()), 0);
  H5Dclose(dataset);
  H5Fclose(file);
  return copy;
}

/// A copy of the HDF5 file `source` at `copy` whose int32 vector dataset `path` lost its
/// last `dropped` entries: a file whose arrays disagree in length, which the stages must
/// refuse.
inline std::filesystem::path copy_with_shorter_vector(const std::filesystem::path& source,
                                                      const std::filesystem::path& copy,
                                                      const char* path, size_t dropped) {
  std::filesystem::copy_file(source, copy, std::filesystem::copy_options::overwrite_existing);
  auto values = hair::h5::read_vector<int32_t>(hair::h5::File::open_read_only(source), path);
  values.resize(values.size() > dropped ? values.size() - dropped : 0);
  hid_t file = H5Fopen(copy.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  EXPECT_GE(H5Ldelete(file, path, H5P_DEFAULT), 0);
  const hsize_t size = values.size();
  hid_t space = H5Screate_simple(1, &size, nullptr);
  hid_t dataset =
      H5Dcreate2(file, path, H5T_STD_I32LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  EXPECT_GE(H5Dwrite(dataset, H5T_NATIVE_INT32, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0);
  H5Dclose(dataset);
  H5Sclose(space);
  H5Fclose(file);
  return copy;
}

}  // namespace hair::test
