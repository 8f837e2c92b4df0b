#include "hair/h5/chunk_compression.h"

#include <zlib.h>

#include <algorithm>

namespace hair::h5 {
namespace {

/// One piece of a deflate stream: raw deflate of `size` bytes, ended by a sync flush (so
/// that the next piece starts on a byte boundary) or, for the last, by the final block;
/// and the piece's Adler-32.
struct DeflatePiece {
  std::vector<unsigned char> bytes;
  uLong adler = 0;
  bool ok = false;
};

DeflatePiece deflate_piece(const unsigned char* data, size_t size, bool last, unsigned level) {
  DeflatePiece piece;
  piece.adler = adler32(adler32(0, nullptr, 0), data, static_cast<uInt>(size));
  z_stream stream{};
  if (deflateInit2(&stream, piece_deflate_level(data, size, level), Z_DEFLATED, -15, 8,
                   Z_DEFAULT_STRATEGY) != Z_OK)
    return piece;
  piece.bytes.resize(deflateBound(&stream, static_cast<uLong>(size)) + 16);
  stream.next_in = const_cast<unsigned char*>(data);
  stream.avail_in = static_cast<uInt>(size);
  stream.next_out = piece.bytes.data();
  stream.avail_out = static_cast<uInt>(piece.bytes.size());
  int status = deflate(&stream, last ? Z_FINISH : Z_SYNC_FLUSH);
  piece.ok = last ? status == Z_STREAM_END : (status == Z_OK && stream.avail_in == 0);
  piece.bytes.resize(piece.bytes.size() - stream.avail_out);
  deflateEnd(&stream);
  return piece;
}

}  // namespace

int piece_deflate_level(const unsigned char* data, size_t size, unsigned level) {
  // A quarter of a small piece at most, so that deflating a piece that shrinks costs
  // little more than once.
  const size_t sample =
      std::min(kStoreSampleBytes, std::max(size / 4, std::min(size, size_t{4096})));
  if (sample == 0) return static_cast<int>(level);
  std::vector<unsigned char> out(compressBound(static_cast<uLong>(sample)));
  uLongf out_size = static_cast<uLongf>(out.size());
  if (compress2(out.data(), &out_size, data, static_cast<uLong>(sample), static_cast<int>(level)) !=
      Z_OK)
    return static_cast<int>(level);
  const bool shrinks =
      static_cast<double>(out_size) < (1.0 - kStoreBelowSaving) * static_cast<double>(sample);
  return shrinks ? static_cast<int>(level) : 0;
}

void shuffle_bytes(const unsigned char* values, size_t count, size_t value_size,
                   unsigned char* shuffled) {
#pragma omp parallel for schedule(static)
  for (size_t k = 0; k < value_size; ++k)
    for (size_t i = 0; i < count; ++i) shuffled[k * count + i] = values[i * value_size + k];
}

std::vector<unsigned char> zlib_stream_in_pieces(const unsigned char* bytes, size_t size,
                                                 size_t piece_bytes, unsigned level) {
  const size_t pieces = std::max<size_t>(1, (size + piece_bytes - 1) / piece_bytes);
  auto piece_size = [&](size_t p) {
    const size_t first = p * piece_bytes;
    return std::min(size - std::min(first, size), piece_bytes);
  };
  std::vector<DeflatePiece> deflated(pieces);
#pragma omp parallel for schedule(dynamic)
  for (size_t p = 0; p < pieces; ++p)
    deflated[p] = deflate_piece(bytes + p * piece_bytes, piece_size(p), p + 1 == pieces, level);
  // A zlib header (deflate, 32 KiB window; its level bits only inform), the pieces, and
  // the Adler-32 of all the bytes, big-endian.
  std::vector<unsigned char> stream = {0x78, 0x01};
  uLong adler = adler32(0, nullptr, 0);
  for (size_t p = 0; p < pieces; ++p) {
    if (!deflated[p].ok) return {};
    stream.insert(stream.end(), deflated[p].bytes.begin(), deflated[p].bytes.end());
    adler = adler32_combine(adler, deflated[p].adler, static_cast<z_off_t>(piece_size(p)));
  }
  for (int shift = 24; shift >= 0; shift -= 8)
    stream.push_back(static_cast<unsigned char>((adler >> shift) & 0xff));
  return stream;
}

std::vector<unsigned char> shuffled_zlib_chunk(const unsigned char* values, size_t count,
                                               size_t value_size, size_t piece_bytes,
                                               unsigned level) {
  std::vector<unsigned char> shuffled(count * value_size);
  shuffle_bytes(values, count, value_size, shuffled.data());
  return zlib_stream_in_pieces(shuffled.data(), shuffled.size(), piece_bytes, level);
}

}  // namespace hair::h5
