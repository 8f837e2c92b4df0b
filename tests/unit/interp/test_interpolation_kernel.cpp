// The interpolation kernels (a strand's points from its guides, points carried by rigid
// frames): the version this machine runs (AVX2 + FMA where the processor has them)
// against the portable one, and both against the formula.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "hair/interp/interpolation_kernel.h"

namespace hair {
namespace {

/// Floats on a 64-byte boundary (the guide tables of interpolate_strand_runs()).
struct AlignedFloats {
  explicit AlignedFloats(size_t count) : storage(count + 16) {
    const auto misalignment = reinterpret_cast<uintptr_t>(storage.data()) % 64 / sizeof(float);
    data = storage.data() + (misalignment ? 16 - misalignment : 0);
  }
  std::vector<float> storage;
  float* data;
};

// Guides of different particle counts; parameters in random order (every point a new run
// of the AVX2 version's runs) and rising along the strand (as a strand's are: runs of
// points between two guide particles); more points than the guides' segments and fewer
// (10 and 5 points); weights summing to 1 and, for one guide, 1 itself (the runs read the
// guide's table in place). Both kernels (point by point and in runs) and both versions of
// each against the formula.
TEST(InterpolationKernel, EveryVersionComputesTheWeightedGuidePoints) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> value(-1, 1), share(0, 1);
  const int particles[3] = {9, 5, 13};
  std::vector<AlignedFloats> tables;
  for (int k = 0; k < 3; ++k) {
    tables.emplace_back(static_cast<size_t>(particles[k] * kParticleFloats));
    for (int v = 0; v < particles[k] * kParticleFloats; ++v) tables.back().data[v] = value(random);
  }
  const float* guide_table[3] = {tables[0].data, tables[1].data, tables[2].data};
  float segments[3];
  for (int k = 0; k < 3; ++k) segments[k] = static_cast<float>(particles[k] - 1);
  for (int point_count : {257, 10, 5})
    for (bool rising : {false, true}) {
      std::vector<float> offset(3 * static_cast<size_t>(point_count));
      for (float& v : offset) v = 0.1f * value(random);
      std::vector<float> parameter(static_cast<size_t>(point_count));
      for (int i = 0; i < point_count; ++i)
        parameter[i] = i == point_count - 1 ? 1.0f : share(random);
      if (rising) std::sort(parameter.begin(), parameter.end());
      for (int guide_count = 1; guide_count <= 3; ++guide_count)
        for (bool whole_weight : {false, true}) {
          if (whole_weight && guide_count > 1) continue;
          const float weight[3] = {whole_weight ? 1.0f : 0.5f, 0.3f, 0.2f};
          std::vector<std::array<int32_t, 3>> run_particles;
          std::vector<uint8_t> run_of_point(static_cast<size_t>(point_count));
          const int runs = strand_runs(segments, guide_count, parameter.data(), point_count,
                                       run_of_point.data(), run_particles);
          ASSERT_GT(runs, 0);
          ASSERT_EQ(run_particles.size(), static_cast<size_t>(runs));
          std::vector<std::vector<float>> results;
          for (int version = 0; version < 4; ++version) {
            std::vector<float> out(3 * static_cast<size_t>(point_count), -7);
            if (version == 0)
              interpolate_strand_points(guide_table, segments, weight, guide_count,
                                        parameter.data(), offset.data(), point_count, out.data());
            else if (version == 1)
              interpolate_strand_points_portable(guide_table, segments, weight, guide_count,
                                                 parameter.data(), offset.data(), point_count,
                                                 out.data());
            else if (version == 2)
              interpolate_strand_runs(guide_table, weight, guide_count, run_particles.data(), runs,
                                      run_of_point.data(), parameter.data(), offset.data(),
                                      point_count, out.data());
            else
              interpolate_strand_runs_portable(
                  guide_table, weight, guide_count, run_particles.data(), runs, run_of_point.data(),
                  parameter.data(), offset.data(), point_count, out.data());
            results.push_back(out);
          }
          const char* names[4] = {"points", "points, portable", "runs", "runs, portable"};
          for (int i = 0; i < point_count; ++i) {
            // The formula in double: sum_g w_g (P + u Q + sum_c d_c (P_c + u Q_c)) at the
            // particle that starts the point's segment.
            double expected[3] = {0, 0, 0};
            for (int k = 0; k < guide_count; ++k) {
              double position = static_cast<double>(parameter[i]) * segments[k];
              int particle = std::min(static_cast<int>(position), particles[k] - 2);
              const float* a = guide_table[k] + particle * kParticleFloats;
              for (int r = 0; r < 3; ++r) {
                const double u = parameter[i];
                double p = a[r] + u * a[4 + r];
                for (int c = 1; c < 4; ++c)
                  p += offset[3 * i + c - 1] * (a[8 * c + r] + u * a[8 * c + 4 + r]);
                expected[r] += weight[k] * p;
              }
            }
            for (int version = 0; version < 4; ++version)
              for (int r = 0; r < 3; ++r)
                EXPECT_NEAR(results[static_cast<size_t>(version)][3 * i + r], expected[r], 1e-5)
                    << names[version] << ": point " << i << " of " << point_count << ", "
                    << guide_count << " guides of weight " << weight[0] << "..., rising " << rising;
          }
        }
    }
  std::printf("[ kernel   ] this machine runs the %s version\n",
              interpolation_uses_avx2() ? "AVX2 + FMA" : "portable");
}

// The runs of a strand: of several guides, where the particles change along it; of one,
// every particle from its first to its last; none (and nothing appended) past
// kMaxStrandRuns.
TEST(InterpolationKernel, StrandRunsFollowTheGuidesParticles) {
  const float segments[3] = {4, 2, 300};
  // Parameters 0, 0.1, ..., 1: on guide 0 (4 segments) particles 0 0 0 1 1 2 2 2 3 3 3
  // (u S = 0, 0.4, 0.8, 1.2, 1.6, 2, 2.4, 2.8, 3.2, 3.6 and 4, the last on segment 3); on
  // guide 1 (2 segments) 0 0 0 0 0 1 1 1 1 1 1.
  std::vector<float> parameter;
  for (int i = 0; i <= 10; ++i) parameter.push_back(static_cast<float>(i) / 10);
  std::vector<uint8_t> run_of_point(parameter.size());
  std::vector<std::array<int32_t, 3>> runs;
  ASSERT_EQ(strand_runs(segments, 2, parameter.data(), 11, run_of_point.data(), runs), 4);
  const std::vector<std::array<int32_t, 3>> expected_runs = {
      {0, 0, -1}, {1, 0, -1}, {2, 1, -1}, {3, 1, -1}};
  EXPECT_EQ(runs, expected_runs);
  EXPECT_EQ(run_of_point, (std::vector<uint8_t>{0, 0, 0, 1, 1, 2, 2, 2, 3, 3, 3}));

  // One guide: its particles 0 to 3 in order, with or without a point on each.
  runs.clear();
  const float one_point[2] = {0.1f, 0.9f};
  ASSERT_EQ(strand_runs(segments, 1, one_point, 2, run_of_point.data(), runs), 4);
  EXPECT_EQ(runs, (std::vector<std::array<int32_t, 3>>{
                      {0, -1, -1}, {1, -1, -1}, {2, -1, -1}, {3, -1, -1}}));
  EXPECT_EQ(run_of_point[0], 0);
  EXPECT_EQ(run_of_point[1], 3);

  // Too many: guide 2's 300 particles along one strand, alone and with guide 0.
  std::vector<float> long_parameter;
  for (int i = 0; i <= 600; ++i) long_parameter.push_back(static_cast<float>(i) / 600);
  std::vector<uint8_t> long_runs(long_parameter.size());
  runs = {{7, 7, 7}};
  const float with_guide_0[2] = {300, 4};
  EXPECT_EQ(strand_runs(segments + 2, 1, long_parameter.data(), 601, long_runs.data(), runs), 0);
  EXPECT_EQ(strand_runs(with_guide_0, 2, long_parameter.data(), 601, long_runs.data(), runs), 0);
  EXPECT_EQ(runs.size(), 1u) << "nothing appended where the runs are too many";
  // No points: no runs.
  EXPECT_EQ(strand_runs(segments, 3, nullptr, 0, nullptr, runs), 0);
}

// Points carried by rigid frames: one frame for all, and a frame per point that changes
// every few points (a braided strand's tetrahedra).
TEST(InterpolationKernel, EveryVersionCarriesPointsByTheirFrames) {
  std::mt19937 random(11);
  std::uniform_real_distribution<float> value(-1, 1);
  constexpr int kFrames = 4;
  std::vector<float> frames(kFrames * kFrameFloats);
  for (float& v : frames) v = value(random);
  // No points, no frames (a scene without braids): nothing read.
  transform_points(nullptr, nullptr, nullptr, 0, nullptr);
  for (int point_count : {1, 2, 40}) {
    std::vector<float> local(3 * static_cast<size_t>(point_count));
    for (float& v : local) v = 0.1f * value(random);
    std::vector<int32_t> frame_index(static_cast<size_t>(point_count));
    for (int i = 0; i < point_count; ++i)
      frame_index[static_cast<size_t>(i)] = (i / 3 + i % 2) % kFrames;
    for (bool per_point : {false, true}) {
      const int32_t* index = per_point ? frame_index.data() : nullptr;
      std::vector<float> fast(local.size(), -7), portable(local.size(), -7);
      transform_points(frames.data(), index, local.data(), point_count, fast.data());
      transform_points_portable(frames.data(), index, local.data(), point_count, portable.data());
      for (int i = 0; i < point_count; ++i) {
        const float* f =
            frames.data() + (per_point ? frame_index[static_cast<size_t>(i)] : 0) * kFrameFloats;
        for (int r = 0; r < 3; ++r) {
          double expected = f[r];
          for (int c = 0; c < 3; ++c)
            expected += static_cast<double>(f[4 + 4 * c + r]) *
                        local[3 * static_cast<size_t>(i) + static_cast<size_t>(c)];
          EXPECT_NEAR(fast[3 * static_cast<size_t>(i) + static_cast<size_t>(r)], expected, 1e-6)
              << "point " << i << " of " << point_count;
          EXPECT_NEAR(portable[3 * static_cast<size_t>(i) + static_cast<size_t>(r)], expected, 1e-6)
              << "point " << i;
        }
      }
    }
  }
}

}  // namespace
}  // namespace hair
