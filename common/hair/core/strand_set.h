#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <map>
#include <string>
#include <variant>
#include <vector>

namespace hair {

/// Row-major n x 3 float32 positions, the layout of HDF5 `points` datasets.
using Points3f = Eigen::Matrix<float, Eigen::Dynamic, 3, Eigen::RowMajor>;

/// Row `row` of `points` in double precision, as the algorithms compute.
inline Eigen::Vector3d point_of(const Points3f& points, int64_t row) {
  return points.row(row).cast<double>().transpose();
}

/// A column of per-strand or per-point values.
using AttributeColumn = std::variant<std::vector<int32_t>, std::vector<float>, Points3f>;

/// A set of polyline strands in CSR layout (DESIGN.md, data conventions):
/// `points` holds every point, root first within each strand; strand s owns rows
/// [offsets[s], offsets[s+1]). offsets has strand_count()+1 entries, starts at 0,
/// never decreases and ends at points.rows(). Attributes are named columns with one
/// entry per strand or per point.
struct StrandSet {
  Points3f points;                                           ///< #points x 3, metres
  std::vector<int64_t> offsets{0};                           ///< #strands + 1
  std::map<std::string, AttributeColumn> strand_attributes;  ///< each #strands long
  std::map<std::string, AttributeColumn> point_attributes;   ///< each #points long

  int64_t strand_count() const { return static_cast<int64_t>(offsets.size()) - 1; }
  int64_t point_count() const { return points.rows(); }
  int64_t strand_size(int64_t strand) const { return offsets[strand + 1] - offsets[strand]; }

  /// Read-only view of one strand's points, #strand_size x 3.
  auto strand(int64_t s) const { return points.middleRows(offsets[s], strand_size(s)); }
  auto strand(int64_t s) { return points.middleRows(offsets[s], strand_size(s)); }

  /// Appends a strand (#n x 3 rows, root first); attributes must be filled by the caller.
  void append_strand(const Points3f& strand_points);
};

/// A strand set of `polylines` (each #n x 3, root first), built in one allocation;
/// prefer it to repeated append_strand() for more than a few strands.
StrandSet strand_set_from_polylines(const std::vector<Points3f>& polylines);

/// Throws hair::Error (runtime) naming the first violation: offsets not starting at 0,
/// decreasing, not ending at #points; a strand with fewer than `min_points_per_strand`
/// points; a non-finite coordinate (names the strand); an attribute of the wrong length.
void check_strand_set(const StrandSet& strands, int min_points_per_strand = 2);

}  // namespace hair
