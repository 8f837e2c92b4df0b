#include "hair/h5/strand_set_io.h"

#include <type_traits>

#include "hair/core/error.h"
#include "hair/h5/dataset.h"

namespace hair::h5 {

namespace {

void write_columns(File& file, const std::string& group_path,
                   const std::map<std::string, AttributeColumn>& columns) {
  for (const auto& [name, column] : columns) {
    const std::string path = child_path(group_path, name);
    std::visit(
        [&](const auto& values) {
          using Column = std::decay_t<decltype(values)>;
          if constexpr (std::is_same_v<Column, Points3f>)
            write_matrix(file, path, values);
          else
            write_vector(file, path, values);
        },
        column);
  }
}

/// Reads the columns of `group_path` (none if the group is missing), checking that each
/// has `expected_length` rows.
std::map<std::string, AttributeColumn> read_columns(const File& file, const std::string& group_path,
                                                    int64_t expected_length,
                                                    const std::string& length_name) {
  std::map<std::string, AttributeColumn> columns;
  if (file.kind_of(group_path) != ObjectKind::group) return columns;
  for (const std::string& name : file.member_names(group_path)) {
    const std::string path = child_path(group_path, name);
    const DatasetInfo info = dataset_info(file, path);
    const Shape& shape = info.shape;
    if (info.dtype == Dtype::int32 && shape.size() == 1) {
      columns[name] = read_vector<int32_t>(file, path);
    } else if (info.dtype == Dtype::float32 && shape.size() == 1) {
      columns[name] = read_vector<float>(file, path);
    } else if (info.dtype == Dtype::float32 && shape.size() == 2 && shape[1] == 3) {
      columns[name] = read_matrix<float, 3>(file, path);
    } else {
      throw Error::bad_dataset(file.name(), path,
                               "expected int32 [n], float32 [n] or float32 [n, 3], found " +
                                   info.type_name + " " + format_shape(shape));
    }
    if (shape[0] != expected_length) {
      throw Error::bad_dataset(file.name(), path,
                               "expected " + std::to_string(expected_length) + " rows (" +
                                   length_name + "), found " + std::to_string(shape[0]));
    }
  }
  return columns;
}

/// Throws bad_input unless `offsets` start at 0, never decrease and end at `point_count`.
void check_offsets(const std::vector<int64_t>& offsets, int64_t point_count, const File& file,
                   const std::string& path) {
  if (offsets.empty() || offsets.front() != 0) {
    throw Error::bad_dataset(file.name(), path, "expected CSR offsets starting at 0");
  }
  for (size_t index = 1; index < offsets.size(); ++index) {
    if (offsets[index] < offsets[index - 1]) {
      throw Error::bad_dataset(file.name(), path,
                               "expected non-decreasing CSR offsets, found " +
                                   std::to_string(offsets[index]) + " after " +
                                   std::to_string(offsets[index - 1]) + " at [" +
                                   std::to_string(index) + "]");
    }
  }
  if (offsets.back() != point_count) {
    throw Error::bad_dataset(
        file.name(), path,
        "expected CSR offsets ending at #points = " + std::to_string(point_count) + ", found " +
            std::to_string(offsets.back()));
  }
}

}  // namespace

void write_strand_set(File& file, const std::string& group_path, const StrandSet& strands) {
  file.create_group(group_path);
  write_matrix(file, child_path(group_path, "points"), strands.points);
  write_vector(file, child_path(group_path, "offsets"), strands.offsets);
  write_columns(file, child_path(group_path, "strand_attributes"), strands.strand_attributes);
  write_columns(file, child_path(group_path, "point_attributes"), strands.point_attributes);
}

StrandSet read_strand_set(const File& file, const std::string& group_path) {
  StrandSet strands;
  strands.points = read_matrix<float, 3>(file, child_path(group_path, "points"));
  strands.offsets = read_vector<int64_t>(file, child_path(group_path, "offsets"));
  check_offsets(strands.offsets, strands.point_count(), file, child_path(group_path, "offsets"));
  strands.strand_attributes = read_columns(file, child_path(group_path, "strand_attributes"),
                                           strands.strand_count(), "#strands");
  strands.point_attributes = read_columns(file, child_path(group_path, "point_attributes"),
                                          strands.point_count(), "#points");
  return strands;
}

}  // namespace hair::h5
