#include "hair/grow/surface_sampling.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <utility>

#include "hair/core/error.h"
#include "hair/geom/point_index.h"

namespace hair {
namespace {

/// At most this many candidates: ids stay far inside int32 and the neighbour lists (about
/// 4 pi / (2 sqrt 3) * candidate_factor = 18 entries a candidate for the default factor)
/// inside a few GiB.
constexpr int64_t kMaxCandidates = int64_t{1} << 26;
/// Weight limiting (Yuksel 2015): distances below 2 r_max * beta (1 - (N/M)^gamma) count as
/// that distance.
constexpr double kLimitBeta = 0.65;
constexpr double kLimitGamma = 1.5;

/// A uniform draw in [0, 1) from the top 53 bits of one output of the generator.
double uniform01(std::mt19937_64& random) {
  return static_cast<double>(random() >> 11) * 0x1.0p-53;
}

/// The selected triangles of positive area, with their running area sum for drawing a
/// triangle with probability proportional to its area.
struct Region {
  std::vector<int32_t> triangle;
  std::vector<double> cumulative_m2;  ///< one per entry of `triangle`, increasing
  double area_m2() const { return cumulative_m2.empty() ? 0.0 : cumulative_m2.back(); }
};

Eigen::Vector3d corner(const Points3f& vertices, const Triangles3i& triangles, Eigen::Index t,
                       int k) {
  return vertices.row(triangles(t, k)).cast<double>().transpose();
}

/// Checks the arguments and gathers the region; throws hair::Error (see the header).
Region selected_region(const Points3f& vertices, const Triangles3i& triangles,
                       const std::vector<uint8_t>& use_triangle, int64_t count,
                       int candidate_factor) {
  const std::string what = "surface sampling: ";
  if (count < 1)
    throw Error::usage(what + "count = " + std::to_string(count) + " must be at least 1");
  if (candidate_factor < 1)
    throw Error::usage(what + "candidate_factor = " + std::to_string(candidate_factor) +
                       " must be at least 1");
  if (count > kMaxCandidates / candidate_factor)
    throw Error::usage(what + "count = " + std::to_string(count) +
                       " times candidate_factor = " + std::to_string(candidate_factor) +
                       " is over the limit of " + std::to_string(kMaxCandidates) + " candidates");
  if (static_cast<int64_t>(use_triangle.size()) != triangles.rows())
    throw Error::usage(what + "use_triangle has " + std::to_string(use_triangle.size()) +
                       " entries for " + std::to_string(triangles.rows()) + " triangles");

  Region region;
  double area_m2 = 0;
  bool any_selected = false;
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    if (use_triangle[static_cast<size_t>(t)] == 0) continue;
    any_selected = true;
    for (int k = 0; k < 3; ++k) {
      int32_t v = triangles(t, k);
      if (v < 0 || v >= vertices.rows())
        throw Error::bad_input("", what + "triangle " + std::to_string(t) + " names vertex " +
                                       std::to_string(v) + " of " +
                                       std::to_string(vertices.rows()));
      if (!vertices.row(v).allFinite())
        throw Error::bad_input("", what + "vertex " + std::to_string(v) + " of triangle " +
                                       std::to_string(t) + " is NaN or infinite");
    }
    Eigen::Vector3d a = corner(vertices, triangles, t, 0);
    double triangle_m2 =
        0.5 *
        (corner(vertices, triangles, t, 1) - a).cross(corner(vertices, triangles, t, 2) - a).norm();
    if (!(triangle_m2 > 0)) continue;  // never drawn: skip degenerate triangles
    area_m2 += triangle_m2;
    region.triangle.push_back(static_cast<int32_t>(t));
    region.cumulative_m2.push_back(area_m2);
  }
  if (!any_selected) throw Error::bad_input("", what + "no triangle is selected");
  if (!(area_m2 > 0) || !std::isfinite(area_m2))
    throw Error::bad_input("", what + "the selected triangles have area " +
                                   std::to_string(area_m2) + " m^2 (zero or not finite)");
  return region;
}

/// `count` points drawn uniformly by area over the region; positions #count x 3 and
/// the triangle of each.
struct Candidates {
  Points3f positions;
  std::vector<int32_t> triangle;
  int64_t draws = 0;  ///< points drawn, those `accept` refused included
};

/// Draws per candidate wanted after which an acceptance that refuses them all gives up.
constexpr int64_t kMaxDrawsPerCandidate = 1000;

Candidates uniform_candidates(const Points3f& vertices, const Triangles3i& triangles,
                              const Region& region, int64_t count, uint64_t seed,
                              const SampleAcceptance& accept) {
  std::mt19937_64 random(seed);
  Candidates candidates;
  candidates.positions.resize(count, 3);
  candidates.triangle.resize(static_cast<size_t>(count));
  const double area_m2 = region.area_m2();
  for (int64_t i = 0; i < count;) {
    if (++candidates.draws > kMaxDrawsPerCandidate * count)
      throw Error::bad_input(
          "", "surface sampling: no point of the selected triangles is accepted (" +
                  std::to_string(i) + " of " + std::to_string(count) + " candidates in " +
                  std::to_string(candidates.draws - 1) + " draws)");
    double target_m2 = uniform01(random) * area_m2;
    auto entry = static_cast<size_t>(
        std::upper_bound(region.cumulative_m2.begin(), region.cumulative_m2.end(), target_m2) -
        region.cumulative_m2.begin());
    entry = std::min(entry, region.triangle.size() - 1);  // target rounded up to the total
    int32_t t = region.triangle[entry];
    // Uniform in the triangle: sqrt of one draw picks the distance from corner a.
    double s = std::sqrt(uniform01(random)), u = uniform01(random);
    Eigen::Vector3d point = (1 - s) * corner(vertices, triangles, t, 0) +
                            s * (1 - u) * corner(vertices, triangles, t, 1) +
                            s * u * corner(vertices, triangles, t, 2);
    if (accept && !accept(point, t)) continue;
    candidates.positions.row(i) = point.cast<float>().transpose();
    candidates.triangle[static_cast<size_t>(i)] = t;
    ++i;
  }
  return candidates;
}

/// Bit k of the low 21 bits of `x` moved to bit 3k (for a 3-D Morton code).
uint64_t spread_bits(uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffff;
  x = (x | x << 16) & 0x1f0000ff0000ff;
  x = (x | x << 8) & 0x100f00f00f00f00f;
  x = (x | x << 4) & 0x10c30c30c30c30c3;
  x = (x | x << 2) & 0x1249249249249249;
  return x;
}

/// The candidates reordered along a Z-order (Morton) curve over cubic cells of `cell_m`,
/// ties by draw order: neighbours in space become mostly neighbours in memory, which
/// speeds the neighbour queries and the elimination (and hands the caller samples in a
/// cache-friendly order).
Candidates spatially_ordered(const Candidates& candidates, double cell_m) {
  const Eigen::Index count = candidates.positions.rows();
  Eigen::RowVector3d lowest = candidates.positions.colwise().minCoeff().cast<double>();
  std::vector<std::pair<uint64_t, int32_t>> keyed(static_cast<size_t>(count));
  for (Eigen::Index i = 0; i < count; ++i) {
    uint64_t key = 0;
    for (int axis = 0; axis < 3; ++axis) {
      double cell = (candidates.positions(i, axis) - lowest[axis]) / cell_m;
      key |= spread_bits(static_cast<uint64_t>(std::clamp(cell, 0.0, double{0x1fffff}))) << axis;
    }
    keyed[static_cast<size_t>(i)] = {key, static_cast<int32_t>(i)};
  }
  std::sort(keyed.begin(), keyed.end());
  Candidates ordered;
  ordered.positions.resize(count, 3);
  ordered.triangle.resize(static_cast<size_t>(count));
  for (size_t k = 0; k < keyed.size(); ++k) {
    ordered.positions.row(static_cast<Eigen::Index>(k)) = candidates.positions.row(keyed[k].second);
    ordered.triangle[k] = candidates.triangle[static_cast<size_t>(keyed[k].second)];
  }
  return ordered;
}

/// Each candidate's neighbours within `radius` (itself left out) and the weight each
/// contributes, in CSR layout: candidate i owns entries [offsets[i], offsets[i+1]).
struct Neighbourhood {
  std::vector<int64_t> offsets;
  std::vector<int32_t> neighbour;
  std::vector<double> weight;
};

Neighbourhood weighted_neighbours(const Points3f& positions, double radius_m,
                                  double limit_distance_m) {
  const auto count = static_cast<int64_t>(positions.rows());
  PointIndex index(positions);
  std::vector<std::vector<int32_t>> found(static_cast<size_t>(count));
  const auto radius = static_cast<float>(radius_m);
#pragma omp parallel for schedule(static)
  for (int64_t i = 0; i < count; ++i)
    found[static_cast<size_t>(i)] = index.within(positions.row(i).transpose(), radius);

  Neighbourhood neighbourhood;
  neighbourhood.offsets.assign(static_cast<size_t>(count) + 1, 0);
  for (int64_t i = 0; i < count; ++i)
    neighbourhood.offsets[static_cast<size_t>(i) + 1] =
        neighbourhood.offsets[static_cast<size_t>(i)] +
        static_cast<int64_t>(found[static_cast<size_t>(i)].size());
  neighbourhood.neighbour.reserve(static_cast<size_t>(neighbourhood.offsets.back()));
  neighbourhood.weight.reserve(static_cast<size_t>(neighbourhood.offsets.back()));
  for (int64_t i = 0; i < count; ++i) {
    Eigen::Vector3d p = positions.row(i).cast<double>().transpose();
    for (int32_t j : found[static_cast<size_t>(i)]) {
      if (j == i) continue;
      // Computed in double from both ends alike, so w_ij == w_ji exactly.
      double d_m = (positions.row(j).cast<double>().transpose() - p).norm();
      double closeness = std::max(1 - std::max(d_m, limit_distance_m) / radius_m, 0.0);
      double closeness2 = closeness * closeness, closeness4 = closeness2 * closeness2;
      neighbourhood.neighbour.push_back(j);
      neighbourhood.weight.push_back(closeness4 * closeness4);  // alpha = 8
    }
    neighbourhood.offsets[static_cast<size_t>(i) + 1] =
        static_cast<int64_t>(neighbourhood.neighbour.size());
  }
  return neighbourhood;
}

/// A max-heap of candidates by weight (the lower index first among equal weights) whose
/// weights can be lowered in place: each candidate knows its slot. Weights live in the
/// heap's entries, so sifting reads memory in order.
class EliminationHeap {
 public:
  explicit EliminationHeap(const std::vector<double>& weight) : slot_(weight.size()) {
    heap_.reserve(weight.size());
    for (size_t i = 0; i < weight.size(); ++i)
      heap_.push_back({weight[i], static_cast<int32_t>(i)});
    for (size_t i = 0; i < heap_.size(); ++i) slot_[i] = static_cast<int32_t>(i);
    for (size_t i = heap_.size() / 2; i-- > 0;) sift_down(i);
  }

