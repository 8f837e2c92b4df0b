#include "hair/grow/grow_measures.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include "hair/core/error.h"
#include "hair/geom/point_index.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;

Vec3 row3(const Points3f& points, int64_t row) {
  return points.row(row).cast<double>().transpose();
}

/// Mean and 95th percentile (nearest rank) of `values`, which it sorts.
std::pair<double, double> mean_and_p95(std::vector<double>& values) {
  if (values.empty()) return {0, 0};
  std::sort(values.begin(), values.end());
  double sum = 0;
  for (double v : values) sum += v;
  auto rank = static_cast<size_t>(std::ceil(0.95 * static_cast<double>(values.size())));
  return {sum / static_cast<double>(values.size()), values[std::max<size_t>(rank, 1) - 1]};
}

double segment_distance(const Vec3& p, const Vec3& a, const Vec3& b) {
  Vec3 ab = b - a;
  double length2 = ab.squaredNorm();
  double t = length2 > 0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

/// A uniform draw in [0, 1) from 53 bits, the same on every standard library.
double unit_draw(std::mt19937_64& random) {
  return static_cast<double>(random() >> 11) * 0x1.0p-53;
}

/// Points on a triangle mesh, each with the triangle it lies on.
struct MeshSamples {
  std::vector<Vec3> points;
  std::vector<Eigen::Index> triangle;
};

/// `count` points drawn uniformly by area over the hair mesh, from a fixed seed.
MeshSamples sample_hair_mesh(const Points3f& hair_vertices, const Triangles3i& hair_triangles,
                             int64_t count) {
  std::vector<double> area(static_cast<size_t>(hair_triangles.rows()));
  double total_area = 0;
  for (Eigen::Index t = 0; t < hair_triangles.rows(); ++t) {
    Vec3 a = row3(hair_vertices, hair_triangles(t, 0)),
         b = row3(hair_vertices, hair_triangles(t, 1)),
         c = row3(hair_vertices, hair_triangles(t, 2));
    total_area += 0.5 * (b - a).cross(c - a).norm();
    area[static_cast<size_t>(t)] = total_area;
  }
  std::mt19937_64 random(1);
  MeshSamples mesh_samples;
  std::vector<Vec3>& samples = mesh_samples.points;
  std::vector<Eigen::Index>& sample_triangle = mesh_samples.triangle;
  samples.resize(static_cast<size_t>(count));
  sample_triangle.resize(samples.size());
  for (size_t i = 0; i < samples.size(); ++i) {
    Vec3& sample = samples[i];
    double pick = unit_draw(random) * total_area;
    auto t =
        static_cast<Eigen::Index>(std::upper_bound(area.begin(), area.end(), pick) - area.begin());
    t = std::min<Eigen::Index>(t, hair_triangles.rows() - 1);
    double u = unit_draw(random), v = unit_draw(random);
    if (u + v > 1) {
      u = 1 - u;
      v = 1 - v;
    }
    Vec3 a = row3(hair_vertices, hair_triangles(t, 0)),
         b = row3(hair_vertices, hair_triangles(t, 1)),
         c = row3(hair_vertices, hair_triangles(t, 2));
    sample = a + u * (b - a) + v * (c - a);
    sample_triangle[i] = t;
  }
  return mesh_samples;
}

/// Per sample, its distance in H to the nearest grown strand segment. Candidate segments
/// are those ending at the grown points nearest each sample.
std::vector<double> coverage_h(const StrandSet& grown, const std::vector<Vec3>& samples,
                               double h) {
  PointIndex grown_index(grown.points);
  std::vector<int64_t> point_strand(static_cast<size_t>(grown.point_count()));
  for (int64_t s = 0; s < grown.strand_count(); ++s)
    for (int64_t row = grown.offsets[s]; row < grown.offsets[s + 1]; ++row)
      point_strand[static_cast<size_t>(row)] = s;
  std::vector<double> coverage(samples.size());
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < samples.size(); ++i) {
    double best = std::numeric_limits<double>::infinity();
    for (int32_t row : grown_index.nearest(samples[i].cast<float>(), 8)) {
      int64_t s = point_strand[static_cast<size_t>(row)];
      Vec3 p = row3(grown.points, row);
      best = std::min(best, (p - samples[i]).norm());
      if (row > grown.offsets[s])
        best = std::min(best, segment_distance(samples[i], row3(grown.points, row - 1), p));
      if (row + 1 < grown.offsets[s + 1])
        best = std::min(best, segment_distance(samples[i], p, row3(grown.points, row + 1)));
    }
    coverage[i] = best / h;
  }
  return coverage;
}

