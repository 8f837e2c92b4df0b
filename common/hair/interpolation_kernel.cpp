#include "hair/interpolation_kernel.h"

#include <algorithm>
#include <cmath>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define HAIR_HAVE_AVX2_KERNEL 1
#endif

namespace hair {
namespace {

/// The record of the particle that starts the segment of a guide at arc parameter u.
inline const float* particle_at(const float* table, float segments, float u) {
  int particle = std::min(static_cast<int>(u * segments), static_cast<int>(segments) - 1);
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
      const float* a = particle_at(guide_table[k], segments[k], u);
      for (int r = 0; r < 3; ++r) {
        float p = a[r] + u * a[16 + r];
        p += (a[4 + r] + u * a[20 + r]) * d[0];
        p += (a[8 + r] + u * a[24 + r]) * d[1];
        p += (a[12 + r] + u * a[28 + r]) * d[2];
        sum[r] += weight[k] * p;
      }
    }
    for (int r = 0; r < 3; ++r) out[3 * i + r] = sum[r];
  }
}

void transform_points_portable(const float* frames, const int32_t* frame_index, const float* local,
                               int64_t count, float* out) {
  for (int64_t i = 0; i < count; ++i) {
    const float* f =
        frames + (frame_index ? static_cast<int64_t>(frame_index[i]) : 0) * kFrameFloats;
    const float* p = local + 3 * i;
    for (int r = 0; r < 3; ++r)
      out[3 * i + r] = f[r] + f[4 + r] * p[0] + f[8 + r] * p[1] + f[12 + r] * p[2];
  }
}

