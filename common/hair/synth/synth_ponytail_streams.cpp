// A ponytail: cap grids from the hairline to a band and tails hanging from it, or coiled
// round it into a bun (ComponentSpec::Kind ponytail).
#include "hair/synth/synth_component_streams.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <utility>

#include "hair/synth/synth_curves.h"

namespace hair::synth {

namespace {

/// A bun's coil for the stream leaving the band at `start_angle` (radians round the band's
/// outward axis `band_out`, from `side` towards `up`): from 6 mm off the band's centre it
/// spirals out to `radius_m` over its first half turn and goes on round at that radius,
/// `length_m` in all, rising off the head by 1 cm a turn so that later turns lie over the
/// earlier ones, kept `clearance_m` off the body. Streams leaving from all round the band
/// fill a ring: a bun.
std::vector<Vec3> bun_coil(const Head& head, const Vec3& band, const Vec3& band_out,
                           const Vec3& side, const Vec3& up, double start_angle, double radius_m,
                           double length_m, double clearance_m) {
  constexpr double kStart_m = 0.006, kRisePerTurn_m = 0.01;
  std::vector<Vec3> points;
  double angle = start_angle, along = 0;
  auto at = [&](double turned) {
    double r = kStart_m + (radius_m - kStart_m) * std::min(1.0, turned / kPi);
    double rise = kRisePerTurn_m * turned / (2 * kPi);
    return Vec3(band + r * (std::cos(angle) * side + std::sin(angle) * up) + rise * band_out);
  };
  points.push_back(at(0));
  while (along < length_m) {
    double turned = angle - start_angle;
    double r = kStart_m + (radius_m - kStart_m) * std::min(1.0, turned / kPi);
    angle += kStep_m / std::max(r, 0.01);
    Vec3 next = head.pushed_out(at(angle - start_angle), clearance_m);
    along += (next - points.back()).norm();
    points.push_back(next);
  }
  return points;
}

}  // namespace

void add_ponytail(const ComponentSpec& component, int component_index, const DefectSpec& defects,
                  const Head& head, Rng& rng, std::vector<Stream>& streams) {
  auto [band, band_out] = band_point(head, component);
  Vec3 side = band_out.cross(Vec3::UnitY()).normalized();
  Vec3 up = side.cross(band_out).normalized();
  std::vector<Vec3> directions = root_directions(component, component.stream_count, rng);
  for (size_t k = 0; k < directions.size(); ++k) {
    double ring_angle = 2 * kPi * static_cast<double>(k) / static_cast<double>(directions.size());
    Vec3 cap_end = band + 0.006 * (std::cos(ring_angle) * side + std::sin(ring_angle) * up);
    Stream stream;
    stream.component = component_index;
    stream.style = HairStyle::fixed;
    stream.points =
        cap_curve(head, directions[k], cap_end, defects.scalp_lift_m, defects.body_clearance_m,
                  CapShape{component.cap_volume_m, component.cap_drape});
    measure_arc_length(stream);
    double cap_length = stream.length_m();
    double total = rng.uniform(component.length_min_m, component.length_max_m);
    double tail_length = std::max(0.05, total - cap_length);
    if (component.bun_radius_m > 0) {
      append_points(stream.points,
                    bun_coil(head, band, band_out, side, up, ring_angle, component.bun_radius_m,
                             tail_length, defects.body_clearance_m));
    } else {
      Vec3 tail_start = (band_out + 0.4 * Vec3(0, -1, 0)).normalized();
      append_points(stream.points, grown_curve(head, cap_end, tail_start, tail_length, 0.05,
                                               defects.body_clearance_m));
    }
    measure_arc_length(stream);
    frame_stream(stream, head);
    double root_width = component.strip_width_m * rng.uniform(0.8, 1.2);
    double tail_width = 0.015 * rng.uniform(0.8, 1.2);
    stream.width_m.resize(stream.points.size());
    for (size_t i = 0; i < stream.points.size(); ++i) {
      double s = stream.along_m[i];
      stream.width_m[i] =
          s < cap_length ? root_width + (0.008 - root_width) * (s / cap_length) : tail_width;
    }
    Piece cap{0.0, cap_length, HairStyle::fixed, defects.cap_rails};
    stream.pieces.push_back(cap);
    double tail_begin = cap_length + component.band_gap_m;
    // A bun is held: fixed hair, as the cap; a tail hangs free.
    const HairStyle tail_style = component.bun_radius_m > 0 ? HairStyle::fixed : HairStyle::normal;
    if (component.bun_radius_m > 0) stream.style = HairStyle::fixed;
    if (tail_begin < stream.length_m() - 2 * defects.segment_length_m) {
      auto tail = cut_pieces(tail_begin, stream.length_m(),
                             rng.integer(1, defects.normal_pieces_max), tail_style, defects, rng);
      stream.pieces.insert(stream.pieces.end(), tail.begin(), tail.end());
    }
    streams.push_back(std::move(stream));
  }
}

}  // namespace hair::synth
