// Short hair lying on the head: cap grids fanning out from a crown whorl down to the
// hairline (ComponentSpec::Kind short_cap).
#include "hair/synth/synth_component_streams.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <utility>

namespace hair::synth {

void add_short_cap(const ComponentSpec& component, int component_index, const DefectSpec& defects,
                   const Head& head, Rng& rng, std::vector<Stream>& streams) {
  // The whorl and a frame around it: first towards the face, second towards +X.
  Vec3 whorl = direction(component.band_azimuth_deg, component.band_polar_deg);
  Vec3 towards_face = Vec3::UnitZ() - Vec3::UnitZ().dot(whorl) * whorl;
  if (towards_face.norm() < 1e-6) towards_face = Vec3::UnitX() - Vec3::UnitX().dot(whorl) * whorl;
  towards_face.normalize();
  Vec3 towards_side = whorl.cross(towards_face);
  auto away_from_whorl = [&](double around_deg, double from_whorl_deg) {
    double around = radians(around_deg), from = radians(from_whorl_deg);
    return Vec3(std::cos(from) * whorl + std::sin(from) * (std::cos(around) * towards_face +
                                                           std::sin(around) * towards_side));
  };
  auto below_hairline = [](const Vec3& dir) {
    double polar_deg = std::acos(std::clamp(dir.y(), -1.0, 1.0)) * 180.0 / kPi;
    double azimuth_deg = std::atan2(dir.x(), dir.z()) * 180.0 / kPi;
    return polar_deg > hairline_polar_deg(azimuth_deg);
  };
  int count = component.stream_count;
  double sector_deg = (component.azimuth_max_deg - component.azimuth_min_deg) / count;
  const double step_deg = kStep_m / head.radius_m * 180.0 / kPi;
  // The whorl turns every grid the same way (neighbours stay side by side): by this much
  // over 90 degrees from the whorl.
  double swirl_deg = rng.uniform(-component.swirl_max_deg, component.swirl_max_deg);
  if (component.swirl_min_deg > 0)  // a magnitude in [min, max], the sign from the draw above
    swirl_deg =
        std::copysign(rng.uniform(component.swirl_min_deg, component.swirl_max_deg), swirl_deg);
  for (int k = 0; k < count; ++k) {
    double around_deg = component.azimuth_min_deg + sector_deg * (k + 0.5 + rng.uniform(-0.1, 0.1));
    double root_deg = rng.uniform(component.polar_min_deg, component.polar_max_deg);
    double margin_deg = rng.uniform(0.0, 4.0);  // the tip this far short of the hairline
    double length = rng.uniform(component.length_min_m, component.length_max_m);
    // Directions from the root away from the whorl until the hairline, the drawn length
    // (measured on the scalp) or the far side of the head.
    std::vector<Vec3> directions;
    double along = 0;
    Vec3 previous = Vec3::Zero();
    for (double from_deg = root_deg; from_deg < 170.0; from_deg += step_deg) {
      double turned_deg = around_deg + swirl_deg * (from_deg - root_deg) / 90.0;
      Vec3 dir = away_from_whorl(turned_deg, from_deg);
      Vec3 margin_dir = away_from_whorl(turned_deg, from_deg + margin_deg);
      if (below_hairline(margin_dir)) break;
      Vec3 p = head.surface(dir).first;
      if (!directions.empty()) along += (p - previous).norm();
      if (along > length) break;
      directions.push_back(dir);
      previous = p;
    }
    if (directions.size() < 2) continue;  // the root is at the hairline
    Stream stream;
    stream.component = component_index;
    stream.style = HairStyle::short_hair;
    stream.trim_tips = false;
    for (size_t i = 0; i < directions.size(); ++i) {
      double lift = defects.scalp_lift_m * (1.0 + 0.5 * static_cast<double>(i) /
                                                      static_cast<double>(directions.size() - 1));
      auto [surface, outward] = head.surface(directions[i]);
      stream.points.push_back(surface + lift * outward);
      stream.scalp_lift_m.push_back(lift);
    }
    // Points found from afar (Head::surface) snap to the body's corners: smooth the
    // curve, keeping it on the scalp.
    for (int pass = 0; pass < 8; ++pass)
      for (size_t i = 1; i + 1 < stream.points.size(); ++i) {
        Vec3 smooth = 0.5 * stream.points[i] + 0.25 * (stream.points[i - 1] + stream.points[i + 1]);
        stream.points[i] = pass < 4 ? on_scalp(head, smooth, stream.scalp_lift_m[i]) : smooth;
      }
    measure_arc_length(stream);
    frame_stream(stream, head);
    double width = component.strip_width_m * rng.uniform(0.9, 1.1);
    stream.width_m.resize(stream.points.size());
    for (size_t i = 0; i < stream.points.size(); ++i) {
      double from_whorl = std::acos(std::clamp(directions[i].dot(whorl), -1.0, 1.0));
      stream.width_m[i] = width * std::max(0.15, std::sin(from_whorl));
    }
    stream.pieces = cut_pieces(0, stream.length_m(), rng.integer(1, defects.normal_pieces_max),
                               HairStyle::short_hair, defects, rng);
    for (Piece& piece : stream.pieces) piece.rails = defects.cap_rails;
    streams.push_back(std::move(stream));
  }
}

}  // namespace hair::synth