/// The worst group's coverage into `measures` (GrowMeasures::worst_group): `coverage` per
/// sample, `sample_triangle` the hair triangle of each, `hair_triangle_group` the group of
/// each triangle.
void measure_worst_group(const std::vector<double>& coverage,
                         const std::vector<Eigen::Index>& sample_triangle,
                         const std::vector<int32_t>& hair_triangle_group,
                         GrowMeasures& measures) {
  std::map<int32_t, std::pair<double, int64_t>> by_group;  // sum, count
  for (size_t i = 0; i < coverage.size(); ++i) {
    auto& [sum, count] = by_group[hair_triangle_group[static_cast<size_t>(sample_triangle[i])]];
    sum += coverage[i];
    ++count;
  }
  for (const auto& [group, sum_count] : by_group) {
    const auto& [sum, count] = sum_count;
    if (count < GrowMeasures::kMinGroupSamples) continue;
    const double mean = sum / static_cast<double>(count);
    if (measures.worst_group < 0 || mean > measures.worst_group_coverage_mean_h) {
      measures.worst_group = group;
      measures.worst_group_coverage_mean_h = mean;
      measures.worst_group_samples = count;
    }
  }
}

/// Fidelity and the body into `measures`: every grown point but the roots, to the hair
/// mesh and on which side of the body's nearest triangle it lies.
void measure_fidelity_and_body(const StrandSet& grown, const Points3f& hair_vertices,
                               const Triangles3i& hair_triangles, const Points3f& body_vertices,
                               const Triangles3i& body_triangles, double h,
                               GrowMeasures& measures) {
  TriangleMeshDistance hair_distance(hair_vertices, hair_triangles);
  TriangleMeshDistance body_distance(body_vertices, body_triangles);
  std::vector<int64_t> rows;
  for (int64_t s = 0; s < grown.strand_count(); ++s)
    for (int64_t row = grown.offsets[s] + 1; row < grown.offsets[s + 1]; ++row) rows.push_back(row);
  measures.strand_points = static_cast<int64_t>(rows.size());
  std::vector<double> fidelity(rows.size());
  int64_t inside = 0;
#pragma omp parallel for schedule(static) reduction(+ : inside)
  for (size_t i = 0; i < rows.size(); ++i) {
    Vec3 p = row3(grown.points, rows[i]);
    fidelity[i] = hair_distance.distance(p) / h;
    TriangleMeshDistance::Nearest nearest = body_distance.nearest(p);
    Vec3 a = row3(body_vertices, body_triangles(nearest.triangle, 0)),
         b = row3(body_vertices, body_triangles(nearest.triangle, 1)),
         c = row3(body_vertices, body_triangles(nearest.triangle, 2));
    Vec3 normal = (b - a).cross(c - a);
    inside += (p - nearest.closest_point).dot(normal) < 0 ? 1 : 0;
  }
  std::tie(measures.fidelity_mean_h, measures.fidelity_p95_h) = mean_and_p95(fidelity);
  measures.inside_body_share =
      rows.empty() ? 0.0 : static_cast<double>(inside) / static_cast<double>(rows.size());
}

