#include "hair/core/error.h"
#include "hair/h5/attribute.h"
#include "hair/h5/dataset.h"
#include "hair/h5/file.h"
#include "hair/h5/strand_set_io.h"
#include "unit/test_h5_support.h"

namespace hair::h5 {
namespace {

using H5StrandSetTest = testing::TemporaryDirectoryTest;

/// Three strands of 2, 3 and 4 points with one column of every kind.
StrandSet sample_strands() {
  StrandSet strands;
  strands.points.resize(9, 3);
  for (int row = 0; row < 9; ++row) strands.points.row(row) << row * 0.01f, 1.0f - row * 0.1f, 0.5f;
  strands.offsets = {0, 2, 5, 9};
  strands.strand_attributes["group"] = std::vector<int32_t>{0, 0, 1};
  strands.strand_attributes["thickness"] = std::vector<float>{0.1f, 0.2f, 0.3f};
  Points3f root_normals = Points3f::Zero(3, 3);
  root_normals.col(1).setOnes();
  strands.strand_attributes["root_normal"] = root_normals;
  strands.point_attributes["source_vertex"] = std::vector<int32_t>{0, 1, 2, 3, 4, 5, 6, 7, 8};
  return strands;
}

TEST_F(H5StrandSetTest, RoundTripKeepsPointsOffsetsAndEveryColumn) {
  const StrandSet strands = sample_strands();
  {
    File file = File::create(path("strands.h5"));
    write_strand_set(file, "/strands", strands);
    file.close();
  }
  const File file = File::open_read_only(path("strands.h5"));
  EXPECT_EQ(file.kind_of("/strands/strand_attributes/group"), ObjectKind::dataset);
  EXPECT_EQ(file.kind_of("/strands/point_attributes/source_vertex"), ObjectKind::dataset);
  EXPECT_EQ(dataset_info(file, "/strands/points").type_name, "float32");
  EXPECT_EQ(dataset_info(file, "/strands/offsets").type_name, "int64");
  const StrandSet read = read_strand_set(file, "/strands");
  EXPECT_TRUE((read.points == strands.points));
  EXPECT_EQ(read.offsets, strands.offsets);
  EXPECT_EQ(read.strand_attributes, strands.strand_attributes);
  EXPECT_EQ(read.point_attributes, strands.point_attributes);
}

TEST_F(H5StrandSetTest, StrandSetWithoutColumnsAtTheRoot) {
  StrandSet strands;
  strands.points = Points3f::Ones(4, 3);
  strands.offsets = {0, 4};
  {
    File file = File::create(path("plain.h5"));
    write_strand_set(file, "/", strands);
    file.close();
  }
  const StrandSet read = read_strand_set(File::open_read_only(path("plain.h5")), "/");
  EXPECT_EQ(read.strand_count(), 1);
  EXPECT_TRUE(read.strand_attributes.empty());
}

TEST_F(H5StrandSetTest, BadOffsetsAreReported) {
  File file = File::create(path("bad.h5"), "bad.h5");
  write_matrix(file, "/s/points", Points3f::Zero(5, 3).eval());
  write_vector<int64_t>(file, "/s/offsets", {0, 3, 2, 5});
  try {
    read_strand_set(file, "/s");
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::bad_input);
    EXPECT_EQ(error.dataset(), "/s/offsets");
    EXPECT_NE(error.reason().find("non-decreasing"), std::string::npos) << error.reason();
  }
  File short_file = File::create(path("short.h5"), "short.h5");
  write_matrix(short_file, "/s/points", Points3f::Zero(5, 3).eval());
  write_vector<int64_t>(short_file, "/s/offsets", {0, 3, 4});
  try {
    read_strand_set(short_file, "/s");
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_STREQ(error.what(),
                 "short.h5:/s/offsets: expected CSR offsets ending at #points = 5, found 4");
  }
}

TEST_F(H5StrandSetTest, ColumnOfTheWrongLengthOrTypeIsReported) {
  StrandSet strands = sample_strands();
  {
    File file = File::create(path("length.h5"), "length.h5");
    write_strand_set(file, "/strands", strands);
    write_vector<int32_t>(file, "/strands/point_attributes/extra", {1, 2});
    EXPECT_THROW(read_strand_set(file, "/strands"), Error);
  }
  File file = File::create(path("type.h5"), "type.h5");
  write_strand_set(file, "/strands", strands);
  write_vector<double>(file, "/strands/strand_attributes/weight", {1, 2, 3});
  try {
    read_strand_set(file, "/strands");
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_EQ(error.dataset(), "/strands/strand_attributes/weight");
    EXPECT_NE(error.reason().find("found float64 [3]"), std::string::npos) << error.reason();
  }
}

}  // namespace
}  // namespace hair::h5
