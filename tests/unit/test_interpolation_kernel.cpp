// The per-strand interpolation kernel: the version this machine runs (AVX2 + FMA where
// the processor has them) against the portable one, and both against the formula.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "hair/interpolation_kernel.h"

namespace hair {
namespace {

TEST(InterpolationKernel, EveryVersionComputesTheWeightedGuidePoints) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> value(-1, 1), share(0, 1);
  constexpr int kParticles = 9;
  std::vector<std::vector<float>> tables(3, std::vector<float>(kParticles * kParticleFloats));
  for (auto& table : tables)
    for (float& v : table) v = value(random);
  const float* guide_table[3] = {tables[0].data(), tables[1].data(), tables[2].data()};
  const float segments[3] = {kParticles - 1, kParticles - 1, kParticles - 1};
  const float weight[3] = {0.5f, 0.3f, 0.2f};
  constexpr int kPoints = 257;
  std::vector<float> parameter(kPoints), offset(3 * kPoints);
  for (int i = 0; i < kPoints; ++i) parameter[i] = i == kPoints - 1 ? 1.0f : share(random);
  for (float& v : offset) v = 0.1f * value(random);

  for (int guide_count = 1; guide_count <= 3; ++guide_count) {
    std::vector<float> fast(3 * kPoints), portable(3 * kPoints);
    interpolate_strand_points(guide_table, segments, weight, guide_count, parameter.data(),
                              offset.data(), kPoints, fast.data());
    interpolate_strand_points_portable(guide_table, segments, weight, guide_count, parameter.data(),
                                       offset.data(), kPoints, portable.data());
    for (int i = 0; i < kPoints; ++i) {
      // The formula in double: sum_g w_g (p + f dp + sum_c d_c (m_c + f dm_c)).
      double expected[3] = {0, 0, 0};
      for (int k = 0; k < guide_count; ++k) {
        double position = static_cast<double>(parameter[i]) * segments[k];
        int particle = std::min(static_cast<int>(position), kParticles - 2);
        double f = position - particle;
        const float* a = guide_table[k] + particle * kParticleFloats;
        for (int r = 0; r < 3; ++r) {
          double p = a[r] + f * a[16 + r];
          for (int c = 0; c < 3; ++c)
            p += offset[3 * i + c] * (a[4 + 4 * c + r] + f * a[20 + 4 * c + r]);
          expected[r] += weight[k] * p;
        }
      }
      for (int r = 0; r < 3; ++r) {
        EXPECT_NEAR(portable[3 * i + r], expected[r], 1e-5) << "point " << i;
        EXPECT_NEAR(fast[3 * i + r], expected[r], 1e-5) << "point " << i;
      }
    }
  }
  std::printf("[ kernel   ] this machine runs the %s version\n",
              interpolation_uses_avx2() ? "AVX2 + FMA" : "portable");
}

}  // namespace
}  // namespace hair
