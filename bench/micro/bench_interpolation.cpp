// Google Benchmark of interpolate's per-frame loop (interpolate_frame) on a synthetic head:
// 169 guides of 20 particles on a 13 x 13 grid 1.5 cm apart, hanging 40 cm and swung 30
// degrees about their anchors, and S strands of P points rooted among them (the guides'
// cluster, so barycentric where the triangle allows), with 1 and 2 threads. Without reading
// or writing files, and at a chosen points per strand: the paper's strands had a few tens of
// points, our grown ones 28 to 144 (docs/interpolate.md). Then the memory floor: a loop that
// only moves the same bytes per point. With HAIR_BENCH_SCENE=DIR (a folder holding a
// pipeline's guides.h5, strands.h5 and styles.h5, e.g. bench/interpolate_makehuman.sh's
// work folder), also interpolate_frame on that real scene, frame 1, with default
// parameters, and its interpolated points and runs by guide count.
//   build/bin/hair-bench-interpolation --benchmark_repetitions=5 --benchmark_report_aggregates_only
#include <benchmark/benchmark.h>
#include <omp.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "hair/h5/file.h"
#include "hair/interp/frames_io.h"
#include "hair/interp/strand_interpolation.h"
#include "hair/style/hair_style.h"

namespace {

using Vec3 = Eigen::Vector3d;
constexpr int kGrid = 13, kParticles = 20;
constexpr double kSpacing = 0.015, kLength = 0.4;

struct Scene {
  hair::StrandSet strands;
  hair::InterpolationGuides guides;
  std::vector<float> swung;  ///< the guides in a frame
};

Scene make_scene(int64_t strand_count, int points_per_strand) {
  Scene scene;
  hair::InterpolationGuides& g = scene.guides;
  std::vector<Vec3> points;
  const Eigen::Matrix3d swing = Eigen::AngleAxisd(0.5, Vec3::UnitX()).toRotationMatrix();
  for (int i = 0; i < kGrid; ++i) {
    for (int j = 0; j < kGrid; ++j) {
      Vec3 anchor(kSpacing * i, 0, kSpacing * j);
      for (int k = 0; k < kParticles; ++k) {
        Vec3 p = anchor + Vec3(0, -kLength * k / (kParticles - 1), 0);
        points.push_back(p);
        Vec3 q = anchor + swing * (p - anchor);
        scene.swung.insert(scene.swung.end(), {static_cast<float>(q.x()), static_cast<float>(q.y()),
                                               static_cast<float>(q.z())});
      }
      g.offsets.push_back(static_cast<int64_t>(points.size()));
      g.cluster.push_back(0);
      g.is_wisp_centre.push_back(0);
      g.strand.push_back(-1);
    }
  }
  g.rest_points.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (size_t i = 0; i < points.size(); ++i)
    g.rest_points.row(static_cast<Eigen::Index>(i)) = points[i].cast<float>().transpose();
  g.cluster_simulated_style = {static_cast<int8_t>(hair::HairStyle::normal)};

  std::mt19937 random(7);
  std::uniform_real_distribution<double> across(0, kSpacing * (kGrid - 1));
  std::vector<hair::Points3f> polylines;
  for (int64_t s = 0; s < strand_count; ++s) {
    Vec3 root(across(random), 0, across(random));
    hair::Points3f strand(points_per_strand, 3);
    for (int i = 0; i < points_per_strand; ++i) {
      double t = static_cast<double>(i) / (points_per_strand - 1);
      strand.row(i) << static_cast<float>(root.x() + 0.003 * std::sin(8 * t)),
          static_cast<float>(-kLength * t), static_cast<float>(root.z());
    }
    polylines.push_back(strand);
  }
  scene.strands = hair::strand_set_from_polylines(polylines);
  scene.strands.point_attributes["cluster"] =
      std::vector<int32_t>(static_cast<size_t>(scene.strands.point_count()), 0);
  return scene;
}

void interpolate_frame(benchmark::State& state) {
  const int64_t strands = state.range(0);
  const int points = static_cast<int>(state.range(1));
  const int threads = static_cast<int>(state.range(2));
  Scene scene = make_scene(strands, points);
  hair::StrandBinding binding = hair::bind_strands(scene.strands, scene.guides, {});
  std::vector<float> out;
  omp_set_num_threads(threads);
  hair::GuideFrame frame{scene.swung.data(), nullptr, {}};
  for (auto _ : state) {
    hair::interpolate_frame(binding, scene.strands, frame, out);
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["points"] = static_cast<double>(scene.strands.point_count());
  state.counters["ns_per_point"] = benchmark::Counter(
      static_cast<double>(scene.strands.point_count()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(interpolate_frame)
    ->ArgNames({"strands", "points", "threads"})
    ->Args({10000, 25, 1})
    ->Args({10000, 25, 2})
    ->Args({10000, 60, 1})
    ->Args({10000, 60, 2})
    ->Args({10000, 144, 1})
    ->Args({10000, 144, 2})
    ->Args({100000, 25, 1})
    ->Args({100000, 25, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

/// The memory floor of a frame: a loop that moves the bytes interpolate_frame() moves per
/// point (its parameter and offset read, 16 bytes; its point written, 12) with next to no
/// arithmetic, over as many points as long01 has at 10,000 and 100,000 strands.
void memory_floor(benchmark::State& state) {
  const auto points = static_cast<size_t>(state.range(0));
  const int threads = static_cast<int>(state.range(1));
  std::vector<float> parameter(points, 0.5f), offset(3 * points, 0.25f), out(3 * points);
  omp_set_num_threads(threads);
  for (auto _ : state) {
    const auto count = static_cast<int64_t>(points);
#pragma omp parallel for schedule(static)
    for (int64_t i = 0; i < count; ++i) {
      const float u = parameter[static_cast<size_t>(i)];
      const float* d = offset.data() + 3 * i;
      float* o = out.data() + 3 * i;
      o[0] = d[0] + u;
      o[1] = d[1] * u;
      o[2] = d[2] - u;
    }
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["ns_per_point"] = benchmark::Counter(
      static_cast<double>(points),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(memory_floor)
    ->ArgNames({"points", "threads"})
    ->Args({1278434, 1})
    ->Args({1278434, 2})
    ->Args({12814741, 1})
    ->Args({12814741, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

/// interpolate_frame on the scene in `folder` (guides.h5, strands.h5, styles.h5), frame 1.
void real_scene(benchmark::State& state, const std::string& folder) {
  const int threads = static_cast<int>(state.range(0));
  hair::h5::File guides_file = hair::h5::File::open_read_only(folder + "/guides.h5");
  hair::InterpolationInput input = hair::read_interpolation_input(
      guides_file, hair::h5::File::open_read_only(folder + "/strands.h5"),
      hair::h5::File::open_read_only(folder + "/styles.h5"));
  hair::StrandBinding binding = hair::bind_strands(input.strands, input.guides, {});
  hair::GuideFrameData data = hair::read_guide_frame(guides_file, input.frame_count > 1 ? 1 : 0);
  hair::GuideFrame frame{data.guide_points_m.data(), data.wisp_frames.data(),
                         input.head[input.frame_count > 1 ? 1 : 0]};
  std::vector<float> out;
  omp_set_num_threads(threads);
  for (auto _ : state) {
    hair::interpolate_frame(binding, input.strands, frame, out);
    benchmark::DoNotOptimize(out.data());
  }
  const auto points = static_cast<double>(input.strands.point_count());
  state.counters["points"] = points;
  // Interpolated points and runs by the strand's guide count (1 = clump, 3 = barycentric).
  double run_points[4] = {}, runs[4] = {};
  for (int64_t s = 0; s < input.strands.strand_count(); ++s) {
    const auto si = static_cast<size_t>(s);
    if (binding.bridged[si]) continue;
    const int count = hair::strand_guides(binding, s).count;
    run_points[count] +=
        static_cast<double>(binding.bound_from[si] - binding.interpolated_from[si]);
    runs[count] += static_cast<double>(binding.run_offsets[si + 1] - binding.run_offsets[si]);
  }
  for (int count : {1, 2, 3}) {
    state.counters["points_" + std::to_string(count) + "_guides"] = run_points[count];
    state.counters["runs_" + std::to_string(count) + "_guides"] = runs[count];
  }
  state.counters["ns_per_point"] = benchmark::Counter(
      points, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

}  // namespace

int main(int argc, char** argv) {
  if (const char* folder = std::getenv("HAIR_BENCH_SCENE"))
    benchmark::RegisterBenchmark("real_scene", real_scene, std::string(folder))
        ->ArgName("threads")
        ->Arg(1)
        ->Arg(2)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
