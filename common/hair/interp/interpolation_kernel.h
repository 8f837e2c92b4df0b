#pragma once
// The innermost loop of interpolate_frame(): the points of one strand from up to three
// guides, sum_g w_g (G_g(u) + F_g(u) d), over the per-frame table of guide particles.
// An AVX2 + FMA version is chosen at run time where the processor has them (the build
// targets plain x86-64); both compute the same sums, rounded differently (FMA), so frames
// agree to float rounding across machines and bit for bit on one machine.

#include <array>
#include <cstdint>
#include <vector>

namespace hair {

/// Floats per guide particle in the table, each of its eight columns 4 floats (xyz and a
/// pad). Of the guide's position and frame C = (G, F0, F1, F2), linear along each segment
/// in the arc parameter u: particle j's record holds, per column c of C (floats 8c to
/// 8c + 7), P_j = C_j - j B_j and then Q_j = S B_j, where B_j = C_j+1 - C_j and S is the
/// guide's segment count, so that on segment j (u S in [j, j + 1]) C(u) = P_j + u Q_j.
inline constexpr int kParticleFloats = 32;

/// One strand's interpolated points, point by point. The guide tables must be 32-byte
/// aligned.
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

/// The most runs interpolate_strand_runs() takes for one strand (a run's index is a byte).
inline constexpr int kMaxStrandRuns = 256;

/// Splits a strand's points into runs for interpolate_strand_runs(): consecutive points
/// whose segments start at the same particle of every guide (particle min(floor(u S),
/// S - 1) of a guide of S segments); of one guide, its particles in order from the
/// strand's first to its last, whether a point falls on each or not (so that the kernel
/// reads the guide's records in place). Appends each run's particles (guide_count of them,
/// the rest -1) to `run_particles` and writes each point's run into `run_of_point`;
/// returns the number of runs, or 0 (and appends nothing) where there would be more than
/// kMaxStrandRuns.
int strand_runs(const float* segments, int guide_count, const float* parameter, int64_t count,
                uint8_t* run_of_point, std::vector<std::array<int32_t, 3>>& run_particles);

/// One strand's interpolated points as interpolate_strand_points() computes them, from its
/// runs (strand_runs()): the weighted sum of the guides' records is formed once per run,
/// and each point then costs one record's worth of multiply-adds, with no branch on where
/// its parameter falls. The guide tables must be 32-byte aligned.
///
/// @param run_particles  per run, each guide's particle
/// @param run_count      1 to kMaxStrandRuns
/// @param run_of_point   per point, its run
void interpolate_strand_runs(const float* const* guide_table, const float* weight, int guide_count,
                             const std::array<int32_t, 3>* run_particles, int run_count,
                             const uint8_t* run_of_point, const float* parameter,
                             const float* offset, int64_t count, float* out);

/// The portable version of interpolate_strand_runs().
void interpolate_strand_runs_portable(const float* const* guide_table, const float* weight,
                                      int guide_count, const std::array<int32_t, 3>* run_particles,
                                      int run_count, const uint8_t* run_of_point,
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

/// Whether interpolate_strand_points(), interpolate_strand_runs() and transform_points()
/// run their AVX2 + FMA versions on this machine.
bool interpolation_uses_avx2();

}  // namespace hair