  size_t size() const { return heap_.size(); }
  bool contains(int32_t id) const { return slot_[static_cast<size_t>(id)] >= 0; }

  /// Removes the heaviest candidate and returns its id.
  int32_t pop() {
    int32_t top = heap_.front().id;
    slot_[static_cast<size_t>(top)] = -1;
    heap_.front() = heap_.back();
    heap_.pop_back();
    if (!heap_.empty()) sift_down(0);
    return top;
  }

  /// Lowers the weight of a candidate still in the heap by `amount` >= 0.
  void lower(int32_t id, double amount) {
    auto slot = static_cast<size_t>(slot_[static_cast<size_t>(id)]);
    heap_[slot].weight -= amount;
    sift_down(slot);
  }

 private:
  struct Entry {
    double weight;
    int32_t id;
  };

  static bool heavier(const Entry& a, const Entry& b) {
    return a.weight > b.weight || (a.weight == b.weight && a.id < b.id);
  }

  void sift_down(size_t slot) {
    Entry entry = heap_[slot];
    for (;;) {
      size_t child = 2 * slot + 1;
      if (child >= heap_.size()) break;
      if (child + 1 < heap_.size() && heavier(heap_[child + 1], heap_[child])) ++child;
      if (!heavier(heap_[child], entry)) break;
      heap_[slot] = heap_[child];
      slot_[static_cast<size_t>(heap_[slot].id)] = static_cast<int32_t>(slot);
      slot = child;
    }
    heap_[slot] = entry;
    slot_[static_cast<size_t>(entry.id)] = static_cast<int32_t>(slot);
  }

