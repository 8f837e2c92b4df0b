#pragma once
// Datasets of per-frame data, [n_frames, rows, columns] float32 with one compressed chunk
// per frame, written and read one frame at a time so that memory stays one frame's worth.

#include <cstdint>
#include <string>
#include <vector>

#include "hair/h5/file.h"
#include "hair/h5/handle.h"

namespace hair::h5 {

/// Deflate level of per-frame datasets: 1, not kDeflateLevel, as coordinates compress
/// about as well at 1 and a frame of a million points deflates several times faster.
inline constexpr unsigned kFrameDeflateLevel = 1;

/// Bytes of a frame's chunk deflated by one thread: a frame's chunk is deflated in pieces
/// of this size on all OpenMP threads and the pieces joined into one zlib stream (as pigz
/// does: each piece ends on a byte boundary, the checksums are combined; pieces of noise
/// stored: chunk_compression.h).
inline constexpr size_t kFrameDeflatePieceBytes = size_t{1} << 20;

/// Creates `path` (float32, [frames, rows, columns], chunk [1, rows, columns], shuffle and
/// deflate at kFrameDeflateLevel, pieces of noise stored) and writes it frame by frame. The writer
/// shuffles and deflates each frame itself, in parallel, and hands HDF5 the compressed chunk
/// (H5Dwrite_chunk): a chunk HDF5's own filters read back, without their one thread.
class FrameDatasetWriter {
 public:
  FrameDatasetWriter(File& file, const std::string& path, int64_t frames, int64_t rows,
                     int64_t columns);
  /// Writes frame `frame` from rows x columns values (row-major). Throws a runtime
  /// error naming the file and dataset on failure.
  void write(int64_t frame, const std::vector<float>& values);

 private:
  std::string file_name_, path_;
  int64_t frames_ = 0, rows_ = 0, columns_ = 0;
  Handle dataset_;
};

/// Reads frame `frame` of the [n_frames, rows, columns] float32 dataset `path`:
/// rows x columns values. Throws bad_input (missing, other type or rank, frame out of
/// range) naming the file and dataset.
std::vector<float> read_frame(const File& file, const std::string& path, int64_t frame);

}  // namespace hair::h5
