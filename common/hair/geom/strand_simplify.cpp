#include "hair/geom/strand_simplify.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

#include "hair/core/error.h"

namespace hair {
namespace {

/// Distance of p from the segment [a, b].
double segment_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                        const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

}  // namespace

std::vector<int64_t> rows_within_tolerance(const StrandSet& strands, double tolerance_m) {
  if (!(tolerance_m >= 0) || !std::isfinite(tolerance_m))
    throw Error::usage("the tolerance must be a finite distance of at least 0, not " +
                       std::to_string(tolerance_m));
  std::vector<int64_t> rows;
  std::vector<uint8_t> keep;
  std::vector<std::pair<int64_t, int64_t>> spans;
  for (int64_t s = 0; s < strands.strand_count(); ++s) {
    const int64_t first = strands.offsets[static_cast<size_t>(s)];
    const int64_t last = strands.offsets[static_cast<size_t>(s) + 1] - 1;
    if (last < first) continue;
    keep.assign(static_cast<size_t>(last - first + 1), 0);
    keep.front() = keep.back() = 1;
    // Douglas-Peucker without recursion: a span keeps its farthest point if that lies
    // beyond the tolerance, and both halves are looked at again.
    spans.assign(1, {first, last});
    while (!spans.empty()) {
      const auto [a, b] = spans.back();
      spans.pop_back();
      if (b - a < 2) continue;
      const Eigen::Vector3d pa = point_of(strands.points, a), pb = point_of(strands.points, b);
      double farthest = -1;
      int64_t at = -1;
      for (int64_t r = a + 1; r < b; ++r) {
        const double distance = segment_distance(point_of(strands.points, r), pa, pb);
        if (distance > farthest) farthest = distance, at = r;
      }
      if (!(farthest > tolerance_m)) continue;
      keep[static_cast<size_t>(at - first)] = 1;
      spans.push_back({a, at});
      spans.push_back({at, b});
    }
    for (int64_t r = first; r <= last; ++r)
      if (keep[static_cast<size_t>(r - first)]) rows.push_back(r);
  }
  return rows;
}

double largest_deviation(const Points3f& points, const std::vector<int64_t>& rows) {
  double largest = 0;
  for (size_t k = 0; k + 1 < rows.size(); ++k) {
    const int64_t a = rows[k], b = rows[k + 1];
    if (b - a < 2) continue;
    // Every strand's root and tip are kept: a gap between kept rows lies in one strand.
    const Eigen::Vector3d pa = point_of(points, a), pb = point_of(points, b);
    for (int64_t r = a + 1; r < b; ++r)
      largest = std::max(largest, segment_distance(point_of(points, r), pa, pb));
  }
  return largest;
}

Points3f select_rows(const Points3f& points, const std::vector<int64_t>& rows) {
  Points3f selected(static_cast<Eigen::Index>(rows.size()), 3);
  for (size_t k = 0; k < rows.size(); ++k)
    selected.row(static_cast<Eigen::Index>(k)) = points.row(rows[k]);
  return selected;
}

StrandSet select_points(const StrandSet& strands, const std::vector<int64_t>& rows) {
  StrandSet selected;
  selected.points = select_rows(strands.points, rows);
  selected.offsets.assign(1, 0);
  size_t k = 0;
  for (int64_t s = 0; s < strands.strand_count(); ++s) {
    const int64_t end = strands.offsets[static_cast<size_t>(s) + 1];
    while (k < rows.size() && rows[k] < end) ++k;
    selected.offsets.push_back(static_cast<int64_t>(k));
  }
  selected.strand_attributes = strands.strand_attributes;
  for (const auto& [name, column] : strands.point_attributes)
    std::visit(
        [&](const auto& values) {
          using Column = std::decay_t<decltype(values)>;
          if constexpr (std::is_same_v<Column, Points3f>) {
            selected.point_attributes[name] = select_rows(values, rows);
          } else {
            Column kept;
            kept.reserve(rows.size());
            for (int64_t row : rows) kept.push_back(values[static_cast<size_t>(row)]);
            selected.point_attributes[name] = std::move(kept);
          }
        },
        column);
  return selected;
}

}  // namespace hair
