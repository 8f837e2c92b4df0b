#include "hair/interp/interpolation_kernel.h"

#include <algorithm>
#include <cmath>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define HAIR_HAVE_AVX2_KERNEL 1
#endif

namespace hair {
namespace {

/// The particle that starts the segment of a guide of `segments` segments at arc parameter u.
inline int particle_index(float segments, float u) {
  return std::min(static_cast<int>(u * segments), static_cast<int>(segments) - 1);
}

/// The record of that particle.
inline const float* particle_at(const float* table, float segments, float u) {
  return table + static_cast<int64_t>(particle_index(segments, u)) * kParticleFloats;
}

/// sum_g w_g (P_g e + u Q_g e) for e = (1, d) over the records a_g, in float.
inline void weighted_point(const float* const* records, const float* weight, int guide_count,
                           float u, const float* d, float* out) {
  const float e[4] = {1, d[0], d[1], d[2]};
  float sum[3] = {0, 0, 0};
  for (int k = 0; k < guide_count; ++k) {
    const float* a = records[k];
    for (int r = 0; r < 3; ++r) {
      float p = 0;
      for (int c = 0; c < 4; ++c) p += e[c] * (a[8 * c + r] + u * a[8 * c + 4 + r]);
      sum[r] += weight[k] * p;
    }
  }
  for (int r = 0; r < 3; ++r) out[r] = sum[r];
}

}  // namespace

void interpolate_strand_points_portable(const float* const* guide_table, const float* segments,
                                        const float* weight, int guide_count,
                                        const float* parameter, const float* offset, int64_t count,
                                        float* out) {
  for (int64_t i = 0; i < count; ++i) {
    const float* records[3];
    for (int k = 0; k < guide_count; ++k)
      records[k] = particle_at(guide_table[k], segments[k], parameter[i]);
    weighted_point(records, weight, guide_count, parameter[i], offset + 3 * i, out + 3 * i);
  }
}

int strand_runs(const float* segments, int guide_count, const float* parameter, int64_t count,
                uint8_t* run_of_point, std::vector<std::array<int32_t, 3>>& run_particles) {
  if (count <= 0) return 0;
  if (guide_count == 1) {
    // Run r is particle first + r, from the strand's first particle to its last.
    int first = particle_index(segments[0], parameter[0]), last = first;
    for (int64_t i = 1; i < count; ++i) {
      const int particle = particle_index(segments[0], parameter[i]);
      first = std::min(first, particle);
      last = std::max(last, particle);
    }
    if (last - first >= kMaxStrandRuns) return 0;
    for (int64_t i = 0; i < count; ++i)
      run_of_point[i] = static_cast<uint8_t>(particle_index(segments[0], parameter[i]) - first);
    for (int particle = first; particle <= last; ++particle)
      run_particles.push_back({particle, -1, -1});
    return last - first + 1;
  }
  const size_t first = run_particles.size();
  std::array<int32_t, 3> current = {-1, -1, -1};
  int runs = 0;
  for (int64_t i = 0; i < count; ++i) {
    std::array<int32_t, 3> particles = {-1, -1, -1};
    for (int k = 0; k < guide_count; ++k)
      particles[static_cast<size_t>(k)] = particle_index(segments[k], parameter[i]);
    if (runs == 0 || particles != current) {
      if (runs == kMaxStrandRuns) {
        run_particles.resize(first);
        return 0;
      }
      current = particles;
      run_particles.push_back(particles);
      ++runs;
    }
    run_of_point[i] = static_cast<uint8_t>(runs - 1);
  }
  return runs;
}

void interpolate_strand_runs_portable(const float* const* guide_table, const float* weight,
                                      int guide_count, const std::array<int32_t, 3>* run_particles,
                                      int /*run_count*/, const uint8_t* run_of_point,
                                      const float* parameter, const float* offset, int64_t count,
                                      float* out) {
  for (int64_t i = 0; i < count; ++i) {
    const std::array<int32_t, 3>& particles = run_particles[run_of_point[i]];
    const float* records[3];
    for (int k = 0; k < guide_count; ++k)
      records[k] = guide_table[k] +
                   static_cast<int64_t>(particles[static_cast<size_t>(k)]) * kParticleFloats;
    weighted_point(records, weight, guide_count, parameter[i], offset + 3 * i, out + 3 * i);
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
// A particle's record is four 8-float registers R_c = [P_c | Q_c], c = position and the
// frame's three columns. For a point with offset d, s = R_0 + d0 R_1 + d1 R_2 + d2 R_3
// (three fused multiply-adds) is [P e | Q e] with e = (1, d), and the point is
// P e + u Q e: s's low half plus u times its high half (one more). Two versions:
//  - in runs (strand_runs()): the weighted sum of the guides' records R = sum_g w_g R_g
//    once per run into a table on the stack, then per point its run's R (loaded by the
//    point's run index: no branch on the parameter, whose changes of run a branch
//    predictor cannot guess) and the four multiply-adds above;
//  - per point, for a strand of more runs than a byte counts: s per guide at the point's
//    particle, weighted into one sum.
// The guide count is a template parameter, so the guide loops unroll.

/// The point's three floats; four where the fourth is the next point's x, written over on
/// the next turn.
__attribute__((target("avx2,fma"))) inline void store_point(__m128 point, bool last, float* out) {
  if (!last) {
    _mm_storeu_ps(out, point);
    return;
  }
  alignas(16) float xyzw[4];
  _mm_store_ps(xyzw, point);
  out[0] = xyzw[0];
  out[1] = xyzw[1];
  out[2] = xyzw[2];
}

/// [P e | Q e] for e = (1, d) from a record's four registers (32-byte aligned), with d's
/// components in every lane.
__attribute__((target("avx2,fma"))) inline __m256 apply_offset(const float* record, __m256 d0,
                                                               __m256 d1, __m256 d2) {
  __m256 s = _mm256_fmadd_ps(d0, _mm256_load_ps(record + 8), _mm256_load_ps(record));
  s = _mm256_fmadd_ps(d1, _mm256_load_ps(record + 16), s);
  return _mm256_fmadd_ps(d2, _mm256_load_ps(record + 24), s);
}

/// P e + u Q e from [P e | Q e].
__attribute__((target("avx2,fma"))) inline __m128 at_parameter(__m256 s, float u) {
  return _mm_fmadd_ps(_mm_set1_ps(u), _mm256_extractf128_ps(s, 1), _mm256_castps256_ps128(s));
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
  for (int64_t i = 0; i < count; ++i) {
    const float u = parameter[i];
    const float* d = offset + 3 * i;
    const __m256 d0 = _mm256_broadcast_ss(d), d1 = _mm256_broadcast_ss(d + 1),
                 d2 = _mm256_broadcast_ss(d + 2);
    __m256 sum = _mm256_setzero_ps();
    for (int k = 0; k < kGuides; ++k) {
      const int j = std::min(static_cast<int>(u * segments[k]), guides.last[k]);
      const float* a = guide_table[k] + static_cast<int64_t>(j) * kParticleFloats;
      sum = _mm256_fmadd_ps(guides.weight[k], apply_offset(a, d0, d1, d2), sum);
    }
    store_point(at_parameter(sum, u), i + 1 == count, out + 3 * i);
  }
}

/// Point i of a strand in runs, from its run's record.
__attribute__((target("avx2,fma"))) inline __m128 run_point(const float* records,
                                                            const uint8_t* run_of_point,
                                                            const float* parameter,
                                                            const float* offset, int64_t i) {
  const float* record = records + static_cast<size_t>(run_of_point[i]) * kParticleFloats;
  const float* d = offset + 3 * i;
  return at_parameter(apply_offset(record, _mm256_broadcast_ss(d), _mm256_broadcast_ss(d + 1),
                                   _mm256_broadcast_ss(d + 2)),
                      parameter[i]);
}

template <int kGuides>
__attribute__((target("avx2,fma"))) void interpolate_avx2_runs(
    const float* const* guide_table, const float* weight,
    const std::array<int32_t, 3>* run_particles, int run_count, const uint8_t* run_of_point,
    const float* parameter, const float* offset, int64_t count, float* out) {
  // Per run, the weighted sum of its guides' records; for one guide of weight 1, whose runs
  // are its particles in order (strand_runs()), the guide's own records.
  alignas(32) float weighted[kMaxStrandRuns * kParticleFloats];
  const float* records = weighted;
  if (kGuides == 1 && weight[0] == 1) {
    records = guide_table[0] + static_cast<int64_t>(run_particles[0][0]) * kParticleFloats;
  } else {
    for (int r = 0; r < run_count; ++r) {
      const float* a[kGuides];
      for (int k = 0; k < kGuides; ++k)
        a[k] = guide_table[k] +
               static_cast<int64_t>(run_particles[r][static_cast<size_t>(k)]) * kParticleFloats;
      for (int c = 0; c < 4; ++c) {
        __m256 sum = _mm256_mul_ps(_mm256_set1_ps(weight[0]), _mm256_load_ps(a[0] + 8 * c));
        for (int k = 1; k < kGuides; ++k)
          sum = _mm256_fmadd_ps(_mm256_set1_ps(weight[k]), _mm256_load_ps(a[k] + 8 * c), sum);
        _mm256_store_ps(weighted + r * kParticleFloats + 8 * c, sum);
      }
    }
  }
  // Each point's four floats written (the fourth over the next point's x) but the last's.
  for (int64_t i = 0; i + 1 < count; ++i)
    _mm_storeu_ps(out + 3 * i, run_point(records, run_of_point, parameter, offset, i));
  if (count > 0)
    store_point(run_point(records, run_of_point, parameter, offset, count - 1), true,
                out + 3 * (count - 1));
}

// o + p0 c0 + p1 c1 + p2 c2 on 4-float registers (three fused multiply-adds).
__attribute__((target("avx2,fma"))) void transform_avx2(const float* frames,
                                                        const int32_t* frame_index,
                                                        const float* local, int64_t count,
                                                        float* out) {
  if (count <= 0) return;  // `frames` may be empty then
  int32_t current = frame_index ? frame_index[0] : 0;
  const float* first = frames + static_cast<int64_t>(current) * kFrameFloats;
  __m128 o = _mm_loadu_ps(first), c0 = _mm_loadu_ps(first + 4), c1 = _mm_loadu_ps(first + 8),
         c2 = _mm_loadu_ps(first + 12);
  for (int64_t i = 0; i < count; ++i) {
    if (frame_index && frame_index[i] != current) {
      current = frame_index[i];
      const float* f = frames + static_cast<int64_t>(current) * kFrameFloats;
      o = _mm_loadu_ps(f);
      c0 = _mm_loadu_ps(f + 4);
      c1 = _mm_loadu_ps(f + 8);
      c2 = _mm_loadu_ps(f + 12);
    }
    const float* p = local + 3 * i;
    __m128 point = _mm_fmadd_ps(_mm_broadcast_ss(p), c0, o);
    point = _mm_fmadd_ps(_mm_broadcast_ss(p + 1), c1, point);
    point = _mm_fmadd_ps(_mm_broadcast_ss(p + 2), c2, point);
    store_point(point, i + 1 == count, out + 3 * i);
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
        return interpolate_avx2_per_point<1>(guide_table, segments, weight, parameter, offset,
                                             count, out);
      case 2:
        return interpolate_avx2_per_point<2>(guide_table, segments, weight, parameter, offset,
                                             count, out);
      case 3:
        return interpolate_avx2_per_point<3>(guide_table, segments, weight, parameter, offset,
                                             count, out);
      default:
        break;
    }
#endif
  interpolate_strand_points_portable(guide_table, segments, weight, guide_count, parameter, offset,
                                     count, out);
}

void interpolate_strand_runs(const float* const* guide_table, const float* weight, int guide_count,
                             const std::array<int32_t, 3>* run_particles, int run_count,
                             const uint8_t* run_of_point, const float* parameter,
                             const float* offset, int64_t count, float* out) {
#ifdef HAIR_HAVE_AVX2_KERNEL
  if (interpolation_uses_avx2()) switch (guide_count) {
      case 1:
        return interpolate_avx2_runs<1>(guide_table, weight, run_particles, run_count, run_of_point,
                                        parameter, offset, count, out);
      case 2:
        return interpolate_avx2_runs<2>(guide_table, weight, run_particles, run_count, run_of_point,
                                        parameter, offset, count, out);
      case 3:
        return interpolate_avx2_runs<3>(guide_table, weight, run_particles, run_count, run_of_point,
                                        parameter, offset, count, out);
      default:
        break;
    }
#endif
  interpolate_strand_runs_portable(guide_table, weight, guide_count, run_particles, run_count,
                                   run_of_point, parameter, offset, count, out);
}

void transform_points(const float* frames, const int32_t* frame_index, const float* local,
                      int64_t count, float* out) {
#ifdef HAIR_HAVE_AVX2_KERNEL
  if (interpolation_uses_avx2()) return transform_avx2(frames, frame_index, local, count, out);
#endif
  transform_points_portable(frames, frame_index, local, count, out);
}

}  // namespace hair
