#include "hair/extract/group_sense.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <type_traits>
#include <variant>
#include <vector>

#include "hair/geom/point_index.h"

namespace hair {
namespace {

/// A group's segments: midpoints (indexed), unit directions and the strand each is of.
struct GroupSegments {
  std::vector<Eigen::Vector3f> direction;
  std::vector<int64_t> owner;
  std::optional<PointIndex> index;
};

GroupSegments group_segments(const StrandSet& strands, std::span<const int64_t> group) {
  GroupSegments segments;
  std::vector<Eigen::Vector3f> midpoints;
  for (int64_t s : group)
    for (int64_t row = strands.offsets[static_cast<size_t>(s)] + 1;
         row < strands.offsets[static_cast<size_t>(s) + 1]; ++row) {
      const Eigen::Vector3f segment =
          (strands.points.row(row) - strands.points.row(row - 1)).transpose();
      if (!(segment.norm() > 0)) continue;
      segments.direction.push_back(segment.normalized());
      midpoints.push_back(0.5f *
                          (strands.points.row(row) + strands.points.row(row - 1)).transpose());
      segments.owner.push_back(s);
    }
  if (midpoints.empty()) return segments;
  Points3f rows(static_cast<Eigen::Index>(midpoints.size()), 3);
  for (size_t k = 0; k < midpoints.size(); ++k)
    rows.row(static_cast<Eigen::Index>(k)) = midpoints[k].transpose();
  segments.index.emplace(rows);
  return segments;
}

double mean_cosine(const StrandSet& strands, const GroupSegments& segments, int64_t s,
                   const GroupSenseParams& params, int& judged) {
  judged = 0;
  if (!segments.index) return 0;
  double sum = 0;
  std::vector<int64_t> seen;
  for (int64_t row = strands.offsets[static_cast<size_t>(s)] + 1;
       row < strands.offsets[static_cast<size_t>(s) + 1]; ++row) {
    const Eigen::Vector3f segment =
        (strands.points.row(row) - strands.points.row(row - 1)).transpose();
    if (!(segment.norm() > 0)) continue;
    const Eigen::Vector3f midpoint =
        0.5f * (strands.points.row(row) + strands.points.row(row - 1)).transpose();
    const Eigen::Vector3f direction = segment.normalized();
    seen.clear();
    double cosine_sum = 0;
    int along = 0;  // neighbours running along the same axis
    segments.index->visit_within(midpoint, static_cast<float>(params.radius_m), [&](int32_t id) {
      const int64_t other = segments.owner[static_cast<size_t>(id)];
      if (other == s || std::find(seen.begin(), seen.end(), other) != seen.end()) return true;
      seen.push_back(other);  // its nearest segment: ids come nearest first
      const double cosine = direction.dot(segments.direction[static_cast<size_t>(id)]);
      if (std::abs(cosine) >= params.min_axis_cosine) cosine_sum += cosine, ++along;
      return static_cast<int>(seen.size()) < params.neighbours;
    });
    if (along == 0) continue;
    sum += cosine_sum / along;
    ++judged;
  }
  return judged > 0 ? sum / judged : 0.0;
}

/// Reverses strand `s`'s points and point attributes in place.
void reverse_strand(StrandSet& strands, int64_t s) {
  const int64_t first = strands.offsets[static_cast<size_t>(s)];
  const int64_t count = strands.strand_size(s);
  strands.points.middleRows(first, count) =
      strands.points.middleRows(first, count).colwise().reverse().eval();
  for (auto& [name, column] : strands.point_attributes)
    std::visit(
        [&](auto& values) {
          using Column = std::decay_t<decltype(values)>;
          if constexpr (std::is_same_v<Column, Points3f>) {
            values.middleRows(first, count) =
                values.middleRows(first, count).colwise().reverse().eval();
          } else {
            std::reverse(values.begin() + first, values.begin() + first + count);
          }
        },
        column);
}

}  // namespace

double mean_cosine_with_group(const StrandSet& strands, std::span<const int64_t> group, int64_t s,
                              const GroupSenseParams& params, int& judged) {
  return mean_cosine(strands, group_segments(strands, group), s, params, judged);
}

int64_t turn_strands_against_their_group(StrandSet& strands,
                                         std::span<const int32_t> group_first_strand,
                                         const GroupSenseParams& params) {
  int64_t turned = 0;
  for (size_t g = 0; g + 1 < group_first_strand.size(); ++g) {
    std::vector<int64_t> group;
    for (int64_t s = group_first_strand[g]; s < group_first_strand[g + 1]; ++s) group.push_back(s);
    if (group.size() < 3) continue;                   // two strands: no majority
    std::vector<bool> reversed(group.size(), false);  // each strand: turned an odd number of times
    for (int round = 0; round < params.max_rounds; ++round) {
      const GroupSegments segments = group_segments(strands, group);
      std::vector<int64_t> against;
      for (int64_t s : group) {
        int judged = 0;
        const double cosine = mean_cosine(strands, segments, s, params, judged);
        if (judged >= params.min_judged && cosine <= -params.min_mean_cosine) against.push_back(s);
      }
      if (against.empty()) break;
      for (int64_t s : against) {
        reverse_strand(strands, s);
        reversed[static_cast<size_t>(s - group.front())] =
            !reversed[static_cast<size_t>(s - group.front())];
      }
    }
    turned += std::count(reversed.begin(), reversed.end(), true);
  }
  return turned;
}

}  // namespace hair
