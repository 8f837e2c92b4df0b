// A byte-flipped extract.h5 (a fixed family of variants) through every program that
// reads it: typeify, grow, classify, simulate, hair-render and hair-inspect. Each must
// exit 0 (the flip fell where the file holds nothing) or 2 with one error line, never
// die of a signal, and leave nothing behind but a finished output (issue 30). The
// family's size is HAIR_CORRUPTED_VARIANTS (default 120 for each program in the suite;
// the bench runs more);
// bench/corrupted_intermediates.sh reports the counts in docs/bench/corrupted.md. And
// well-formed files whose contents do not hold together (offsets that do not end at the
// point count, an id out of range, a NaN) are refused naming the file and dataset.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "clean_failures.h"
#include "hair/h5/dataset.h"
#include "sample_pipeline.h"
#include "support/run_command.h"

namespace {

namespace fs = std::filesystem;
using hair::test::kBin;
using hair::test::kSamples;
using hair::test::run_command;
using hair::test::run_stage;
using hair::test::SampleOutputs;
using hair::test::TemporaryDirectory;
using hair::test::text_lines;

const fs::path kModel = fs::path(HAIR_SOURCE_DIR) / "models" / "style_extended.yml";

/// How many variants a program gets: HAIR_CORRUPTED_VARIANTS if set, else `fallback`.
int variant_count(int fallback) {
  const char* text = std::getenv("HAIR_CORRUPTED_VARIANTS");
  return text != nullptr ? std::max(1, std::atoi(text)) : fallback;
}

/// Variant `index` of `valid`: 1-3 bytes, each XORed with a non-zero byte, at positions
/// drawn from a generator seeded by the index, so that any variant can be remade alone.
std::vector<uint8_t> flipped_variant(const std::vector<uint8_t>& valid, int index) {
  std::mt19937_64 random(static_cast<uint64_t>(index) * 7919 + 30);
  std::vector<uint8_t> bytes = valid;
  const int flips = 1 + static_cast<int>(random() % 3);
  for (int f = 0; f < flips; ++f)
    bytes[random() % bytes.size()] ^= static_cast<uint8_t>(1 + random() % 255);
  return bytes;
}

/// A program that reads extract.h5: its arguments given the extract file and an output
/// path (empty for hair-inspect, which writes none).
struct Reader {
  std::string program;
  std::function<std::vector<std::string>(const fs::path&, const fs::path&)> arguments;
  std::string output_name;  ///< empty: writes nothing
  int default_variants;
};

class CorruptedIntermediates : public ::testing::Test {
 protected:
  static void TearDownTestSuite() { directory_.reset(); }
  static const TemporaryDirectory& directory() {
    if (!directory_) directory_ = std::make_unique<TemporaryDirectory>("corrupted");
    return *directory_;
  }
  /// braid01 up to styles.h5 with few strands: the inputs beside the corrupted file.
  static const SampleOutputs& braid() {
    static const SampleOutputs out = [] {
      SampleOutputs made =
          hair::test::run_sample_pipeline(directory() / "braid", kSamples / "hair" / "braid01.obj", 400);
      run_stage("classify", {made.extract.string(), made.clusters.string(), made.strands.string(),
                             "--model", kModel.string(), "-o", styles().string()});
      return made;
    }();
    return out;
  }
  static fs::path styles() { return directory() / "braid" / "styles.h5"; }

  /// Runs `reader` on variants 0 .. count-1 of braid01's extract.h5 and checks each run.
  static void expect_clean_runs(const Reader& reader) {
    const std::vector<uint8_t> valid = hair::test::read_file_octets(braid().extract);
    const fs::path folder = directory() / ("runs_" + reader.program);
    const int count = variant_count(reader.default_variants);
    {
      // The file as written reads: the refusals below are the flips'.
      fs::remove_all(folder);
      fs::create_directories(folder);
      fs::copy_file(braid().extract, folder / "extract.h5");
      const fs::path output = reader.output_name.empty() ? fs::path() : folder / reader.output_name;
      std::vector<std::string> arguments = reader.arguments(folder / "extract.h5", output);
      if (!output.empty()) arguments.insert(arguments.end(), {"-o", output.string()});
      const auto result = run_command(kBin / reader.program, arguments);
      ASSERT_EQ(result.exit_code, 0) << reader.program << " on the valid file: " << result.err;
    }
    int refused = 0;
    for (int index = 0; index < count; ++index) {
      fs::remove_all(folder);
      fs::create_directories(folder);
      const fs::path extract = folder / "extract.h5";
      {
        const std::vector<uint8_t> bytes = flipped_variant(valid, index);
        std::ofstream(extract, std::ios::binary)
            .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
      }
      const fs::path output = reader.output_name.empty() ? fs::path() : folder / reader.output_name;
      std::vector<std::string> arguments = reader.arguments(extract, output);
      if (!output.empty()) arguments.insert(arguments.end(), {"-o", output.string()});
      const auto result = run_command(kBin / reader.program, arguments);
      const std::string what = reader.program + ", variant " + std::to_string(index);
      ASSERT_TRUE(result.exit_code == 0 || result.exit_code == 2)
          << what << ": exit " << result.exit_code << "\n" << result.err;
      std::vector<std::string> left;
      for (const auto& entry : fs::directory_iterator(folder)) left.push_back(entry.path().filename());
      std::sort(left.begin(), left.end());
      std::vector<std::string> expected = {"extract.h5"};
      if (result.exit_code == 0 && !output.empty()) expected.push_back(reader.output_name);
      std::sort(expected.begin(), expected.end());
      EXPECT_EQ(left, expected) << what;
      if (result.exit_code == 2) {
        ++refused;
        // hair-inspect lists what it could read of an invalid file on stdout and ends the
        // listing with the violation; a file it cannot open is one line on stderr.
        const std::vector<std::string> out_lines = text_lines(result.out);
        if (reader.output_name.empty() && result.err.empty() && !out_lines.empty()) {
          EXPECT_TRUE(out_lines.back().starts_with("invalid: ")) << what << ": " << result.out;
          EXPECT_NE(out_lines.back().find("extract.h5"), std::string::npos) << what;
          continue;
        }
        const std::vector<std::string> lines = text_lines(result.err);
        ASSERT_EQ(lines.size(), 1u) << what << ": " << result.err;
        EXPECT_NE(lines[0].find("extract.h5"), std::string::npos) << what << ": " << lines[0];
      }
    }
    std::cout << "corrupted: " << reader.program << ": " << count << " variants, " << refused
              << " refused (exit 2), " << count - refused << " read (exit 0), 0 signals\n";
    // Most flipped bytes fall on checksummed metadata or chunks.
    EXPECT_GE(refused, count / 2) << reader.program << ": " << refused << " of " << count;
  }

