#include "hair/geom/strand_geometry.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "hair/core/error.h"

namespace hair {
namespace {

/// Fewer strands than this are processed on one thread: starting threads costs more.
constexpr int64_t kParallelStrandCount = 64;

/// Where one resampled point lies on the original strand: between rows `from_row` and
/// `to_row` of the original points, `to_weight` of the way (0: at from_row).
struct ArcSample {
  int64_t from_row;
  int64_t to_row;
  double to_weight;
};

Eigen::Vector3d point_at(const StrandSet& strands, int64_t row) {
  return strands.points.row(row).transpose().cast<double>();
}

/// Arc length from the root to each point of strand `strand`, metres: #points of the strand.
void cumulative_arc_length(const StrandSet& strands, int64_t strand, std::vector<double>& arc_m) {
  const int64_t first_row = strands.offsets[strand];
  const int64_t size = strands.strand_size(strand);
  arc_m.resize(static_cast<size_t>(size));
  double length_m = 0.0;
  for (int64_t index = 0; index < size; ++index) {
    if (index > 0) {
      length_m +=
          (point_at(strands, first_row + index) - point_at(strands, first_row + index - 1)).norm();
    }
    arc_m[static_cast<size_t>(index)] = length_m;
  }
}

/// `count` (>= 2) samples uniform in arc length over a strand whose points start at
/// `first_row` and whose cumulative arc lengths are `arc_m`. The first sample is the root
/// and the last the tip, exactly; zero-length segments are stepped over.
void uniform_arc_samples(const std::vector<double>& arc_m, int64_t first_row, int64_t count,
                         std::vector<ArcSample>& samples) {
  const auto size = static_cast<int64_t>(arc_m.size());
  samples.resize(static_cast<size_t>(count));
  if (size == 1) {
    std::fill(samples.begin(), samples.end(), ArcSample{first_row, first_row, 0.0});
    return;
  }
  const double length_m = arc_m.back();
  int64_t segment = 0;  // from point `segment` to point `segment + 1`
  for (int64_t index = 0; index < count; ++index) {
    const double target_m = length_m * static_cast<double>(index) / static_cast<double>(count - 1);
    while (segment + 2 < size && arc_m[static_cast<size_t>(segment + 1)] <= target_m) ++segment;
    const double start_m = arc_m[static_cast<size_t>(segment)];
    const double segment_m = arc_m[static_cast<size_t>(segment + 1)] - start_m;
    const double weight =
        segment_m > 0.0 ? std::clamp((target_m - start_m) / segment_m, 0.0, 1.0) : 0.0;
    samples[static_cast<size_t>(index)] = {first_row + segment, first_row + segment + 1, weight};
  }
  samples.front() = {first_row, first_row + 1, 0.0};
  samples.back() = {first_row + size - 2, first_row + size - 1, 1.0};
}

/// An empty column of the same kind as `column`, `length` entries long.
AttributeColumn sized_like(const AttributeColumn& column, int64_t length) {
  return std::visit(
      [length](const auto& values) -> AttributeColumn {
        using Values = std::decay_t<decltype(values)>;
        if constexpr (std::is_same_v<Values, Points3f>) {
          return Points3f(length, 3);
        } else {
          return Values(static_cast<size_t>(length));
        }
      },
      column);
}

/// Writes the values of `source` (one per original point) at `samples` into `target`
/// from row `first_target_row` on: linear for float and Points3f, nearest for int.
void resample_column(const AttributeColumn& source, const std::vector<ArcSample>& samples,
                     int64_t first_target_row, AttributeColumn& target) {
  std::visit(
      [&](const auto& source_values) {
        using Values = std::decay_t<decltype(source_values)>;
        auto& target_values = std::get<Values>(target);
        for (size_t index = 0; index < samples.size(); ++index) {
          const ArcSample& sample = samples[index];
          const int64_t row = first_target_row + static_cast<int64_t>(index);
          if constexpr (std::is_same_v<Values, Points3f>) {
            const Eigen::RowVector3d from =
                source_values.row(sample.from_row).template cast<double>();
            const Eigen::RowVector3d to = source_values.row(sample.to_row).template cast<double>();
            target_values.row(row) =
                ((1.0 - sample.to_weight) * from + sample.to_weight * to).template cast<float>();
          } else if constexpr (std::is_same_v<Values, std::vector<float>>) {
            const double from = source_values[static_cast<size_t>(sample.from_row)];
            const double to = source_values[static_cast<size_t>(sample.to_row)];
            target_values[static_cast<size_t>(row)] =
                static_cast<float>((1.0 - sample.to_weight) * from + sample.to_weight * to);
          } else {
            const int64_t nearest = sample.to_weight <= 0.5 ? sample.from_row : sample.to_row;
            target_values[static_cast<size_t>(row)] = source_values[static_cast<size_t>(nearest)];
          }
        }
      },
      source);
}

/// `strands` with strand s resampled to `point_counts[s]` (>= 2) points, uniform in arc
/// length, attributes carried over.
StrandSet resampled(const StrandSet& strands, const std::vector<int64_t>& point_counts) {
  const int64_t strand_count = strands.strand_count();
  StrandSet output;
  output.offsets.resize(static_cast<size_t>(strand_count) + 1);
  for (int64_t strand = 0; strand < strand_count; ++strand) {
    output.offsets[static_cast<size_t>(strand) + 1] =
        output.offsets[static_cast<size_t>(strand)] + point_counts[static_cast<size_t>(strand)];
  }
  const int64_t point_count = output.offsets.back();
  output.points.resize(point_count, 3);
  output.strand_attributes = strands.strand_attributes;
  std::vector<std::pair<const AttributeColumn*, AttributeColumn*>> point_columns;
  for (const auto& [name, column] : strands.point_attributes) {
    auto [slot, inserted] = output.point_attributes.emplace(name, sized_like(column, point_count));
    point_columns.emplace_back(&column, &slot->second);
  }

#pragma omp parallel if (strand_count >= kParallelStrandCount)
  {
    std::vector<double> arc_m;
    std::vector<ArcSample> samples;
#pragma omp for schedule(dynamic, 64)
    for (int64_t strand = 0; strand < strand_count; ++strand) {
      cumulative_arc_length(strands, strand, arc_m);
      uniform_arc_samples(arc_m, strands.offsets[static_cast<size_t>(strand)],
                          point_counts[static_cast<size_t>(strand)], samples);
      const int64_t first_row = output.offsets[static_cast<size_t>(strand)];
      for (size_t index = 0; index < samples.size(); ++index) {
        const ArcSample& sample = samples[index];
        const Eigen::Vector3d position =
            (1.0 - sample.to_weight) * point_at(strands, sample.from_row) +
            sample.to_weight * point_at(strands, sample.to_row);
        output.points.row(first_row + static_cast<int64_t>(index)) =
            position.transpose().cast<float>();
      }
      for (const auto& [source, target] : point_columns) {
        resample_column(*source, samples, first_row, *target);
      }
    }
  }
  return output;
}

/// strand_lengths in double precision.
std::vector<double> strand_lengths_double(const StrandSet& strands) {
  const int64_t strand_count = strands.strand_count();
  std::vector<double> lengths_m(static_cast<size_t>(strand_count));
#pragma omp parallel for schedule(static) if (strand_count >= kParallelStrandCount)
  for (int64_t strand = 0; strand < strand_count; ++strand) {
    double length_m = 0.0;
    for (int64_t row = strands.offsets[strand] + 1; row < strands.offsets[strand + 1]; ++row) {
      length_m += (point_at(strands, row) - point_at(strands, row - 1)).norm();
    }
    lengths_m[static_cast<size_t>(strand)] = length_m;
  }
  return lengths_m;
}

}  // namespace

std::vector<float> strand_lengths(const StrandSet& strands) {
  const std::vector<double> lengths_m = strand_lengths_double(strands);
  return std::vector<float>(lengths_m.begin(), lengths_m.end());
}

Points3f strand_tangents(const StrandSet& strands) {
  const int64_t strand_count = strands.strand_count();
  Points3f tangents = Points3f::Zero(strands.point_count(), 3);
#pragma omp parallel if (strand_count >= kParallelStrandCount)
  {
    std::vector<Eigen::Vector3d> directions;  // of the segments, unit or zero
    std::vector<bool> has_length;             // per segment
#pragma omp for schedule(static)
    for (int64_t strand = 0; strand < strand_count; ++strand) {
      const int64_t first_row = strands.offsets[strand];
      const int64_t size = strands.strand_size(strand);
      if (size < 2) continue;
      const auto segment_count = static_cast<size_t>(size - 1);
      directions.assign(segment_count, Eigen::Vector3d::Zero());
      has_length.assign(segment_count, false);
      for (size_t segment = 0; segment < segment_count; ++segment) {
        const int64_t row = first_row + static_cast<int64_t>(segment);
        const Eigen::Vector3d step = point_at(strands, row + 1) - point_at(strands, row);
        const double length_m = step.norm();
        if (length_m > 0.0) {
          directions[segment] = step / length_m;
          has_length[segment] = true;
        }
      }
      const auto first_with_length = std::find(has_length.begin(), has_length.end(), true);
      if (first_with_length == has_length.end()) continue;  // all points coincide
      // Zero-length segments take the nearest earlier direction (the first one before it).
      Eigen::Vector3d last_direction =
          directions[static_cast<size_t>(first_with_length - has_length.begin())];
      for (size_t segment = 0; segment < segment_count; ++segment) {
        if (has_length[segment]) {
          last_direction = directions[segment];
        } else {
          directions[segment] = last_direction;
        }
      }
      tangents.row(first_row) = directions.front().transpose().cast<float>();
      tangents.row(first_row + size - 1) = directions.back().transpose().cast<float>();
      for (size_t point = 1; point + 1 < static_cast<size_t>(size); ++point) {
        const Eigen::Vector3d sum = directions[point - 1] + directions[point];
        const double norm = sum.norm();
        const Eigen::Vector3d tangent =
            norm > 1e-9 ? Eigen::Vector3d(sum / norm) : directions[point - 1];
        tangents.row(first_row + static_cast<int64_t>(point)) = tangent.transpose().cast<float>();
      }
    }
  }
  return tangents;
}

StrandSet resample_by_count(const StrandSet& strands, int points_per_strand) {
  if (points_per_strand < 2) {
    throw Error::usage(fmt::format("points_per_strand = {} must be at least 2", points_per_strand));
  }
  check_strand_set(strands, 1);
  return resampled(strands, std::vector<int64_t>(static_cast<size_t>(strands.strand_count()),
                                                 points_per_strand));
}

StrandSet resample_by_spacing(const StrandSet& strands, float spacing_m) {
  if (!(spacing_m > 0.0f) || !std::isfinite(spacing_m)) {
    throw Error::usage(fmt::format("spacing_m = {} must be positive and finite", spacing_m));
  }
  check_strand_set(strands, 1);
  constexpr double kMaxSegments = 1e9;
  constexpr double kRoundingTolerance = 1e-6;  // relative, on length / spacing
  const std::vector<double> lengths_m = strand_lengths_double(strands);
  std::vector<int64_t> point_counts(lengths_m.size());
  for (size_t strand = 0; strand < lengths_m.size(); ++strand) {
    const double segments = lengths_m[strand] / static_cast<double>(spacing_m);
    if (segments > kMaxSegments) {
      throw Error::usage(fmt::format("spacing_m = {} gives strand {} ({} m long) over {} points",
                                     spacing_m, strand, lengths_m[strand], kMaxSegments));
    }
    const auto whole_segments =
        static_cast<int64_t>(std::ceil(segments * (1.0 - kRoundingTolerance)));
    point_counts[strand] = std::max<int64_t>(2, whole_segments + 1);
  }
  return resampled(strands, point_counts);
}

}  // namespace hair
