#pragma once
// The innermost loop of interpolate_frame(): the points of one strand from up to three
// guides, sum_g w_g (G_g(u) + F_g(u) d), over the per-frame table of guide particles.
// An AVX2 + FMA version is chosen at run time where the processor has them (the build
// targets plain x86-64); both compute the same sums, rounded differently (FMA), so frames
// agree to float rounding across machines and bit for bit on one machine.

#include <cstdint>

namespace hair {

/// Floats per guide particle in the table, each of its eight columns 4 floats (xyz and a
/// pad). Of the guide's position and frame C = (G, F0, F1, F2), linear along each segment
/// in the arc parameter u: particle j's record holds P_j = C_j - j B_j and then Q_j = S B_j,
/// where B_j = C_j+1 - C_j and S is the guide's segment count, so that on segment j
/// (u S in [j, j + 1]) C(u) = P_j + u Q_j.
inline constexpr int kParticleFloats = 32;

/// One strand's interpolated points.
///
/// @param guide_table  per used guide, its first particle's record in the table
/// @param segments     per used guide, its particle count - 1 (at least 1)
/// @param weight       per used guide
/// @param guide_count  1 to 3
/// @param parameter    per point: arc parameter u in [0, 1]
/// @param offset       per point: rest offset d, 3 floats
/// @param count        points
/// @param out          per point: 3 floats
void interpolate_strand_points(const float* const* guide_table, const float* segments,
                               const float* weight, int guide_count, const float* parameter,
                               const float* offset, int64_t count, float* out);

/// The portable version, which interpolate_strand_points() runs without AVX2 + FMA (for
/// tests that compare the two).
void interpolate_strand_points_portable(const float* const* guide_table, const float* segments,
                                        const float* weight, int guide_count,
                                        const float* parameter, const float* offset, int64_t count,
                                        float* out);

/// Floats per rigid frame in the table of transform_points(): origin, then the three columns
/// of the rotation, each 4 floats (xyz and a pad).
inline constexpr int kFrameFloats = 16;

/// Points carried by rigid frames: out_i = o + R p_i for the frame `frame_index[i]` of
/// `frames` (the head, a wisp tetrahedron), or frame 0 for every point where
/// `frame_index` is null. Consecutive points of the same frame reuse it.
///
/// @param frames       per frame: kFrameFloats floats
/// @param frame_index  per point, or null
/// @param local        per point: its position in its frame, 3 floats
/// @param count        points
/// @param out          per point: 3 floats
void transform_points(const float* frames, const int32_t* frame_index, const float* local,
                      int64_t count, float* out);

/// The portable version of transform_points().
void transform_points_portable(const float* frames, const int32_t* frame_index, const float* local,
                               int64_t count, float* out);

/// Whether interpolate_strand_points() and transform_points() run their AVX2 + FMA
/// versions on this machine.
bool interpolation_uses_avx2();

}  // namespace hair
