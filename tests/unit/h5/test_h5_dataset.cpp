#include <fstream>
#include <iterator>
#include <limits>
#include <numeric>
#include <random>
#include <type_traits>

#include "hair/core/error.h"
#include "hair/core/strand_set.h"
#include "hair/h5/dataset.h"
#include "hair/h5/file.h"
#include "unit/test_h5_support.h"

namespace hair::h5 {
namespace {

using H5DatasetTest = testing::TemporaryDirectoryTest;

/// Values 0, 1, 2, ... wrapped to T's range, with a negative one for signed types.
template <typename T>
std::vector<T> sample_values(size_t count) {
  std::vector<T> values(count);
  for (size_t index = 0; index < count; ++index) values[index] = static_cast<T>(index % 100);
  if constexpr (std::numeric_limits<T>::is_signed) values.back() = static_cast<T>(-7);
  return values;
}

template <typename T>
class H5DtypeRoundTrip : public testing::TemporaryDirectoryTest {};

using ElementTypes = ::testing::Types<float, double, int8_t, uint8_t, int32_t, int64_t>;
TYPED_TEST_SUITE(H5DtypeRoundTrip, ElementTypes);

TYPED_TEST(H5DtypeRoundTrip, OneAndTwoDimensionalArraysReadBackExactly) {
  const std::vector<TypeParam> vector = sample_values<TypeParam>(17);
  const std::vector<TypeParam> table = sample_values<TypeParam>(12);
  {
    File file = File::create(this->path("types.h5"));
    write_vector(file, "/v", vector);
    write_dataset(file, "/group/t", table, {4, 3});
    file.close();
  }
  const File file = File::open_read_only(this->path("types.h5"));
  EXPECT_EQ(read_vector<TypeParam>(file, "/v"), vector);
  const Array<TypeParam> array = read_array<TypeParam>(file, "/group/t");
  EXPECT_EQ(array.shape, (Shape{4, 3}));
  EXPECT_EQ(array.values, table);
  const DatasetInfo info = dataset_info(file, "/group/t");
  EXPECT_EQ(info.dtype, dtype_of<TypeParam>());
  EXPECT_EQ(info.type_name, dtype_name(dtype_of<TypeParam>()));
}

TYPED_TEST(H5DtypeRoundTrip, ChunkedArraysReadBackExactly) {
  // Several chunks of rows and a part-filled last one, compressed by us
  // (chunk_compression.h) and read back through HDF5's own filters: random values,
  // whose low byte planes are stored, and a slow ramp, which deflates.
  const int64_t rows = 3 * kTargetChunkBytes / static_cast<int64_t>(3 * sizeof(TypeParam)) + 123;
  std::vector<TypeParam> noise(static_cast<size_t>(rows * 3)), ramp(noise.size());
  std::mt19937_64 random(11);
  for (size_t i = 0; i < noise.size(); ++i) {
    if constexpr (std::is_floating_point_v<TypeParam>)
      noise[i] = static_cast<TypeParam>(std::uniform_real_distribution<double>(-3, 3)(random));
    else
      noise[i] = static_cast<TypeParam>(random());
    ramp[i] = static_cast<TypeParam>(i / 1000);
  }
  {
    File file = File::create(this->path("chunked.h5"));
    write_dataset(file, "/noise", noise, {rows, 3});
    write_dataset(file, "/ramp", ramp, {rows * 3});
    file.close();
  }
  const File file = File::open_read_only(this->path("chunked.h5"));
  const Array<TypeParam> read_noise = read_array<TypeParam>(file, "/noise");
  EXPECT_EQ(read_noise.shape, (Shape{rows, 3}));
  EXPECT_TRUE(read_noise.values == noise);
  EXPECT_TRUE(read_array<TypeParam>(file, "/ramp").values == ramp);
  const DatasetInfo info = dataset_info(file, "/noise");
  EXPECT_EQ(info.filters, (std::vector<std::string>{"shuffle", "deflate(4)"}));
  EXPECT_LT(info.chunk_shape[0], rows);
  const double raw = static_cast<double>(noise.size() * sizeof(TypeParam));
  EXPECT_LT(static_cast<double>(H5Dget_storage_size(file.open_dataset("/noise").get())),
            1.01 * raw);
  EXPECT_LT(static_cast<double>(H5Dget_storage_size(file.open_dataset("/ramp").get())),
            0.05 * raw);
}

TEST_F(H5DatasetTest, EigenMatricesRoundTrip) {
  Points3f points(5, 3);
  for (int row = 0; row < 5; ++row) points.row(row) << row * 1.5f, -row * 0.25f, 3.0f + row;
  Eigen::Matrix<int32_t, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> triangles(2, 4);
  triangles << 0, 1, 2, 3, 4, 5, 6, 7;
  {
    File file = File::create(path("eigen.h5"));
    write_matrix(file, "/points", points);
    write_matrix(file, "/triangles", triangles);
    file.close();
  }
  const File file = File::open_read_only(path("eigen.h5"));
  EXPECT_EQ(dataset_info(file, "/points").shape, (Shape{5, 3}));
  EXPECT_TRUE((read_matrix<float, 3>(file, "/points") == points));
  EXPECT_TRUE((read_matrix<int32_t, Eigen::Dynamic>(file, "/triangles") == triangles));
  // Row-major in the file: the second stored value is the first row's y.
  EXPECT_EQ(read_array<float>(file, "/points").values[1], -0.0f);
  EXPECT_EQ(read_array<float>(file, "/points").values[4], -0.25f);
}

TEST_F(H5DatasetTest, EmptyDatasetsRoundTrip) {
  File file = File::create(path("empty.h5"));
  write_vector<int64_t>(file, "/none", {});
  write_matrix(file, "/no_points", Points3f(0, 3));
  EXPECT_TRUE(read_vector<int64_t>(file, "/none").empty());
  EXPECT_EQ((read_matrix<float, 3>(file, "/no_points").rows()), 0);
}

TEST_F(H5DatasetTest, WrongDtypeNamesExpectedAndFound) {
  File file = File::create(path("strands.h5"), "strands.h5");
  write_dataset<double>(file, "/strands/points", std::vector<double>(6, 0.0), {2, 3});
  try {
    read_matrix<float, 3>(file, "/strands/points");
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::bad_input);
    EXPECT_STREQ(error.what(), "strands.h5:/strands/points: expected float32, found float64");
  }
  write_vector<int32_t>(file, "/ids", {1, 2});
  EXPECT_THROW(read_vector<int64_t>(file, "/ids"), Error);
  EXPECT_THROW(read_vector<uint8_t>(file, "/ids"), Error);
}

TEST_F(H5DatasetTest, WrongRankOrColumnsNamesTheShape) {
  File file = File::create(path("shape.h5"), "shape.h5");
  write_dataset<float>(file, "/p", std::vector<float>(8, 0.0f), {2, 4});
  try {
    read_matrix<float, 3>(file, "/p");
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_STREQ(error.what(), "shape.h5:/p: expected shape [n, 3], found [2, 4]");
  }
  try {
    read_vector<float>(file, "/p");
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_STREQ(error.what(), "shape.h5:/p: expected shape [n], found [2, 4]");
  }
}

TEST_F(H5DatasetTest, ValueCountMustMatchShape) {
  File file = File::create(path("count.h5"));
  EXPECT_THROW(write_dataset<float>(file, "/p", std::vector<float>(5, 0.0f), {2, 3}), Error);
}

/// Layout, chunk dimensions and filter ids of a dataset, read with the HDF5 API itself.
struct StoredLayout {
  H5D_layout_t layout = H5D_LAYOUT_ERROR;
  std::vector<hsize_t> chunk;
  std::vector<H5Z_filter_t> filters;
  unsigned deflate_level = 0;
};

StoredLayout stored_layout(const std::filesystem::path& path, const char* dataset_path) {
  StoredLayout result;
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t dataset = H5Dopen2(file, dataset_path, H5P_DEFAULT);
  const hid_t properties = H5Dget_create_plist(dataset);
  result.layout = H5Pget_layout(properties);
  if (result.layout == H5D_CHUNKED) {
    result.chunk.resize(static_cast<size_t>(H5Pget_chunk(properties, 0, nullptr)));
    H5Pget_chunk(properties, static_cast<int>(result.chunk.size()), result.chunk.data());
  }
  for (int index = 0; index < H5Pget_nfilters(properties); ++index) {
    unsigned flags = 0;
    size_t value_count = 1;
    unsigned value = 0;
    const H5Z_filter_t filter = H5Pget_filter2(properties, static_cast<unsigned>(index), &flags,
                                               &value_count, &value, 0, nullptr, nullptr);
    result.filters.push_back(filter);
    if (filter == H5Z_FILTER_DEFLATE) result.deflate_level = value;
  }
  H5Pclose(properties);
  H5Dclose(dataset);
  H5Fclose(file);
  return result;
}

TEST_F(H5DatasetTest, SmallArraysAreOneChecksummedChunkLargeOnesChunkedAndCompressed) {
  Points3f large = Points3f::Zero(100000, 3);
  large.col(1).setLinSpaced(0.0f, 1.0f);
  {
    File file = File::create(path("layout.h5"));
    write_vector(file, "/small", std::vector<float>(kSingleChunkLimit, 1.0f));
    write_matrix(file, "/large", large);
    file.close();
  }
  const StoredLayout small = stored_layout(path("layout.h5"), "/small");
  EXPECT_EQ(small.layout, H5D_CHUNKED);
  EXPECT_EQ(small.chunk, (std::vector<hsize_t>{static_cast<hsize_t>(kSingleChunkLimit)}));
  EXPECT_EQ(small.filters, std::vector<H5Z_filter_t>{H5Z_FILTER_FLETCHER32});

  const StoredLayout chunked = stored_layout(path("layout.h5"), "/large");
  ASSERT_EQ(chunked.layout, H5D_CHUNKED);
  ASSERT_EQ(chunked.chunk.size(), 2u);
  const hsize_t chunk_bytes = chunked.chunk[0] * chunked.chunk[1] * sizeof(float);
  EXPECT_EQ(chunked.chunk[1], 3u);  // whole rows
  EXPECT_GE(chunk_bytes, 64u * 1024);
  EXPECT_LE(chunk_bytes, 256u * 1024);
  EXPECT_EQ(chunked.filters, (std::vector<H5Z_filter_t>{H5Z_FILTER_SHUFFLE, H5Z_FILTER_DEFLATE}));
  EXPECT_EQ(chunked.deflate_level, kDeflateLevel);

  const File file = File::open_read_only(path("layout.h5"));
  EXPECT_TRUE((read_matrix<float, 3>(file, "/large") == large));
  EXPECT_LT(std::filesystem::file_size(path("layout.h5")), 100000u * 3 * sizeof(float) / 4);
}

TEST_F(H5DatasetTest, ExplicitChunkShapeGivesOneFramePerChunk) {
  const int frames = 4;
  const int points = 50;
  std::vector<float> values(static_cast<size_t>(frames * points * 3));
  std::iota(values.begin(), values.end(), 0.0f);
  {
    File file = File::create(path("frames.h5"));
    write_dataset(file, "/frames", values, {frames, points, 3}, {.chunk_shape = {1, points, 3}});
    file.close();
  }
  const StoredLayout layout = stored_layout(path("frames.h5"), "/frames");
  ASSERT_EQ(layout.layout, H5D_CHUNKED);
  EXPECT_EQ(layout.chunk, (std::vector<hsize_t>{1, points, 3}));
  EXPECT_EQ(layout.filters.size(), 2u);
  const File file = File::open_read_only(path("frames.h5"));
  EXPECT_EQ(read_array<float>(file, "/frames").values, values);
  EXPECT_EQ(dataset_info(file, "/frames").chunk_shape, (Shape{1, points, 3}));
}

TEST_F(H5DatasetTest, ChunkShapeOfAnotherRankIsRefused) {
  File file = File::create(path("bad_chunk.h5"));
  EXPECT_THROW(write_vector(file, "/v", std::vector<float>(10, 0.0f), {.chunk_shape = {2, 2}}),
               Error);
}

TEST_F(H5DatasetTest, SameContentGivesByteIdenticalFiles) {
  const auto write = [&](const std::string& name) {
    File file = File::create(path(name));
    write_matrix(file, "/strands/points", Points3f::Ones(6000, 3).eval());
    write_vector<int64_t>(file, "/strands/offsets", {0, 3000, 6000});
    file.close();
  };
  write("first.h5");
  write("second.h5");
  std::ifstream first(path("first.h5"), std::ios::binary);
  std::ifstream second(path("second.h5"), std::ios::binary);
  const std::string first_bytes(std::istreambuf_iterator<char>(first), {});
  const std::string second_bytes(std::istreambuf_iterator<char>(second), {});
  EXPECT_EQ(first_bytes, second_bytes);
}

TEST(H5Shape, FormatsAndCounts) {
  EXPECT_EQ(format_shape({10, 3}), "[10, 3]");
  EXPECT_EQ(format_shape({}), "[]");
  EXPECT_EQ(element_count({4, 3, 2}), 24);
  EXPECT_EQ(element_count({4, 0}), 0);
}

}  // namespace
}  // namespace hair::h5
