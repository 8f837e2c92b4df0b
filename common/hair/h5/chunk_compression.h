#pragma once
// A chunk as HDF5's shuffle + deflate filters would write it, made by us in parallel: the
// bytes shuffled, then one zlib stream deflated in pieces (pigz's method: each piece ends
// on a byte boundary, the checksums are combined), pieces of noise stored. Handed to
// H5Dwrite_chunk, it reads back through HDF5's own filters.

#include <cstddef>
#include <vector>

namespace hair::h5 {

/// A piece is stored, not deflated, where the first kStoreSampleBytes of it deflate by
/// less than this share: deflate's time on noise (a float's low bytes) buys nothing. A
/// stored piece is still part of a valid deflate stream; readers see no difference.
inline constexpr double kStoreBelowSaving = 0.05;
inline constexpr size_t kStoreSampleBytes = size_t{32} << 10;

/// Deflate level for a piece of shuffled bytes: 0 (stored) where its first
/// kStoreSampleBytes (a quarter of a piece under 128 KiB, at least 4 KiB) do not shrink by
/// kStoreBelowSaving at `level`, else `level`. The low
/// bytes of float coordinates (the first half of a shuffled chunk) are noise: deflate
/// spent most of a frame's time on them and saved nothing.
int piece_deflate_level(const unsigned char* data, size_t size, unsigned level);

/// HDF5's shuffle filter: byte k of every value, value by value, for k = 0..size-1.
void shuffle_bytes(const unsigned char* values, size_t count, size_t value_size,
                   unsigned char* shuffled);

/// `bytes` (`size` of them) as one zlib stream (RFC 1950) whose pieces of `piece_bytes`
/// are deflated at piece_deflate_level(piece, level), on all OpenMP threads (one thread
/// inside a parallel region); empty on failure.
std::vector<unsigned char> zlib_stream_in_pieces(const unsigned char* bytes, size_t size,
                                                 size_t piece_bytes, unsigned level);

/// A chunk as HDF5's shuffle + deflate filters would store it: `count` values of
/// `value_size` bytes shuffled, then zlib_stream_in_pieces() of them; empty on failure.
std::vector<unsigned char> shuffled_zlib_chunk(const unsigned char* values, size_t count,
                                               size_t value_size, size_t piece_bytes,
                                               unsigned level);

}  // namespace hair::h5