  std::vector<Entry> heap_;
  std::vector<int32_t> slot_;  ///< per candidate: its place in heap_, -1 once removed
};

/// Weighted sample elimination: removes the heaviest candidate and lightens its
/// neighbours until `keep` remain; returns the kept ids in increasing order.
std::vector<int32_t> eliminated_down_to(const Neighbourhood& neighbourhood, int64_t keep) {
  const size_t candidate_count = neighbourhood.offsets.size() - 1;
  std::vector<double> weight(candidate_count, 0.0);
  for (size_t i = 0; i < candidate_count; ++i)
    for (int64_t e = neighbourhood.offsets[i]; e < neighbourhood.offsets[i + 1]; ++e)
      weight[i] += neighbourhood.weight[static_cast<size_t>(e)];
  EliminationHeap heap(weight);
  while (static_cast<int64_t>(heap.size()) > keep) {
    auto removed = static_cast<size_t>(heap.pop());
    for (int64_t e = neighbourhood.offsets[removed]; e < neighbourhood.offsets[removed + 1]; ++e) {
      int32_t j = neighbourhood.neighbour[static_cast<size_t>(e)];
      if (heap.contains(j)) heap.lower(j, neighbourhood.weight[static_cast<size_t>(e)]);
    }
  }
  std::vector<int32_t> kept;
  kept.reserve(static_cast<size_t>(keep));
  for (size_t i = 0; i < candidate_count; ++i)
    if (heap.contains(static_cast<int32_t>(i))) kept.push_back(static_cast<int32_t>(i));
  return kept;
}

/// Smallest distance between two of the points (0 for fewer than two).
double min_spacing_m(const Points3f& points) {
  if (points.rows() < 2) return 0;
  PointIndex index(points);
  double smallest2 = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    std::vector<int32_t> nearest = index.nearest(points.row(i).transpose(), 2);
    for (int32_t j : nearest)
      if (j != i)
        smallest2 = std::min(
            smallest2, (points.row(j).cast<double>() - points.row(i).cast<double>()).squaredNorm());
  }
  return std::sqrt(smallest2);
}

}  // namespace