/// Roots to the scalp into `measures`: the largest and mean distance of a root from the
/// scalp triangles.
void measure_roots_to_scalp(const StrandSet& grown, const Points3f& body_vertices,
                            const Triangles3i& body_triangles,
                            const std::vector<uint8_t>& scalp_triangle, double h,
                            GrowMeasures& measures) {
  Triangles3i scalp(body_triangles.rows(), 3);
  Eigen::Index scalp_count = 0;
  for (Eigen::Index t = 0; t < body_triangles.rows(); ++t)
    if (scalp_triangle[static_cast<size_t>(t)]) scalp.row(scalp_count++) = body_triangles.row(t);
  scalp.conservativeResize(scalp_count, 3);
  if (scalp_count == 0) throw Error::usage("measure_grown_strands: the body has no scalp");
  TriangleMeshDistance scalp_distance(body_vertices, scalp);
  double root_sum = 0, root_max = 0;
  for (int64_t s = 0; s < grown.strand_count(); ++s) {
    double d = scalp_distance.distance(row3(grown.points, grown.offsets[s])) / h;
    root_sum += d;
    root_max = std::max(root_max, d);
  }
  measures.root_distance_max_h = root_max;
  measures.root_distance_mean_h = root_sum / static_cast<double>(grown.strand_count());
}

}  // namespace

GrowMeasures measure_grown_strands(const StrandSet& grown, const Points3f& hair_vertices,
                                   const Triangles3i& hair_triangles, const Points3f& body_vertices,
                                   const Triangles3i& body_triangles,
                                   const std::vector<uint8_t>& scalp_triangle, double head_height_m,
                                   int64_t mesh_sample_count,
                                   const std::vector<int32_t>& hair_triangle_group) {
  if (grown.strand_count() == 0 || hair_triangles.rows() == 0 || body_triangles.rows() == 0)
    throw Error::usage("measure_grown_strands: nothing to measure");
  const double h = head_height_m;
  GrowMeasures measures;
  // Coverage: mesh samples to the nearest grown segment.
  const MeshSamples samples = sample_hair_mesh(hair_vertices, hair_triangles, mesh_sample_count);
  measures.mesh_samples = mesh_sample_count;
  std::vector<double> coverage = coverage_h(grown, samples.points, h);
  if (hair_triangle_group.size() == static_cast<size_t>(hair_triangles.rows()))
    measure_worst_group(coverage, samples.triangle, hair_triangle_group, measures);
  std::tie(measures.coverage_mean_h, measures.coverage_p95_h) = mean_and_p95(coverage);
  measure_fidelity_and_body(grown, hair_vertices, hair_triangles, body_vertices, body_triangles,
                            h, measures);
  measure_roots_to_scalp(grown, body_vertices, body_triangles, scalp_triangle, h, measures);
  return measures;
}

std::vector<ClusterPassage> cluster_passages(const StrandSet& grown, int64_t cluster_count) {
  std::vector<ClusterPassage> passages(static_cast<size_t>(std::max<int64_t>(cluster_count, 0)));
  const auto& root_cluster = std::get<std::vector<int32_t>>(grown.strand_attributes.at("cluster"));
  const auto& point_cluster = std::get<std::vector<int32_t>>(grown.point_attributes.at("cluster"));
  const auto valid = [&](int32_t c) { return c >= 0 && c < cluster_count; };
  std::vector<int64_t> last_seen(passages.size(), -1);  // the strand that last counted it
  for (int64_t s = 0; s < grown.strand_count(); ++s) {
    const int32_t root = root_cluster[static_cast<size_t>(s)];
    const int32_t tip = point_cluster[static_cast<size_t>(grown.offsets[s + 1] - 1)];
    if (valid(root)) {
      ++passages[static_cast<size_t>(root)].rooted;
      if (tip != root) ++passages[static_cast<size_t>(root)].rooted_leaving;
    }
    for (int64_t row = grown.offsets[s]; row < grown.offsets[s + 1]; ++row) {
      const int32_t c = point_cluster[static_cast<size_t>(row)];
      if (!valid(c) || c == root || last_seen[static_cast<size_t>(c)] == s) continue;
      last_seen[static_cast<size_t>(c)] = s;
      ++passages[static_cast<size_t>(c)].passing_in;
    }
  }
  return passages;
}

}  // namespace hair