 private:
  static inline std::unique_ptr<TemporaryDirectory> directory_;
};

TEST_F(CorruptedIntermediates, Typeify) {
  expect_clean_runs({"typeify", [](const fs::path& extract, const fs::path&) {
                       return std::vector<std::string>{extract.string(), "--quiet"};
                     }, "types.h5", 120});
}

TEST_F(CorruptedIntermediates, HairInspect) {
  expect_clean_runs({"hair-inspect", [](const fs::path& extract, const fs::path&) {
                       return std::vector<std::string>{extract.string()};
                     }, "", 120});
}

TEST_F(CorruptedIntermediates, Grow) {
  expect_clean_runs({"grow", [](const fs::path& extract, const fs::path&) {
                       return std::vector<std::string>{extract.string(), braid().types.string(),
                                                       braid().clusters.string(), "--strand_count",
                                                       "400", "--quiet"};
                     }, "strands.h5", 120});
}

TEST_F(CorruptedIntermediates, Classify) {
  expect_clean_runs({"classify", [](const fs::path& extract, const fs::path&) {
                       return std::vector<std::string>{extract.string(), braid().clusters.string(),
                                                       braid().strands.string(), "--model",
                                                       kModel.string(), "--quiet"};
                     }, "styles.h5", 120});
}

TEST_F(CorruptedIntermediates, Simulate) {
  expect_clean_runs({"simulate", [](const fs::path& extract, const fs::path&) {
                       return std::vector<std::string>{extract.string(), braid().strands.string(),
                                                       styles().string(), "--duration_s", "0.05", "--quiet"};
                     }, "guides.h5", 120});
}

TEST_F(CorruptedIntermediates, HairRender) {
  expect_clean_runs({"hair-render", [](const fs::path& extract, const fs::path&) {
                       // The smallest picture: the reading is under test, not the drawing.
                       return std::vector<std::string>{extract.string(), "--size", "64"};
                     }, "extract.png", 120});
}

/// A copy of `source` at `copy` with element `index` of the 1-D int dataset `path` set
/// to `value` (written through HDF5, so that every checksum still holds: the file is
/// well-formed, its contents are not).
template <typename T>
fs::path copy_with_value(const fs::path& source, const fs::path& copy, const char* path,
                         int64_t index, T value) {
  fs::copy_file(source, copy, fs::copy_options::overwrite_existing);
  std::vector<T> values =
      hair::h5::read_vector<T>(hair::h5::File::open_read_only(source), path);
  values.at(static_cast<size_t>(index < 0 ? static_cast<int64_t>(values.size()) + index : index)) =
      value;
  const hid_t file = H5Fopen(copy.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  const hid_t dataset = H5Dopen2(file, path, H5P_DEFAULT);
  const hid_t type = std::is_same_v<T, int64_t> ? H5T_NATIVE_INT64 : H5T_NATIVE_INT32;
  EXPECT_GE(H5Dwrite(dataset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0);
  H5Dclose(dataset);
  H5Fclose(file);
  return copy;
}

TEST_F(CorruptedIntermediates, WellFormedFilesWithInconsistentContentsAreRefusedByName) {
  const fs::path folder = directory() / "inconsistent";
  fs::create_directories(folder);
  const fs::path extract = braid().extract;
  const int64_t points =
      static_cast<int64_t>(hair::h5::read_vector<int64_t>(hair::h5::File::open_read_only(extract),
                                                          "/strands/offsets")
                               .back());
  const int64_t groups =
      hair::h5::dataset_info(hair::h5::File::open_read_only(extract), "/groups/first_strand")
          .shape[0] - 1;
  // Each error names the file and the dataset.
  const std::vector<hair::test::FailureCase> cases = {
      {{copy_with_value<int64_t>(extract, folder / "offsets.h5", "/strands/offsets", -1,
                                 points - 1).string()},
       "offsets.h5:/strands/offsets"},
      {{copy_with_value<int32_t>(extract, folder / "group_id.h5",
                                 "/strands/strand_attributes/group", 0,
                                 static_cast<int32_t>(groups)).string()},
       "group_id.h5:/strands/strand_attributes/group"},
      {{hair::test::copy_with_nan(extract, folder / "nan.h5", "/strands/points").string()},
       "nan.h5:/strands/points"},
  };
  hair::test::expect_clean_failures(kBin / "typeify", "typeify", cases, folder / "runs",
                                    braid().types);
}

}  // namespace
