#include "hair/h5/frame_dataset.h"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstring>

#include "hair/error.h"
#include "hair/h5/dataset.h"
#include "hair/h5/dtype.h"

namespace hair::h5 {
namespace {

/// HDF5's shuffle filter: byte k of every value, value by value, for k = 0..size-1.
void shuffle_bytes(const unsigned char* values, size_t count, size_t value_size,
                   unsigned char* shuffled) {
#pragma omp parallel for schedule(static)
  for (size_t k = 0; k < value_size; ++k)
    for (size_t i = 0; i < count; ++i) shuffled[k * count + i] = values[i * value_size + k];
}

/// One piece of a deflate stream: raw deflate of `size` bytes, ended by a sync flush (so
/// that the next piece starts on a byte boundary) or, for the last, by the final block;
/// and the piece's Adler-32.
struct DeflatePiece {
  std::vector<unsigned char> bytes;
  uLong adler = 0;
  bool ok = false;
};

DeflatePiece deflate_piece(const unsigned char* data, size_t size, bool last) {
  DeflatePiece piece;
  piece.adler = adler32(adler32(0, nullptr, 0), data, static_cast<uInt>(size));
  z_stream stream{};
  if (deflateInit2(&stream, frame_piece_deflate_level(data, size), Z_DEFLATED, -15, 8,
                   Z_DEFAULT_STRATEGY) != Z_OK)
    return piece;
  piece.bytes.resize(deflateBound(&stream, static_cast<uLong>(size)) + 16);
  stream.next_in = const_cast<unsigned char*>(data);
  stream.avail_in = static_cast<uInt>(size);
  stream.next_out = piece.bytes.data();
  stream.avail_out = static_cast<uInt>(piece.bytes.size());
  int status = deflate(&stream, last ? Z_FINISH : Z_SYNC_FLUSH);
  piece.ok = last ? status == Z_STREAM_END : (status == Z_OK && stream.avail_in == 0);
  piece.bytes.resize(piece.bytes.size() - stream.avail_out);
  deflateEnd(&stream);
  return piece;
}

/// `bytes` as one zlib stream (RFC 1950), deflated in pieces in parallel; empty on failure.
std::vector<unsigned char> zlib_compress_parallel(const std::vector<unsigned char>& bytes) {
  const size_t pieces =
      std::max<size_t>(1, (bytes.size() + kFrameDeflatePieceBytes - 1) / kFrameDeflatePieceBytes);
  std::vector<DeflatePiece> deflated(pieces);
#pragma omp parallel for schedule(dynamic)
  for (size_t p = 0; p < pieces; ++p) {
    size_t first = p * kFrameDeflatePieceBytes;
    size_t size = std::min(bytes.size() - std::min(first, bytes.size()), kFrameDeflatePieceBytes);
    deflated[p] = deflate_piece(bytes.data() + first, size, p + 1 == pieces);
  }
  // The header compress2() writes at level 1 (deflate, 32 KiB window, fastest), the
  // pieces, and the Adler-32 of all the bytes, big-endian.
  std::vector<unsigned char> stream = {0x78, 0x01};
  uLong adler = adler32(0, nullptr, 0);
  for (size_t p = 0; p < pieces; ++p) {
    if (!deflated[p].ok) return {};
    stream.insert(stream.end(), deflated[p].bytes.begin(), deflated[p].bytes.end());
    size_t first = p * kFrameDeflatePieceBytes;
    size_t size = std::min(bytes.size() - std::min(first, bytes.size()), kFrameDeflatePieceBytes);
    adler = adler32_combine(adler, deflated[p].adler, static_cast<z_off_t>(size));
  }
  for (int shift = 24; shift >= 0; shift -= 8)
    stream.push_back(static_cast<unsigned char>((adler >> shift) & 0xff));
  return stream;
}

}  // namespace

int frame_piece_deflate_level(const unsigned char* data, size_t size) {
  const size_t sample = std::min(size, kFrameDeflateSampleBytes);
  if (sample == 0) return static_cast<int>(kFrameDeflateLevel);
  std::vector<unsigned char> out(compressBound(static_cast<uLong>(sample)));
  uLongf out_size = static_cast<uLongf>(out.size());
  if (compress2(out.data(), &out_size, data, static_cast<uLong>(sample),
                static_cast<int>(kFrameDeflateLevel)) != Z_OK)
    return static_cast<int>(kFrameDeflateLevel);
  const bool shrinks =
      static_cast<double>(out_size) < (1.0 - kFrameStoreBelowSaving) * static_cast<double>(sample);
  return shrinks ? static_cast<int>(kFrameDeflateLevel) : 0;
}

FrameDatasetWriter::FrameDatasetWriter(File& file, const std::string& path, int64_t frames,
                                       int64_t rows, int64_t columns)
    : file_name_(file.name()), path_(path), frames_(frames), rows_(rows), columns_(columns) {
  std::string parent = path.substr(0, path.find_last_of('/'));
  if (!parent.empty()) file.create_group(parent);
  std::array<hsize_t, 3> dims = {static_cast<hsize_t>(frames), static_cast<hsize_t>(rows),
                                 static_cast<hsize_t>(columns)};
  Handle space(H5Screate_simple(3, dims.data(), nullptr), H5Sclose);
  Handle properties(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  H5Pset_obj_track_times(properties.get(), false);
  if (frames > 0 && rows > 0 && columns > 0) {
    std::array<hsize_t, 3> chunk = {1, dims[1], dims[2]};
    H5Pset_chunk(properties.get(), 3, chunk.data());
    H5Pset_shuffle(properties.get());
    H5Pset_deflate(properties.get(), kFrameDeflateLevel);
  }
  dataset_ = Handle(H5Dcreate2(file.id(), path.c_str(), file_type(Dtype::float32), space.get(),
                               H5P_DEFAULT, properties.get(), H5P_DEFAULT),
                    H5Dclose);
  if (!dataset_.valid())
    throw Error(ErrorKind::runtime, file_name_, path_, with_hdf5_message("cannot create dataset"));
}

void FrameDatasetWriter::write(int64_t frame, const std::vector<float>& values) {
  if (frame < 0 || frame >= frames_ || static_cast<int64_t>(values.size()) != rows_ * columns_)
    throw Error(ErrorKind::runtime, file_name_, path_,
                "cannot write frame " + std::to_string(frame) + " of " + std::to_string(frames_) +
                    " from " + std::to_string(values.size()) + " values");
  if (rows_ == 0 || columns_ == 0) return;
  static_assert(kFrameDeflateLevel == 1, "the zlib header written is level 1's");
  std::vector<unsigned char> shuffled(values.size() * sizeof(float));
  shuffle_bytes(reinterpret_cast<const unsigned char*>(values.data()), values.size(), sizeof(float),
                shuffled.data());
  std::vector<unsigned char> chunk = zlib_compress_parallel(shuffled);
  std::array<hsize_t, 3> offset = {static_cast<hsize_t>(frame), 0, 0};
  if (chunk.empty() ||
      H5Dwrite_chunk(dataset_.get(), H5P_DEFAULT, 0, offset.data(), chunk.size(), chunk.data()) < 0)
    throw Error(ErrorKind::runtime, file_name_, path_, with_hdf5_message("cannot write frame"));
}

std::vector<float> read_frame(const File& file, const std::string& path, int64_t frame) {
  DatasetInfo info = dataset_info(file, path);
  if (info.dtype != Dtype::float32 || info.shape.size() != 3)
    throw Error::bad_dataset(file.name(), path,
                             "expected [n_frames, n, m] float32, found " +
                                 format_shape(info.shape) + " " + info.type_name);
  if (frame < 0 || frame >= info.shape[0])
    throw Error::bad_dataset(file.name(), path,
                             "has no frame " + std::to_string(frame) + " (it has " +
                                 std::to_string(info.shape[0]) + ")");
  std::vector<float> values(static_cast<size_t>(info.shape[1] * info.shape[2]));
  if (values.empty()) return values;
  const Handle dataset = file.open_dataset(path);
  Handle space(H5Dget_space(dataset.get()), H5Sclose);
  std::array<hsize_t, 3> start = {static_cast<hsize_t>(frame), 0, 0};
  std::array<hsize_t, 3> count = {1, static_cast<hsize_t>(info.shape[1]),
                                  static_cast<hsize_t>(info.shape[2])};
  H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr);
  Handle memory(H5Screate_simple(3, count.data(), nullptr), H5Sclose);
  if (H5Dread(dataset.get(), memory_type(Dtype::float32), memory.get(), space.get(), H5P_DEFAULT,
              values.data()) < 0)
    throw Error::bad_dataset(file.name(), path, with_hdf5_message("cannot read frame"));
  return values;
}

}  // namespace hair::h5
