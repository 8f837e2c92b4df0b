// A braid: cap grids to the braid's top, then three streams interleaving round a hanging
// axis, each lobe woven from one or more cards (ComponentSpec::Kind braid).
#include "hair/synth/synth_component_streams.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <utility>

#include "hair/synth/synth_curves.h"

namespace hair::synth {

namespace {

// The tightest a braid's axis bends: about the braid's width (twice braid_width_m).
constexpr double kBraidMinBendRadius_m = 0.03;

/// `lobe` moved across itself by `offset_m` times its taper at each point: a card beside the
/// lobe's centre. Across is perpendicular to the lobe and to the braid's outward direction.
std::vector<Vec3> card_beside_lobe(const std::vector<Vec3>& lobe, const std::vector<Vec3>& out,
                                   const std::vector<double>& taper, double offset_m) {
  std::vector<Vec3> card = lobe;
  for (size_t i = 0; offset_m != 0 && i < lobe.size(); ++i) {
    Vec3 tangent = lobe[std::min(i + 1, lobe.size() - 1)] - lobe[i > 0 ? i - 1 : 0];
    Vec3 across = tangent.cross(out[i]);
    if (across.norm() > 1e-12) card[i] += offset_m * taper[i] * across.normalized();
  }
  return card;
}

}  // namespace

void add_braid(const ComponentSpec& component, int component_index, const DefectSpec& defects,
               const Head& head, Rng& rng, std::vector<Stream>& streams) {
  auto [band_top, top_out] = band_point(head, component);
  const Vec3 top = band_top + component.braid_lift_m * top_out;
  double length = rng.uniform(component.length_min_m, component.length_max_m);
  // A lifted braid leaves its top backwards, out from the head, before gravity bends it down.
  const double start_down = component.braid_lift_m > 0 ? 0.3 : 0.8;
  std::vector<Vec3> axis =
      grown_curve(head, top, (top_out + start_down * Vec3(0, -1, 0)).normalized(), length, 0.05,
                  defects.body_clearance_m + component.braid_depth_m);
  round_creases(head, axis, kBraidMinBendRadius_m,
                defects.body_clearance_m + component.braid_depth_m);
  std::vector<double> axis_along(axis.size(), 0.0);
  for (size_t i = 1; i < axis.size(); ++i)
    axis_along[i] = axis_along[i - 1] + (axis[i] - axis[i - 1]).norm();
  // Frame of the axis: out of the braid (away from the head) and across it.
  std::vector<Vec3> axis_out(axis.size()), axis_side(axis.size());
  for (size_t i = 0; i < axis.size(); ++i) {
    Vec3 tangent = (axis[std::min(i + 1, axis.size() - 1)] - axis[i > 0 ? i - 1 : 0]).normalized();
    Vec3 out = head.radial(axis[i]);
    Vec3 side = tangent.cross(out).normalized();
    axis_side[i] = side;
    axis_out[i] = side.cross(tangent).normalized();
  }
  double sector = (component.azimuth_max_deg - component.azimuth_min_deg) / 3.0;
  double omega = 2 * kPi / component.braid_period_m;
  // The braid's width at a share of the way from its top (1) to its tip
  // (braid_tip_width_share).
  auto braid_taper = [&](double share) {
    return 1.0 - (1.0 - component.braid_tip_width_share) * std::clamp(share, 0.0, 1.0);
  };
  const int cards = std::max(1, component.braid_cards_per_lobe);
  for (int k = 0; k < 3; ++k) {
    double phase = 2 * kPi * k / 3.0;
    std::vector<Vec3> lobe, braid_out;
    std::vector<double> lobe_taper;
    for (size_t i = 0; i < axis.size(); ++i) {
      double t = omega * axis_along[i] + phase;
      double taper = braid_taper(axis_along[i] / std::max(axis_along.back(), 1e-9));
      lobe.push_back(axis[i] + taper * (component.braid_width_m * std::sin(t) * axis_side[i] +
                                        component.braid_depth_m * std::sin(2 * t) * axis_out[i]));
      lobe_taper.push_back(taper);
      braid_out.push_back(axis_out[i]);
    }
    // The lobe's cards lie side by side across it, overlapping by half a strip width.
    for (int card = 0; card < cards; ++card) {
      const double card_offset = (card - 0.5 * (cards - 1)) * 0.5 * component.strip_width_m;
      std::vector<Vec3> braid_points = card_beside_lobe(lobe, axis_out, lobe_taper, card_offset);
      double azimuth = component.azimuth_min_deg + sector * (k + (card + 0.5) / cards);
      double polar = std::min(component.polar_max_deg, hairline_polar_deg(azimuth)) - 8.0;
      Vec3 root_dir = direction(azimuth, polar);
      Stream stream;
      stream.component = component_index;
      stream.style = HairStyle::braided;
      stream.points = cap_curve(head, root_dir, braid_points.front(), defects.scalp_lift_m,
                                defects.body_clearance_m,
                                CapShape{component.cap_volume_m, component.cap_drape});
      size_t cap_points = stream.points.size();
      append_points(stream.points, braid_points);
      measure_arc_length(stream);
      double cap_length = stream.along_m[cap_points - 1];
      // Cap points face out of the head; braid points face out of the braid.
      std::vector<Vec3> facing;
      for (size_t i = 0; i < stream.points.size(); ++i)
        facing.push_back(i < cap_points
                             ? head.radial(stream.points[i])
                             : braid_out[std::min(i - cap_points + 1, braid_out.size() - 1)]);
      frame_stream(stream, head, &facing);
      double root_width = std::min(0.12, radians(sector / cards) * head.radius_m * 0.8);
      stream.width_m.resize(stream.points.size());
      for (size_t i = 0; i < stream.points.size(); ++i) {
        double s = stream.along_m[i];
        stream.width_m[i] =
            s < cap_length ? root_width + (component.strip_width_m - root_width) * (s / cap_length)
                           : component.strip_width_m *
                                 braid_taper((s - cap_length) /
                                             std::max(stream.length_m() - cap_length, 1e-9));
      }
      stream.trim_tips = false;
      stream.pieces.push_back(Piece{0.0, cap_length, HairStyle::fixed, defects.cap_rails});
      double braid_begin = cap_length + component.band_gap_m;
      int count = std::max(
          1, static_cast<int>((stream.length_m() - braid_begin) / defects.braid_piece_length_m));
      DefectSpec braid_defects = defects;
      braid_defects.segment_length_m =
          std::min(defects.segment_length_m, defects.braid_piece_length_m / 4);
      auto pieces =
          cut_pieces(braid_begin, stream.length_m(), count, HairStyle::braided, braid_defects, rng);
      for (Piece& piece : pieces) piece.rails = rng.integer(2, std::min(3, defects.rails_max));
      stream.pieces.insert(stream.pieces.end(), pieces.begin(), pieces.end());
      streams.push_back(std::move(stream));
    }
  }
}

}  // namespace hair::synth
