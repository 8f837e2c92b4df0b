#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hair/core/error.h"
#include "hair/h5/dtype.h"
#include "hair/h5/file.h"

namespace hair::h5 {

/// Extents of a dataset, outermost first ({rows, columns} for a matrix).
using Shape = std::vector<int64_t>;

/// "[10, 3]".
std::string format_shape(const Shape& shape);

/// Number of elements of `shape` (1 for rank 0).
int64_t element_count(const Shape& shape);

/// How a dataset is stored.
struct DatasetOptions {
  /// Chunk shape, same rank as the data (e.g. {1, n_points, 3}: one frame per chunk).
  /// Empty: datasets of at most kSingleChunkLimit elements are one uncompressed chunk
  /// with a Fletcher-32 checksum, larger ones get row chunks of about kTargetChunkBytes,
  /// compressed with shuffle + deflate level kDeflateLevel (the zlib stream's Adler-32 is
  /// their checksum). Either way HDF5 refuses a chunk whose bytes were corrupted.
  Shape chunk_shape;
};

/// Largest dataset, in elements, stored as one uncompressed, checksummed chunk by default.
inline constexpr int64_t kSingleChunkLimit = 4096;
/// Size aimed at when choosing row chunks automatically.
inline constexpr int64_t kTargetChunkBytes = 128 * 1024;
/// Deflate (gzip) level of chunked datasets.
inline constexpr unsigned kDeflateLevel = 4;

/// Values of an n-dimensional dataset in row-major order, with its shape.
template <typename T>
struct Array {
  std::vector<T> values;  ///< element_count(shape) values, last index fastest
  Shape shape;
};

/// What a dataset holds and how it is stored, for listings and validation.
struct DatasetInfo {
  std::string type_name;             ///< stored_type_name(): "float32", "enum int8", "string", ...
  std::optional<Dtype> dtype;        ///< set when the stored type is exactly one of Dtype
  bool is_enum = false;              ///< an HDF5 enum type
  Shape shape;                       ///< extents
  Shape chunk_shape;                 ///< empty when not chunked
  std::vector<std::string> filters;  ///< e.g. {"shuffle", "deflate(4)"}
};

/// Describes the dataset `path`; throws bad_input if it is missing.
DatasetInfo dataset_info(const File& file, const std::string& path);

/// Creates the dataset `path` (and its missing parent groups) of type `stored_type` and
/// extents `shape`, and writes `values` (element_count(shape) elements of
/// `memory_type`, row-major). The typed writers below call this; enum writers too.
void write_raw_dataset(File& file, const std::string& path, hid_t stored_type, hid_t memory_type,
                       const void* values, const Shape& shape, const DatasetOptions& options);

/// Writes `values`, element_count(shape) elements in row-major order, as the dataset
/// `path` of dtype_of<T>() and extents `shape`.
template <typename T>
void write_dataset(File& file, const std::string& path, const std::vector<T>& values,
                   const Shape& shape, const DatasetOptions& options = {}) {
  if (element_count(shape) != static_cast<int64_t>(values.size())) {
    throw Error(ErrorKind::runtime, file.name(), path,
                "cannot write " + std::to_string(values.size()) + " values as shape " +
                    format_shape(shape));
  }
  write_raw_dataset(file, path, file_type(dtype_of<T>()), memory_type(dtype_of<T>()), values.data(),
                    shape, options);
}

/// Writes a 1-D dataset of #values elements.
template <typename T>
void write_vector(File& file, const std::string& path, const std::vector<T>& values,
                  const DatasetOptions& options = {}) {
  write_raw_dataset(file, path, file_type(dtype_of<T>()), memory_type(dtype_of<T>()), values.data(),
                    {static_cast<int64_t>(values.size())}, options);
}

/// Writes a row-major #rows x #cols matrix (e.g. hair::Points3f) as a 2-D dataset.
template <typename Scalar, int Cols>
void write_matrix(File& file, const std::string& path,
                  const Eigen::Matrix<Scalar, Eigen::Dynamic, Cols, Eigen::RowMajor>& matrix,
                  const DatasetOptions& options = {}) {
  write_raw_dataset(file, path, file_type(dtype_of<Scalar>()), memory_type(dtype_of<Scalar>()),
                    matrix.data(), {matrix.rows(), matrix.cols()}, options);
}

/// Reads the dataset `path` of any rank. Throws bad_input naming the file and dataset if
/// it is missing or its stored type is not exactly dtype_of<T>()
/// ("strands.h5:/strands/points: expected float32, found float64").
template <typename T>
Array<T> read_array(const File& file, const std::string& path);

/// Reads a 1-D dataset; other ranks are a bad_input error.
template <typename T>
std::vector<T> read_vector(const File& file, const std::string& path) {
  Array<T> array = read_array<T>(file, path);
  if (array.shape.size() != 1) {
    throw Error::bad_dataset(file.name(), path,
                             "expected shape [n], found " + format_shape(array.shape));
  }
  return std::move(array.values);
}

/// Reads a 2-D dataset as a row-major #rows x Cols matrix (Cols may be Eigen::Dynamic);
/// another rank or column count is a bad_input error.
template <typename Scalar, int Cols>
Eigen::Matrix<Scalar, Eigen::Dynamic, Cols, Eigen::RowMajor> read_matrix(const File& file,
                                                                         const std::string& path) {
  const Array<Scalar> array = read_array<Scalar>(file, path);
  if (array.shape.size() != 2 || (Cols != Eigen::Dynamic && array.shape[1] != Cols)) {
    const std::string expected =
        Cols == Eigen::Dynamic ? "[n, m]" : "[n, " + std::to_string(Cols) + "]";
    throw Error::bad_dataset(file.name(), path,
                             "expected shape " + expected + ", found " + format_shape(array.shape));
  }
  using Matrix = Eigen::Matrix<Scalar, Eigen::Dynamic, Cols, Eigen::RowMajor>;
  return Eigen::Map<const Matrix>(array.values.data(), array.shape[0], array.shape[1]);
}

}  // namespace hair::h5
