// Per-frame datasets: frames deflated in parallel pieces joined into one chunk (written
// directly) read back exactly, through read_frame and through the block reader the
// schema checks use.
#include <H5Ppublic.h>

#include <array>
#include <cmath>
#include <random>

#include "hair/h5/chunk_compression.h"
#include "hair/h5/dataset_blocks.h"
#include "hair/h5/file.h"
#include "hair/h5/frame_dataset.h"
#include "unit/test_h5_support.h"

namespace hair::h5 {
namespace {

using H5FrameDatasetTest = testing::TemporaryDirectoryTest;

/// A frame of `rows` x 3 values that do not repeat (so that a misplaced chunk shows).
std::vector<float> frame_values(int64_t frame, int64_t rows) {
  std::vector<float> values(static_cast<size_t>(rows * 3));
  for (size_t i = 0; i < values.size(); ++i)
    values[i] = static_cast<float>(std::sin(0.001 * static_cast<double>(i)) + frame);
  return values;
}

TEST_F(H5FrameDatasetTest, FramesDeflatedInSeveralPiecesReadBackExactly) {
  // Three pieces and a partial one per frame.
  const int64_t frames = 3, rows = static_cast<int64_t>(3 * kFrameDeflatePieceBytes / 12) + 1234;
  {
    File file = File::create(path("frames.h5"));
    FrameDatasetWriter writer(file, "/frames/points", frames, rows, 3);
    for (int64_t frame = frames - 1; frame >= 0; --frame)  // any order
      writer.write(frame, frame_values(frame, rows));
    file.close();
  }
  File file = File::open_read_only(path("frames.h5"));
  for (int64_t frame = 0; frame < frames; ++frame)
    EXPECT_EQ(read_frame(file, "/frames/points", frame), frame_values(frame, rows)) << frame;
  std::vector<std::vector<float>> expected_frames;
  for (int64_t frame = 0; frame < frames; ++frame)
    expected_frames.push_back(frame_values(frame, rows));
  int64_t checked = 0;  // values; a block holds whole frames
  for_each_block<double>(
      file, "/frames/points", [&](int64_t first, std::span<const double> values) {
        for (size_t i = 0; i < values.size(); ++i) {
          int64_t at = first + static_cast<int64_t>(i), frame = at / (rows * 3);
          float expected =
              expected_frames[static_cast<size_t>(frame)][static_cast<size_t>(at % (rows * 3))];
          if (values[i] != static_cast<double>(expected)) {
            ADD_FAILURE() << "value " << at << " differs";
            return false;
          }
        }
        checked += static_cast<int64_t>(values.size());
        return true;
      });
  EXPECT_EQ(checked, frames * rows * 3);
  // One chunk per frame, shuffled and deflated (HDF5 read it back through its own
  // filters above).
  Handle dataset = file.open_dataset("/frames/points");
  Handle properties(H5Dget_create_plist(dataset.get()), H5Pclose);
  std::array<hsize_t, 3> chunk{};
  ASSERT_EQ(H5Pget_chunk(properties.get(), 3, chunk.data()), 3);
  EXPECT_EQ(chunk[0], 1u);
  EXPECT_EQ(chunk[1], static_cast<hsize_t>(rows));
  EXPECT_EQ(H5Pget_nfilters(properties.get()), 2);
}

TEST_F(H5FrameDatasetTest, NoiseIsStoredAndSmoothValuesDeflated) {
  // Frame 0: every byte noise (random finite floats), so each piece is stored, not
  // deflated: the chunk holds the raw bytes and a few per stored block. Frame 1: one
  // value repeated, which deflates to next to nothing. Both read back exactly.
  const int64_t rows = static_cast<int64_t>(2 * kFrameDeflatePieceBytes / 12) + 77;
  std::vector<float> noise(static_cast<size_t>(rows * 3)), flat(noise.size(), 0.25f);
  std::mt19937 random(3);
  std::uniform_real_distribution<float> value(-2, 2);
  for (float& v : noise) v = value(random);
  {
    File file = File::create(path("noise.h5"));
    FrameDatasetWriter writer(file, "/p", 2, rows, 3);
    writer.write(0, noise);
    writer.write(1, flat);
    file.close();
  }
  File file = File::open_read_only(path("noise.h5"));
  EXPECT_EQ(read_frame(file, "/p", 0), noise);
  EXPECT_EQ(read_frame(file, "/p", 1), flat);
  Handle dataset = file.open_dataset("/p");
  std::array<hsize_t, 3> first = {0, 0, 0}, second = {1, 0, 0};
  hsize_t noise_bytes = 0, flat_bytes = 0;
  ASSERT_GE(H5Dget_chunk_storage_size(dataset.get(), first.data(), &noise_bytes), 0);
  ASSERT_GE(H5Dget_chunk_storage_size(dataset.get(), second.data(), &flat_bytes), 0);
  const double raw = static_cast<double>(noise.size() * sizeof(float));
  // Random floats in [-2, 2] share their top byte's sign and exponent bits in part, so
  // that plane deflates somewhat; the three others are stored.
  EXPECT_GT(static_cast<double>(noise_bytes), 0.75 * raw);
  EXPECT_LT(static_cast<double>(noise_bytes), 1.001 * raw);
  EXPECT_LT(static_cast<double>(flat_bytes), 0.01 * raw);
  // The choice itself: noise stored, a repeated value and a slow ramp deflated.
  std::vector<unsigned char> bytes(kFrameDeflatePieceBytes);
  std::uniform_int_distribution<int> byte(0, 255);
  for (unsigned char& b : bytes) b = static_cast<unsigned char>(byte(random));
  const auto deflated = static_cast<int>(kFrameDeflateLevel);
  EXPECT_EQ(piece_deflate_level(bytes.data(), bytes.size(), kFrameDeflateLevel), 0);
  std::fill(bytes.begin(), bytes.end(), 7);
  EXPECT_EQ(piece_deflate_level(bytes.data(), bytes.size(), kFrameDeflateLevel), deflated);
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<unsigned char>(i / 4096);
  EXPECT_EQ(piece_deflate_level(bytes.data(), bytes.size(), kFrameDeflateLevel), deflated);
  EXPECT_EQ(piece_deflate_level(bytes.data(), 0, kFrameDeflateLevel), deflated);
}

TEST_F(H5FrameDatasetTest, AFrameSmallerThanAChunkIsOneChunk) {
  {
    File file = File::create(path("small.h5"));
    FrameDatasetWriter writer(file, "/p", 2, 5, 3);
    writer.write(0, frame_values(0, 5));
    writer.write(1, frame_values(1, 5));
    file.close();
  }
  File file = File::open_read_only(path("small.h5"));
  EXPECT_EQ(read_frame(file, "/p", 1), frame_values(1, 5));
}

TEST_F(H5FrameDatasetTest, ASingleFrameReadsBack) {
  // One frame is one chunk as large as the dataset, which HDF5 1.10 indexes as a single
  // chunk; written directly there it read back past its end (interpolate --frames 30:31
  // crashed in the output's schema check).
  // Read back before the file is closed, as a stage checks its output, and after.
  const int64_t rows = 5000;
  const std::vector<float> expected = frame_values(7, rows);
  File written = File::create(path("one.h5"));
  {
    FrameDatasetWriter writer(written, "/frames/points", 1, rows, 3);
    writer.write(0, expected);
    EXPECT_EQ(read_frame(written, "/frames/points", 0), expected);
    int64_t read = 0;
    for_each_block<double>(written, "/frames/points", [&](int64_t, std::span<const double> values) {
      read += static_cast<int64_t>(values.size());
      return true;
    });
    EXPECT_EQ(read, rows * 3);
  }
  written.close();
  File file = File::open_read_only(path("one.h5"));
  EXPECT_EQ(read_frame(file, "/frames/points", 0), expected);
  int64_t checked = 0;
  for_each_block<double>(
      file, "/frames/points", [&](int64_t first, std::span<const double> values) {
        for (size_t i = 0; i < values.size(); ++i)
          if (values[i] != static_cast<double>(expected[static_cast<size_t>(first) + i])) {
            ADD_FAILURE() << "value " << first + static_cast<int64_t>(i) << " differs";
            return false;
          }
        checked += static_cast<int64_t>(values.size());
        return true;
      });
  EXPECT_EQ(checked, rows * 3);
}

}  // namespace
}  // namespace hair::h5
