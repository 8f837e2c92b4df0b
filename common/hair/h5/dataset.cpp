#include "hair/h5/dataset.h"

#include <algorithm>
#include <cstring>
#include <vector>

#include "hair/h5/chunk_compression.h"

namespace hair::h5 {

namespace {

std::vector<hsize_t> to_hsize(const Shape& shape) {
  return std::vector<hsize_t>(shape.begin(), shape.end());
}

/// How a dataset is stored: its chunk shape (empty for an empty dataset, which has no
/// data to store), and whether its chunks are deflated (else checksummed with Fletcher-32).
struct ChunkLayout {
  Shape chunk;
  bool deflated = false;
};

/// The layout of a dataset: the caller's chunks (clamped to the extents), deflated; or,
/// for more than kSingleChunkLimit elements, deflated chunks of whole rows of the first
/// dimension adding up to about kTargetChunkBytes; or else one checksummed chunk.
ChunkLayout chosen_layout(const Shape& shape, size_t element_bytes, const Shape& requested,
                          const std::string& file_name, const std::string& path) {
  const bool is_empty = std::any_of(shape.begin(), shape.end(), [](int64_t n) { return n == 0; });
  if (!requested.empty()) {
    if (requested.size() != shape.size() ||
        std::any_of(requested.begin(), requested.end(), [](int64_t n) { return n <= 0; })) {
      throw Error(ErrorKind::runtime, file_name, path,
                  "chunk shape " + format_shape(requested) + " does not fit data of shape " +
                      format_shape(shape));
    }
    if (is_empty) return {};
    Shape chunk = requested;
    for (size_t axis = 0; axis < shape.size(); ++axis)
      chunk[axis] = std::min(chunk[axis], shape[axis]);
    return {chunk, true};
  }
  if (is_empty) return {};
  if (element_count(shape) <= kSingleChunkLimit) return {shape, false};
  const int64_t row_bytes =
      element_count(Shape(shape.begin() + 1, shape.end())) * static_cast<int64_t>(element_bytes);
  Shape chunk = shape;
  chunk[0] = std::clamp<int64_t>(kTargetChunkBytes / row_bytes, 1, shape[0]);
  return {chunk, true};
}

/// Dataset creation properties: untimed; chunked, then shuffle + deflate or Fletcher-32.
Handle dataset_properties(const ChunkLayout& layout) {
  Handle properties(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  H5Pset_obj_track_times(properties.get(), false);
  keep_in_object_header(properties.get(), false);
  if (!layout.chunk.empty()) {
    const std::vector<hsize_t> chunk_dims = to_hsize(layout.chunk);
    H5Pset_chunk(properties.get(), static_cast<int>(chunk_dims.size()), chunk_dims.data());
    if (layout.deflated) {
      H5Pset_shuffle(properties.get());
      H5Pset_deflate(properties.get(), kDeflateLevel);
    } else {
      H5Pset_fletcher32(properties.get());
    }
  }
  return properties;
}

/// The extents of an open dataset.
Shape dataset_shape(hid_t dataset) {
  const Handle space(H5Dget_space(dataset), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  std::vector<hsize_t> dims(static_cast<size_t>(std::max(rank, 0)));
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  return Shape(dims.begin(), dims.end());
}

/// "shuffle", "deflate(4)", ... for each filter of a dataset creation property list.
std::vector<std::string> filter_names(hid_t properties) {
  std::vector<std::string> names;
  const int count = H5Pget_nfilters(properties);
  for (int index = 0; index < count; ++index) {
    unsigned flags = 0;
    size_t value_count = 4;
    unsigned values[4] = {0, 0, 0, 0};
    char name[64] = {0};
    const H5Z_filter_t filter = H5Pget_filter2(properties, static_cast<unsigned>(index), &flags,
                                               &value_count, values, sizeof(name), name, nullptr);
    if (filter == H5Z_FILTER_DEFLATE) {
      names.push_back("deflate(" + std::to_string(value_count > 0 ? values[0] : 0) + ")");
    } else if (filter == H5Z_FILTER_SHUFFLE) {
      names.push_back("shuffle");
    } else if (filter == H5Z_FILTER_FLETCHER32) {
      names.push_back("fletcher32");
    } else {
      names.push_back(name[0] != 0 ? name : "filter " + std::to_string(filter));
    }
  }
  return names;
}

}  // namespace

std::string format_shape(const Shape& shape) {
  std::string text = "[";
  for (size_t axis = 0; axis < shape.size(); ++axis) {
    if (axis > 0) text += ", ";
    text += std::to_string(shape[axis]);
  }
  return text + "]";
}

int64_t element_count(const Shape& shape) {
  int64_t count = 1;
  for (const int64_t extent : shape) count *= extent;
  return count;
}

DatasetInfo dataset_info(const File& file, const std::string& path) {
  const Handle dataset = file.open_dataset(path);
  const Handle type(H5Dget_type(dataset.get()), H5Tclose);
  DatasetInfo info;
  info.type_name = stored_type_name(type.get());
  info.dtype = dtype_of_stored(type.get());
  info.is_enum = H5Tget_class(type.get()) == H5T_ENUM;
  info.shape = dataset_shape(dataset.get());
  const Handle properties(H5Dget_create_plist(dataset.get()), H5Pclose);
  if (H5Pget_layout(properties.get()) == H5D_CHUNKED) {
    std::vector<hsize_t> chunk(info.shape.size());
    H5Pget_chunk(properties.get(), static_cast<int>(chunk.size()), chunk.data());
    info.chunk_shape = Shape(chunk.begin(), chunk.end());
  }
  info.filters = filter_names(properties.get());
  return info;
}

namespace {

/// Writes `values` (row-major, `shape`) into `dataset`, chunked by whole rows (`chunk`),
/// shuffled and deflated by us on all threads, pieces of noise stored
/// (chunk_compression.h), and handed to HDF5 chunk by chunk (H5Dwrite_chunk). HDF5's own
/// filters read the chunks back. False, with nothing promised about what was written,
/// where this does not apply (chunks not of whole rows; types other than integers and
/// floats stored as in memory) or fails: the caller then writes through H5Dwrite.
bool write_row_chunks(hid_t dataset, hid_t stored_type, hid_t memory_type, const void* values,
                      const Shape& shape, const Shape& chunk) {
  const H5T_class_t type_class = H5Tget_class(memory_type);
  if ((type_class != H5T_INTEGER && type_class != H5T_FLOAT) ||
      H5Tequal(stored_type, memory_type) <= 0)
    return false;
  for (size_t axis = 1; axis < shape.size(); ++axis)
    if (chunk[axis] != shape[axis]) return false;
  const size_t element_bytes = H5Tget_size(memory_type);
  const auto row_bytes =
      static_cast<size_t>(element_count(Shape(shape.begin() + 1, shape.end()))) * element_bytes;
  const int64_t rows = shape[0], chunk_rows = chunk[0];
  const size_t chunk_bytes = static_cast<size_t>(chunk_rows) * row_bytes;
  const int64_t chunks = (rows + chunk_rows - 1) / chunk_rows;
  const auto* bytes = static_cast<const unsigned char*>(values);
  // In batches of about 64 MiB, so that memory stays bounded: compressed in parallel,
  // written in order.
  const int64_t batch = std::max<int64_t>(
      1, static_cast<int64_t>((size_t{64} << 20) / std::max<size_t>(chunk_bytes, 1)));
  std::vector<std::vector<unsigned char>> compressed(static_cast<size_t>(batch));
  std::vector<hsize_t> offset(shape.size(), 0);
  for (int64_t first = 0; first < chunks; first += batch) {
    const int64_t count = std::min(batch, chunks - first);
#pragma omp parallel for schedule(dynamic)
    for (int64_t c = 0; c < count; ++c) {
      // The edge chunk padded with zeros to a whole chunk, as HDF5 filters it; the others
      // read in place. One piece per byte plane, so that the planes of noise are stored.
      const int64_t row0 = (first + c) * chunk_rows;
      const auto filled = static_cast<size_t>(std::min(chunk_rows, rows - row0)) * row_bytes;
      const unsigned char* chunk_values = bytes + static_cast<size_t>(row0) * row_bytes;
      std::vector<unsigned char> padded;
      if (filled < chunk_bytes) {
        padded.assign(chunk_bytes, 0);
        std::memcpy(padded.data(), chunk_values, filled);
        chunk_values = padded.data();
      }
      compressed[static_cast<size_t>(c)] =
          shuffled_zlib_chunk(chunk_values, chunk_bytes / element_bytes, element_bytes,
                              chunk_bytes / element_bytes, kDeflateLevel);
    }
    for (int64_t c = 0; c < count; ++c) {
      const std::vector<unsigned char>& data = compressed[static_cast<size_t>(c)];
      offset[0] = static_cast<hsize_t>((first + c) * chunk_rows);
      if (data.empty() ||
          H5Dwrite_chunk(dataset, H5P_DEFAULT, 0, offset.data(), data.size(), data.data()) < 0)
        return false;
    }
  }
  return true;
}

}  // namespace

void write_raw_dataset(File& file, const std::string& path, hid_t stored_type, hid_t memory_type,
                       const void* values, const Shape& shape, const DatasetOptions& options) {
  if (shape.empty())
    throw Error(ErrorKind::runtime, file.name(), path, "cannot write a rank-0 dataset");
  file.create_group(parent_path(path));
  const ChunkLayout layout =
      chosen_layout(shape, H5Tget_size(memory_type), options.chunk_shape, file.name(), path);
  const std::vector<hsize_t> dims = to_hsize(shape);
  const Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
                     H5Sclose);
  const Handle properties = dataset_properties(layout);
  const Handle dataset(H5Dcreate2(file.id(), path.c_str(), stored_type, space.get(), H5P_DEFAULT,
                                  properties.get(), H5P_DEFAULT),
                       H5Dclose);
  if (!dataset.valid()) {
    throw Error(ErrorKind::runtime, file.name(), path, with_hdf5_message("cannot create dataset"));
  }
  if (element_count(shape) == 0) return;
  if (layout.deflated &&
      write_row_chunks(dataset.get(), stored_type, memory_type, values, shape, layout.chunk))
    return;
  if (H5Dwrite(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values) < 0) {
    throw Error(ErrorKind::runtime, file.name(), path, with_hdf5_message("cannot write dataset"));
  }
}

template <typename T>
Array<T> read_array(const File& file, const std::string& path) {
  const Handle dataset = file.open_dataset(path);
  const Handle type(H5Dget_type(dataset.get()), H5Tclose);
  constexpr Dtype expected = dtype_of<T>();
  if (dtype_of_stored(type.get()) != expected) {
    throw Error::bad_dataset(file.name(), path,
                             "expected " + std::string(dtype_name(expected)) + ", found " +
                                 stored_type_name(type.get()));
  }
  Array<T> array;
  array.shape = dataset_shape(dataset.get());
  array.values.resize(static_cast<size_t>(element_count(array.shape)));
  if (!array.values.empty() && H5Dread(dataset.get(), memory_type(expected), H5S_ALL, H5S_ALL,
                                       H5P_DEFAULT, array.values.data()) < 0) {
    throw Error::bad_dataset(file.name(), path, with_hdf5_message("cannot read dataset"));
  }
  return array;
}

template Array<float> read_array<float>(const File&, const std::string&);
template Array<double> read_array<double>(const File&, const std::string&);
template Array<int8_t> read_array<int8_t>(const File&, const std::string&);
template Array<uint8_t> read_array<uint8_t>(const File&, const std::string&);
template Array<int32_t> read_array<int32_t>(const File&, const std::string&);
template Array<int64_t> read_array<int64_t>(const File&, const std::string&);

}  // namespace hair::h5
