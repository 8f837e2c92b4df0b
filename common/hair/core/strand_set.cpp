#include "hair/core/strand_set.h"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "hair/core/error.h"

namespace hair {
namespace {

int64_t column_length(const AttributeColumn& column) {
  return std::visit(
      [](const auto& values) -> int64_t {
        if constexpr (std::is_same_v<std::decay_t<decltype(values)>, Points3f>) {
          return values.rows();
        } else {
          return static_cast<int64_t>(values.size());
        }
      },
      column);
}

void check_column_lengths(const std::map<std::string, AttributeColumn>& columns, const char* kind,
                          const char* count_name, int64_t expected_length) {
  for (const auto& [name, column] : columns) {
    const int64_t length = column_length(column);
    if (length != expected_length) {
      throw Error::runtime("", fmt::format("{} attribute '{}' has {} entries, expected {} = {}",
                                           kind, name, length, count_name, expected_length));
    }
  }
}

}  // namespace

StrandSet strand_set_from_polylines(const std::vector<Points3f>& polylines) {
  StrandSet strands;
  strands.offsets.reserve(polylines.size() + 1);
  int64_t total = 0;
  for (const Points3f& polyline : polylines) strands.offsets.push_back(total += polyline.rows());
  strands.points.resize(total, 3);
  for (size_t s = 0; s < polylines.size(); ++s)
    strands.points.middleRows(strands.offsets[s], polylines[s].rows()) = polylines[s];
  return strands;
}

// Each append copies every point (an Eigen matrix has no spare capacity): fine for
// building small sets; bulk builders size `points` and `offsets` once and fill them.
void StrandSet::append_strand(const Points3f& strand_points) {
  const int64_t first_row = points.rows();
  points.conservativeResize(first_row + strand_points.rows(), Eigen::NoChange);
  points.middleRows(first_row, strand_points.rows()) = strand_points;
  offsets.push_back(first_row + strand_points.rows());
}

void check_strand_set(const StrandSet& strands, int min_points_per_strand) {
  const auto fail = [](const std::string& reason) { throw Error::runtime("", reason); };
  const auto& offsets = strands.offsets;
  if (offsets.empty()) fail("offsets is empty, expected #strands + 1 entries starting at 0");
  if (offsets.front() != 0) fail(fmt::format("offsets[0] = {}, expected 0", offsets.front()));
  for (size_t strand = 0; strand + 1 < offsets.size(); ++strand) {
    if (offsets[strand + 1] < offsets[strand]) {
      fail(fmt::format("offsets decrease at strand {} ({} then {})", strand, offsets[strand],
                       offsets[strand + 1]));
    }
  }
  if (offsets.back() != strands.point_count()) {
    fail(fmt::format("offsets end at {}, expected #points = {}", offsets.back(),
                     strands.point_count()));
  }
  for (int64_t strand = 0; strand < strands.strand_count(); ++strand) {
    const int64_t size = strands.strand_size(strand);
    if (size < min_points_per_strand) {
      fail(fmt::format("strand {} has {} point{}, expected at least {}", strand, size,
                       size == 1 ? "" : "s", min_points_per_strand));
    }
    for (int64_t row = offsets[strand]; row < offsets[strand + 1]; ++row) {
      if (!strands.points.row(row).allFinite()) {
        const auto point = strands.points.row(row);
        fail(fmt::format("strand {} point {} is not finite ({}, {}, {})", strand,
                         row - offsets[strand], point.x(), point.y(), point.z()));
      }
    }
  }
  check_column_lengths(strands.strand_attributes, "strand", "#strands", strands.strand_count());
  check_column_lengths(strands.point_attributes, "point", "#points", strands.point_count());
}

}  // namespace hair