double max_poisson_disk_radius_m(double area_m2, int64_t count) {
  return std::sqrt(area_m2 / (2 * std::sqrt(3.0) * static_cast<double>(count)));
}

SurfaceSamples poisson_disk_samples(const Points3f& vertices, const Triangles3i& triangles,
                                    const std::vector<uint8_t>& use_triangle, int64_t count,
                                    uint64_t seed, int candidate_factor,
                                    const SampleAcceptance& accept) {
  Region region = selected_region(vertices, triangles, use_triangle, count, candidate_factor);
  const int64_t candidate_count = count * candidate_factor;
  Candidates candidates =
      uniform_candidates(vertices, triangles, region, candidate_count, seed, accept);

  SurfaceSamples samples;
  samples.area_m2 = region.area_m2() * static_cast<double>(candidate_count) /
                    static_cast<double>(candidates.draws);
  samples.max_radius_m = max_poisson_disk_radius_m(samples.area_m2, count);
  const double radius_m = 2 * samples.max_radius_m;  // the neighbourhood of the weights
  candidates = spatially_ordered(candidates, radius_m);
  std::vector<int32_t> kept;
  if (candidate_count == count) {
    kept.resize(static_cast<size_t>(count));
    for (int64_t i = 0; i < count; ++i) kept[static_cast<size_t>(i)] = static_cast<int32_t>(i);
  } else {
    const double ratio = static_cast<double>(count) / static_cast<double>(candidate_count);
    const double limit_m = radius_m * kLimitBeta * (1 - std::pow(ratio, kLimitGamma));
    kept = eliminated_down_to(weighted_neighbours(candidates.positions, radius_m, limit_m), count);
  }

  samples.positions.resize(count, 3);
  samples.normals.resize(count, 3);
  samples.triangle.resize(static_cast<size_t>(count));
  for (int64_t s = 0; s < count; ++s) {
    int32_t c = kept[static_cast<size_t>(s)];
    int32_t t = candidates.triangle[static_cast<size_t>(c)];
    Eigen::Vector3d a = corner(vertices, triangles, t, 0);
    Eigen::Vector3d normal =
        (corner(vertices, triangles, t, 1) - a).cross(corner(vertices, triangles, t, 2) - a);
    samples.positions.row(s) = candidates.positions.row(c);
    samples.normals.row(s) = normal.normalized().cast<float>().transpose();
    samples.triangle[static_cast<size_t>(s)] = t;
  }
  samples.min_spacing_m = min_spacing_m(samples.positions);
  return samples;
}

}  // namespace hair