namespace {

#ifdef HAIR_HAVE_AVX2_KERNEL
// Two columns per 8-float register: [position | column 0] and [column 1 | column 2], and
// the same of the Q half of the record; c01 = [1 | d0] and c23 = [d1 | d2] per point. Two
// versions:
//  - per point: each guide's P + u Q at the point's particle (two fused multiply-adds),
//    weighted into two sums (two more), then c01 and c23 applied (a multiply and a fused
//    multiply-add) and the halves added;
//  - in runs: while the particles j_g of every guide stay the same, sum_g w_g (P_g + u Q_g)
//    is P + u Q with P = sum_g w_g P_g and Q = sum_g w_g Q_g, summed once per run of
//    points (a strand's parameters rise along it), then per point two fused
//    multiply-adds for P + u Q before c01 and c23. A point outside the run's interval
//    starts a new run, so any order of parameters is right; rising ones are fast.
// The runs pay where a strand has more points than its guides have segments together
// (interpolate_strand_points() chooses); the guide count is a template parameter, so the
// guide loop unrolls.

/// The point's three floats from the folded sum; four floats where the fourth is the next
/// point's x, written over on the next turn.
__attribute__((target("avx2,fma"))) inline void store_point(__m256 sum, bool last, float* out) {
  const __m128 folded = _mm_add_ps(_mm256_castps256_ps128(sum), _mm256_extractf128_ps(sum, 1));
  if (!last) {
    _mm_storeu_ps(out, folded);
    return;
  }
  alignas(16) float xyzw[4];
  _mm_store_ps(xyzw, folded);
  out[0] = xyzw[0];
  out[1] = xyzw[1];
  out[2] = xyzw[2];
}

/// [position | column 0] and [column 1 | column 2] applied to an offset d: c01 = [1 | d0]
/// and c23 = [d1 | d2] multiplied in (a multiply and a fused multiply-add); the point is
/// the sum of the halves (store_point()).
__attribute__((target("avx2,fma"))) inline __m256 apply_offset(const float* d, __m256 columns01,
                                                               __m256 columns23) {
  const __m256 c01 = _mm256_blend_ps(_mm256_set1_ps(1), _mm256_broadcast_ss(d), 0xF0);
  const __m256 c23 = _mm256_blend_ps(_mm256_broadcast_ss(d + 1), _mm256_broadcast_ss(d + 2), 0xF0);
  return _mm256_fmadd_ps(c01, columns01, _mm256_mul_ps(c23, columns23));
}

/// Per guide of a strand: its weight in every lane and its last segment.
template <int kGuides>
struct GuideConstants {
  __m256 weight[kGuides];
  int last[kGuides];
  __attribute__((target("avx2,fma"))) GuideConstants(const float* segments, const float* weights) {
    for (int k = 0; k < kGuides; ++k) {
      weight[k] = _mm256_set1_ps(weights[k]);
      last[k] = static_cast<int>(segments[k]) - 1;
    }
  }
};

template <int kGuides>
__attribute__((target("avx2,fma"))) void interpolate_avx2_per_point(
    const float* const* guide_table, const float* segments, const float* weight,
    const float* parameter, const float* offset, int64_t count, float* out) {
  const GuideConstants<kGuides> guides(segments, weight);
  const __m256* weight_k = guides.weight;
  const int* last = guides.last;
  for (int64_t i = 0; i < count; ++i) {
    const float u = parameter[i];
    __m256 sum01 = _mm256_setzero_ps(), sum23 = _mm256_setzero_ps();
    const __m256 uu = _mm256_set1_ps(u);
    for (int k = 0; k < kGuides; ++k) {
      const int j = std::min(static_cast<int>(u * segments[k]), last[k]);
      const float* a = guide_table[k] + static_cast<int64_t>(j) * kParticleFloats;
      sum01 = _mm256_fmadd_ps(
          weight_k[k], _mm256_fmadd_ps(uu, _mm256_loadu_ps(a + 16), _mm256_loadu_ps(a)), sum01);
      sum23 = _mm256_fmadd_ps(
          weight_k[k], _mm256_fmadd_ps(uu, _mm256_loadu_ps(a + 24), _mm256_loadu_ps(a + 8)), sum23);
    }
    store_point(apply_offset(offset + 3 * i, sum01, sum23), i + 1 == count, out + 3 * i);
  }
}

template <int kGuides>
__attribute__((target("avx2,fma"))) void interpolate_avx2_runs(
    const float* const* guide_table, const float* segments, const float* weight,
    const float* parameter, const float* offset, int64_t count, float* out) {
  const GuideConstants<kGuides> guides(segments, weight);
  const __m256* weight_k = guides.weight;
  const int* last = guides.last;
  // The current run: u in [low, high), and its P and Q.
  float low = 1, high = 0;
  __m256 p01 = _mm256_setzero_ps(), p23 = p01, q01 = p01, q23 = p01;
  for (int64_t i = 0; i < count; ++i) {
    const float u = parameter[i];
    if (!(u >= low && u < high)) {
      low = -INFINITY;
      high = INFINITY;
      p01 = p23 = q01 = q23 = _mm256_setzero_ps();
      for (int k = 0; k < kGuides; ++k) {
        const int j = std::min(static_cast<int>(u * segments[k]), last[k]);
        if (j > 0) low = std::max(low, static_cast<float>(j) / segments[k]);
        if (j < last[k]) high = std::min(high, static_cast<float>(j + 1) / segments[k]);
        const float* a = guide_table[k] + static_cast<int64_t>(j) * kParticleFloats;
        p01 = _mm256_fmadd_ps(weight_k[k], _mm256_loadu_ps(a), p01);
        p23 = _mm256_fmadd_ps(weight_k[k], _mm256_loadu_ps(a + 8), p23);
        q01 = _mm256_fmadd_ps(weight_k[k], _mm256_loadu_ps(a + 16), q01);
        q23 = _mm256_fmadd_ps(weight_k[k], _mm256_loadu_ps(a + 24), q23);
      }
    }
    const __m256 uu = _mm256_set1_ps(u);
    store_point(
        apply_offset(offset + 3 * i, _mm256_fmadd_ps(uu, q01, p01), _mm256_fmadd_ps(uu, q23, p23)),
        i + 1 == count, out + 3 * i);
  }
}

template <int kGuides>
void interpolate_avx2(const float* const* guide_table, const float* segments, const float* weight,
                      const float* parameter, const float* offset, int64_t count, float* out) {
  float all_segments = 0;
  for (int k = 0; k < kGuides; ++k) all_segments += segments[k];
  if (static_cast<float>(count) >= all_segments)
    interpolate_avx2_runs<kGuides>(guide_table, segments, weight, parameter, offset, count, out);
  else
    interpolate_avx2_per_point<kGuides>(guide_table, segments, weight, parameter, offset, count,
                                        out);
}

// The frame as [origin | column 0] and [column 1 | column 2], applied to c01 = [1 | p0] and
// c23 = [p1 | p2] (a multiply and a fused multiply-add) and the halves added.
__attribute__((target("avx2,fma"))) void transform_avx2(const float* frames,
                                                        const int32_t* frame_index,
                                                        const float* local, int64_t count,
                                                        float* out) {
  if (count <= 0) return;  // `frames` may be empty then
  int32_t current = frame_index ? frame_index[0] : 0;
  const float* first = frames + static_cast<int64_t>(current) * kFrameFloats;
  __m256 f01 = _mm256_loadu_ps(first), f23 = _mm256_loadu_ps(first + 8);
  for (int64_t i = 0; i < count; ++i) {
    if (frame_index && frame_index[i] != current) {
      current = frame_index[i];
      const float* f = frames + static_cast<int64_t>(current) * kFrameFloats;
      f01 = _mm256_loadu_ps(f);
      f23 = _mm256_loadu_ps(f + 8);
    }
    store_point(apply_offset(local + 3 * i, f01, f23), i + 1 == count, out + 3 * i);
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
  if (interpolation_uses_avx2()) switch (guide_count) {
      case 1:
        return interpolate_avx2<1>(guide_table, segments, weight, parameter, offset, count, out);
      case 2:
        return interpolate_avx2<2>(guide_table, segments, weight, parameter, offset, count, out);
      case 3:
        return interpolate_avx2<3>(guide_table, segments, weight, parameter, offset, count, out);
      default:
        break;
    }
#endif
  interpolate_strand_points_portable(guide_table, segments, weight, guide_count, parameter, offset,
                                     count, out);
}

void transform_points(const float* frames, const int32_t* frame_index, const float* local,
                      int64_t count, float* out) {
#ifdef HAIR_HAVE_AVX2_KERNEL
  if (interpolation_uses_avx2()) return transform_avx2(frames, frame_index, local, count, out);
#endif
  transform_points_portable(frames, frame_index, local, count, out);
}

}  // namespace hair
