#include "hair/interpolation_kernel.h"

#include <algorithm>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define HAIR_HAVE_AVX2_KERNEL 1
#endif

namespace hair {
namespace {

/// The particle record and the fraction past it at arc parameter u of a guide.
inline const float* particle_at(const float* table, float segments, float u, float& fraction) {
  float position = u * segments;
  int particle = std::min(static_cast<int>(position), static_cast<int>(segments) - 1);
  fraction = position - static_cast<float>(particle);
  return table + static_cast<int64_t>(particle) * kParticleFloats;
}

}  // namespace

void interpolate_strand_points_portable(const float* const* guide_table, const float* segments,
                                        const float* weight, int guide_count,
                                        const float* parameter, const float* offset, int64_t count,
                                        float* out) {
  for (int64_t i = 0; i < count; ++i) {
    const float u = parameter[i];
    const float* d = offset + 3 * i;
    float sum[3] = {0, 0, 0};
    for (int k = 0; k < guide_count; ++k) {
      float f = 0;
      const float* a = particle_at(guide_table[k], segments[k], u, f);
      for (int r = 0; r < 3; ++r) {
        float p = a[r] + f * a[16 + r];
        p += (a[4 + r] + f * a[20 + r]) * d[0];
        p += (a[8 + r] + f * a[24 + r]) * d[1];
        p += (a[12 + r] + f * a[28 + r]) * d[2];
        sum[r] += weight[k] * p;
      }
    }
    for (int r = 0; r < 3; ++r) out[3 * i + r] = sum[r];
  }
}

namespace {

#ifdef HAIR_HAVE_AVX2_KERNEL
// Two columns per 8-float register: [position | column 0] and [column 1 | column 2], and
// the same of the steps; c01 = [1 | d0], c23 = [d1 | d2] broadcast per half, so a guide
// costs four fused multiply-adds and one more for the fraction.
__attribute__((target("avx2,fma"))) void interpolate_avx2(
    const float* const* guide_table, const float* segments, const float* weight, int guide_count,
    const float* parameter, const float* offset, int64_t count, float* out) {
  for (int64_t i = 0; i < count; ++i) {
    const float u = parameter[i];
    const float* d = offset + 3 * i;
    const __m256 c01 = _mm256_setr_ps(1, 1, 1, 1, d[0], d[0], d[0], d[0]);
    const __m256 c23 = _mm256_setr_ps(d[1], d[1], d[1], d[1], d[2], d[2], d[2], d[2]);
    __m256 sum = _mm256_setzero_ps();
    for (int k = 0; k < guide_count; ++k) {
      float f = 0;
      const float* a = particle_at(guide_table[k], segments[k], u, f);
      __m256 at =
          _mm256_fmadd_ps(c01, _mm256_loadu_ps(a), _mm256_mul_ps(c23, _mm256_loadu_ps(a + 8)));
      __m256 step = _mm256_fmadd_ps(c01, _mm256_loadu_ps(a + 16),
                                    _mm256_mul_ps(c23, _mm256_loadu_ps(a + 24)));
      __m256 p = _mm256_fmadd_ps(_mm256_set1_ps(f), step, at);
      sum = _mm256_fmadd_ps(_mm256_set1_ps(weight[k]), p, sum);
    }
    __m128 folded = _mm_add_ps(_mm256_castps256_ps128(sum), _mm256_extractf128_ps(sum, 1));
    alignas(16) float xyzw[4];
    _mm_store_ps(xyzw, folded);
    out[3 * i] = xyzw[0];
    out[3 * i + 1] = xyzw[1];
    out[3 * i + 2] = xyzw[2];
  }
}

bool cpu_has_avx2() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}
#endif

}  // namespace

bool interpolation_uses_avx2() {
#ifdef HAIR_HAVE_AVX2_KERNEL
  static const bool has = cpu_has_avx2();
  return has;
#else
  return false;
#endif
}

void interpolate_strand_points(const float* const* guide_table, const float* segments,
                               const float* weight, int guide_count, const float* parameter,
                               const float* offset, int64_t count, float* out) {
#ifdef HAIR_HAVE_AVX2_KERNEL
  if (interpolation_uses_avx2())
    return interpolate_avx2(guide_table, segments, weight, guide_count, parameter, offset, count,
                            out);
#endif
  interpolate_strand_points_portable(guide_table, segments, weight, guide_count, parameter, offset,
                                     count, out);
}

}  // namespace hair
