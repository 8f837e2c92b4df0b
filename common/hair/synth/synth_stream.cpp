// A stream of synthetic hair: its arc length and frames, the waves and ringlets wound into
// it, and the pieces it is cut into.
#include "hair/synth/synth_stream.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace hair::synth {

void measure_arc_length(Stream& stream) {
  stream.along_m.assign(stream.points.size(), 0.0);
  for (size_t i = 1; i < stream.points.size(); ++i)
    stream.along_m[i] = stream.along_m[i - 1] + (stream.points[i] - stream.points[i - 1]).norm();
}

void frame_stream(Stream& stream, const Head& head, const std::vector<Vec3>* axis_normal) {
  size_t n = stream.points.size();
  stream.across.resize(n);
  stream.normal.resize(n);
  Vec3 previous_across = Vec3::UnitX();
  for (size_t i = 0; i < n; ++i) {
    Vec3 tangent = stream.points[std::min(i + 1, n - 1)] - stream.points[i > 0 ? i - 1 : 0];
    tangent.normalize();
    Vec3 out = axis_normal ? (*axis_normal)[i] : head.radial(stream.points[i]);
    Vec3 across = tangent.cross(out);
    if (across.norm() < 1e-6) across = previous_across;
    across.normalize();
    if (across.dot(previous_across) < 0 && i > 0) across = -across;
    stream.across[i] = across;
    stream.normal[i] = across.cross(tangent).normalized();
    previous_across = across;
  }
}

void add_waves(Stream& stream, double amplitude_m, double wavelength_m, double phase) {
  if (amplitude_m <= 0) return;
  for (size_t i = 0; i < stream.points.size(); ++i) {
    double s = stream.along_m[i];
    double fade = std::min(1.0, s / 0.03);
    stream.points[i] +=
        fade * amplitude_m * std::sin(2 * kPi * s / wavelength_m + phase) * stream.across[i];
  }
}

void add_ringlet(Stream& stream, const Head& head, double radius_m, double pitch_m, double phase,
                 double clearance_m) {
  for (size_t i = 0; i < stream.points.size(); ++i) {
    double s = stream.along_m[i];
    double fade = std::min(1.0, s / 0.03);
    double turn = 2 * kPi * s / pitch_m + phase;
    stream.points[i] = head.pushed_out(stream.points[i] + fade * radius_m *
                                                              (std::cos(turn) * stream.across[i] +
                                                               std::sin(turn) * stream.normal[i]),
                                       clearance_m);
  }
  measure_arc_length(stream);
  frame_stream(stream, head);
}

std::vector<Piece> cut_pieces(double start_m, double end_m, int count, HairStyle style,
                              const DefectSpec& defects, Rng& rng) {
  std::vector<Piece> pieces;
  double length = end_m - start_m;
  count = std::max(1, std::min(count, static_cast<int>(length / (4 * defects.segment_length_m))));
  double begin = start_m;
  for (int k = 0; k < count; ++k) {
    Piece piece;
    piece.style = style;
    piece.rails = rng.integer(defects.rails_min, defects.rails_max);
    piece.start_m = begin;
    if (k + 1 == count) {
      piece.end_m = end_m;
    } else {
      double junction = start_m + length * (k + 1) / count;
      if (rng.chance(defects.overlap_share)) {
        piece.end_m = junction + 0.5 * defects.overlap_m;
        begin = junction - 0.5 * defects.overlap_m;
      } else {
        piece.end_m = junction - 0.5 * defects.gap_m;
        begin = junction + 0.5 * defects.gap_m;
      }
    }
    pieces.push_back(piece);
  }
  return pieces;
}

}  // namespace hair::synth
