// The interpolation kernels (a strand's points from its guides, points carried by rigid
// frames): the version this machine runs (AVX2 + FMA where the processor has them)
// against the portable one, and both against the formula.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "hair/interpolation_kernel.h"

namespace hair {
namespace {

// Guides of different particle counts; parameters in random order (every point a new run
// of the AVX2 version's runs) and rising along the strand (as a strand's are: runs of
// points between two guide particles); more points than the guides' segments (the AVX2
// version in runs) and fewer (point by point: 10 and 5 points).
TEST(InterpolationKernel, EveryVersionComputesTheWeightedGuidePoints) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> value(-1, 1), share(0, 1);
  const int particles[3] = {9, 5, 13};
  std::vector<std::vector<float>> tables(3);
  for (int k = 0; k < 3; ++k) {
    tables[static_cast<size_t>(k)].resize(static_cast<size_t>(particles[k] * kParticleFloats));
    for (float& v : tables[static_cast<size_t>(k)]) v = value(random);
  }
  const float* guide_table[3] = {tables[0].data(), tables[1].data(), tables[2].data()};
  float segments[3];
  for (int k = 0; k < 3; ++k) segments[k] = static_cast<float>(particles[k] - 1);
  const float weight[3] = {0.5f, 0.3f, 0.2f};
  for (int point_count : {257, 10, 5})
    for (bool rising : {false, true}) {
      std::vector<float> offset(3 * static_cast<size_t>(point_count));
      for (float& v : offset) v = 0.1f * value(random);
      std::vector<float> parameter(static_cast<size_t>(point_count));
      for (int i = 0; i < point_count; ++i)
        parameter[i] = i == point_count - 1 ? 1.0f : share(random);
      if (rising) std::sort(parameter.begin(), parameter.end());
      for (int guide_count = 1; guide_count <= 3; ++guide_count) {
        std::vector<float> fast(3 * static_cast<size_t>(point_count)), portable(fast.size());
        interpolate_strand_points(guide_table, segments, weight, guide_count, parameter.data(),
                                  offset.data(), point_count, fast.data());
        interpolate_strand_points_portable(guide_table, segments, weight, guide_count,
                                           parameter.data(), offset.data(), point_count,
                                           portable.data());
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
              double p = a[r] + u * a[16 + r];
              for (int c = 0; c < 3; ++c)
                p += offset[3 * i + c] * (a[4 + 4 * c + r] + u * a[20 + 4 * c + r]);
              expected[r] += weight[k] * p;
            }
          }
          for (int r = 0; r < 3; ++r) {
            EXPECT_NEAR(portable[3 * i + r], expected[r], 1e-5)
                << "point " << i << ", " << guide_count << " guides";
            EXPECT_NEAR(fast[3 * i + r], expected[r], 1e-5)
                << "point " << i << " of " << point_count << ", " << guide_count
                << " guides, rising " << rising;
          }
        }
      }
    }
  std::printf("[ kernel   ] this machine runs the %s version\n",
              interpolation_uses_avx2() ? "AVX2 + FMA" : "portable");
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
