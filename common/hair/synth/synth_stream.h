#pragma once
// A stream of synthetic hair: a centre curve with a frame and a width at every point, and
// the pieces it is cut into; its arc length, frames, waves and ringlets.

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "hair/synth/synth_head.h"
#include "hair/synth/synth_model.h"
#include "hair/synth/synth_rng.h"

namespace hair::synth {

inline constexpr double kStep_m = 0.004;  ///< spacing of centre-curve points

/// A part of a stream that becomes one patch.
struct Piece {
  double start_m = 0, end_m = 0;
  HairStyle style = HairStyle::normal;
  int rails = 2;
};

/// A stream: a centre curve with a frame and a width at every point, and its pieces.
struct Stream {
  std::vector<Vec3> points;
  std::vector<double> along_m;  // arc length
  std::vector<Vec3> across;     // unit, across the strip
  std::vector<Vec3> normal;     // unit, out of the strip
  std::vector<double> width_m;
  std::vector<Piece> pieces;
  HairStyle style = HairStyle::normal;
  int component = 0;
  bool trim_tips = true;  // true strands end at slightly different lengths
  bool tube = false;      // meshed as tubes: the true strands fill the tube's round section
  /// Per point, for hair lying on the scalp (short caps): every point across the stream
  /// is put on the head surface at this lift (on_scalp); empty: a flat strip.
  std::vector<double> scalp_lift_m;

  double length_m() const { return along_m.back(); }

  /// Index i with along_m[i] <= s < along_m[i+1] and the weight of point i + 1.
  std::pair<size_t, double> locate(double s) const {
    s = std::clamp(s, 0.0, length_m());
    size_t i =
        static_cast<size_t>(std::upper_bound(along_m.begin(), along_m.end(), s) - along_m.begin());
    i = std::clamp<size_t>(i, 1, along_m.size() - 1) - 1;
    double span = along_m[i + 1] - along_m[i];
    return {i, span > 0 ? (s - along_m[i]) / span : 0.0};
  }
  Vec3 point_at(double s) const {
    auto [i, w] = locate(s);
    return (1 - w) * points[i] + w * points[i + 1];
  }
  Vec3 across_at(double s) const {
    auto [i, w] = locate(s);
    return ((1 - w) * across[i] + w * across[i + 1]).normalized();
  }
  Vec3 normal_at(double s) const {
    auto [i, w] = locate(s);
    return ((1 - w) * normal[i] + w * normal[i + 1]).normalized();
  }
  double width_at(double s) const {
    auto [i, w] = locate(s);
    return (1 - w) * width_m[i] + w * width_m[i + 1];
  }
  double scalp_lift_at(double s) const {
    auto [i, w] = locate(s);
    return (1 - w) * scalp_lift_m[i] + w * scalp_lift_m[i + 1];
  }
};

/// Measures `stream.along_m`, the arc length from the root to each of its points.
void measure_arc_length(Stream& stream);

/// Frames along the curve: across = tangent x radial (the strip lies on the head's
/// surface, or flat around its vertical axis below it), unless `axis_normal` gives
/// the normal to keep facing (braid pieces facing out of the braid).
void frame_stream(Stream& stream, const Head& head, const std::vector<Vec3>* axis_normal = nullptr);

/// Adds waves across the strip (amplitude fading in over the first 3 cm).
void add_waves(Stream& stream, double amplitude_m, double wavelength_m, double phase);

/// Winds the stream round its own curve in a helix of `radius_m` and `pitch_m` per turn
/// along it (fading in over the first 3 cm, as waves do), a corkscrew ringlet, kept
/// `clearance_m` off the body; then its arc lengths and frames are measured again.
void add_ringlet(Stream& stream, const Head& head, double radius_m, double pitch_m, double phase,
                 double clearance_m);

/// Cuts [start, end] into `count` pieces with gaps (or overlaps) at the junctions.
std::vector<Piece> cut_pieces(double start_m, double end_m, int count, HairStyle style,
                              const DefectSpec& defects, Rng& rng);

}  // namespace hair::synth
