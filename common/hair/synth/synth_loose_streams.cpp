// Loose hair: strips and cards hanging from the scalp or standing off it, one stream per
// root (ComponentSpec::Kind normal and short_cards).
#include "hair/synth/synth_component_streams.h"

#include <cmath>
#include <utility>

#include "hair/synth/synth_curves.h"

namespace hair::synth {

namespace {

/// Where hair from a root is combed: away from the crown and down, front roots
/// combed back over the head.
Vec3 comb_direction(const Head& head, const Vec3& root, const Vec3& outward) {
  Vec3 wish;
  Vec3 from_centre = root - head.centre;
  if (from_centre.z() > 0.3 * head.radius_m)
    wish = Vec3(0.0, 0.2, -1.0);
  else
    wish = Vec3(from_centre.x(), 0.0, from_centre.z()).normalized() + Vec3(0, -0.6, -0.3);
  Vec3 tangent = wish - wish.dot(outward) * outward;
  if (tangent.norm() < 1e-6) tangent = Vec3(0, 0, -1);
  return (tangent.normalized() + 0.1 * outward).normalized();
}

}  // namespace

void add_loose_streams(const ComponentSpec& component, int component_index,
                       const DefectSpec& defects, const Head& head, Rng& rng,
                       std::vector<Stream>& streams) {
  bool is_short = component.kind == ComponentSpec::Kind::short_cards;
  for (const Vec3& dir : root_directions(component, component.stream_count, rng)) {
    auto [surface, outward] = head.surface(dir);
    Vec3 root = surface + defects.scalp_lift_m * outward;
    Vec3 start = comb_direction(head, root, outward);
    if (is_short) start = (start + 0.8 * outward).normalized();
    double length = rng.uniform(component.length_min_m, component.length_max_m);
    Stream stream;
    stream.component = component_index;
    stream.style = is_short ? HairStyle::short_hair : HairStyle::normal;
    stream.points = grown_curve(head, root, start, length, is_short ? 0.15 : 0.06,
                                defects.body_clearance_m, !is_short);
    if (!is_short && component.hang_volume_m > 0)
      stand_off(head, stream.points, component.hang_volume_m, defects.body_clearance_m);
    measure_arc_length(stream);
    frame_stream(stream, head);
    add_waves(stream, component.wave_amplitude_m, component.wavelength_m, rng.uniform(0, 2 * kPi));
    measure_arc_length(stream);
    if (component.ringlet_radius_m > 0) {
      add_ringlet(stream, head, component.ringlet_radius_m * rng.uniform(0.85, 1.15),
                  component.ringlet_pitch_m * rng.uniform(0.85, 1.15), rng.uniform(0, 2 * kPi),
                  defects.body_clearance_m);
    }
    frame_stream(stream, head);
    stream.tube = component.tube_sides > 0;
    double width = component.strip_width_m * rng.uniform(0.8, 1.2);
    stream.width_m.assign(stream.points.size(), width);
    int pieces = is_short ? 1 : rng.integer(1, defects.normal_pieces_max);
    stream.pieces = cut_pieces(0, stream.length_m(), pieces, stream.style, defects, rng);
    streams.push_back(std::move(stream));
  }
}

}  // namespace hair::synth
