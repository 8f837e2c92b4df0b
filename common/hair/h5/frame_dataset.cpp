#include "hair/h5/frame_dataset.h"

#include <algorithm>
#include <array>
#include <cstring>

#include "hair/core/error.h"
#include "hair/h5/chunk_compression.h"
#include "hair/h5/dataset.h"
#include "hair/h5/dtype.h"

namespace hair::h5 {

FrameDatasetWriter::FrameDatasetWriter(File& file, const std::string& path, int64_t frames,
                                       int64_t rows, int64_t columns)
    : file_name_(file.name()), path_(path), frames_(frames), rows_(rows), columns_(columns) {
  std::string parent = path.substr(0, path.find_last_of('/'));
  if (!parent.empty()) file.create_group(parent);
  std::array<hsize_t, 3> dims = {static_cast<hsize_t>(frames), static_cast<hsize_t>(rows),
                                 static_cast<hsize_t>(columns)};
  // A single frame is one chunk as large as the dataset, which HDF5 (1.10) then indexes as
  // a single chunk; a filtered chunk written directly (H5Dwrite_chunk) there reads back
  // unfiltered while the dataset is open (a stage's check of its output read deflated
  // bytes as floats, and past the chunk's end). A frame axis that may grow keeps the
  // chunk index of several frames.
  std::array<hsize_t, 3> max_dims = dims;
  if (frames == 1) max_dims[0] = H5S_UNLIMITED;
  Handle space(H5Screate_simple(3, dims.data(), max_dims.data()), H5Sclose);
  Handle properties(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  H5Pset_obj_track_times(properties.get(), false);
  keep_in_object_header(properties.get(), false);
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
  std::vector<unsigned char> chunk =
      shuffled_zlib_chunk(reinterpret_cast<const unsigned char*>(values.data()), values.size(),
                          sizeof(float), kFrameDeflatePieceBytes, kFrameDeflateLevel);
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
