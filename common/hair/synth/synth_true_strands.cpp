// The truth's dense strands of a synthetic hairstyle: strands along each stream, and
// strands rooted on the scalp under cards that stand off the head.
#include "hair/synth/synth_true_strands.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace hair::synth {

namespace {

/// Style of the hair at arc length `along_m` of a stream: that of the last piece starting
/// at or before it (hidden gaps take the style of the piece before them).
HairStyle style_at(const Stream& stream, double along_m) {
  HairStyle style = stream.pieces.front().style;
  for (const Piece& piece : stream.pieces)
    if (piece.start_m <= along_m) style = piece.style;
  return style;
}

/// Appends the true strand `points` of `stream` (at arc lengths `along_m` of it, for their
/// styles); nothing for fewer than two points.
void append_true_strand(const Stream& stream, int32_t stream_id, const std::vector<Vec3>& points,
                        const std::vector<double>& along_m, std::vector<Points3f>& polylines,
                        std::vector<int32_t>& strand_stream, std::vector<HairStyle>& point_style) {
  if (points.size() < 2) return;
  Points3f polyline(static_cast<Eigen::Index>(points.size()), 3);
  for (size_t i = 0; i < points.size(); ++i)
    polyline.row(static_cast<Eigen::Index>(i)) = points[i].cast<float>().transpose();
  polylines.push_back(std::move(polyline));
  strand_stream.push_back(stream_id);
  for (size_t i = 0; i < points.size(); ++i) point_style.push_back(style_at(stream, along_m[i]));
}

}  // namespace

void add_true_strands(const Stream& stream, int32_t stream_id, const Head& head, int count,
                      Rng& rng, std::vector<Points3f>& polylines,
                      std::vector<int32_t>& strand_stream, std::vector<HairStyle>& point_style) {
  for (int j = 0; j < count; ++j) {
    double u = rng.uniform(-0.5, 0.5), v = rng.uniform(-0.5, 0.5) / 3.0;
    if (stream.tube) {  // uniform over the disc of the tube's diameter
      const double radius = 0.5 * std::sqrt(rng.uniform(0, 1)), angle = rng.uniform(0, 2 * kPi);
      u = radius * std::cos(angle);
      v = radius * std::sin(angle);
    }
    double end = stream.length_m() * (stream.trim_tips ? rng.uniform(0.9, 1.0) : 1.0);
    std::vector<Vec3> points;
    for (size_t i = 0; i < stream.points.size() && stream.along_m[i] <= end; ++i) {
      Vec3 across = u * stream.width_m[i] * stream.across[i];
      points.push_back(
          stream.scalp_lift_m.empty()
              ? Vec3(stream.points[i] + across + v * stream.width_m[i] * stream.normal[i])
              : on_scalp(head, stream.points[i] + across,
                         stream.scalp_lift_m[i] * (1.0 + 3.0 * v)));
    }
    append_true_strand(stream, stream_id, points, stream.along_m, polylines, strand_stream,
                       point_style);
  }
}

void add_true_strands_under_volume(const Stream& stream, int32_t stream_id, const Head& head,
                                   int count, double lift_m, Rng& rng,
                                   std::vector<Points3f>& polylines,
                                   std::vector<int32_t>& strand_stream,
                                   std::vector<HairStyle>& point_style) {
  const size_t n = stream.points.size();
  if (n < 2 || !(stream.length_m() > 0)) return;
  auto foot_of = [&](const Vec3& point) { return on_scalp(head, point, lift_m); };
  auto over_scalp = [&](const Vec3& point) {
    const Vec3 foot = (foot_of(point) - head.centre).normalized();
    const double polar_deg = std::acos(std::clamp(foot.y(), -1.0, 1.0)) * 180.0 / kPi;
    return polar_deg <= hairline_polar_deg(std::atan2(foot.x(), foot.z()) * 180.0 / kPi);
  };
  // covered_m[i]: the length of the stretches over the scalp up to point i.
  std::vector<double> covered_m(n, 0.0);
  bool previous_over = over_scalp(stream.points[0]);
  for (size_t i = 1; i < n; ++i) {
    const bool over = over_scalp(stream.points[i]);
    covered_m[i] = covered_m[i - 1] +
                   (previous_over && over ? stream.along_m[i] - stream.along_m[i - 1] : 0.0);
    previous_over = over;
  }
  const double covered_total_m = covered_m.back();
  const int under = static_cast<int>(std::lround(count * covered_total_m / stream.length_m()));
  for (int j = 0; j < under; ++j) {
    const double u = rng.uniform(-0.5, 0.5), v = rng.uniform(-0.5, 0.5) / 3.0;
    const double end = stream.length_m() * (stream.trim_tips ? rng.uniform(0.9, 1.0) : 1.0);
    const double drawn_m = rng.uniform(0, covered_total_m);
    size_t i = static_cast<size_t>(std::upper_bound(covered_m.begin(), covered_m.end(), drawn_m) -
                                   covered_m.begin());
    i = std::clamp<size_t>(i, 1, n - 1);
    const double span_m = covered_m[i] - covered_m[i - 1];
    const double start_m =
        stream.along_m[i - 1] + (span_m > 0 ? (drawn_m - covered_m[i - 1]) / span_m : 0.0) *
                                    (stream.along_m[i] - stream.along_m[i - 1]);
    auto place = [&](double along_m) {
      return Vec3(stream.point_at(along_m) +
                  stream.width_at(along_m) *
                      (u * stream.across_at(along_m) + v * stream.normal_at(along_m)));
    };
    const Vec3 root = foot_of(place(start_m));
    const double climb_m = std::max(2.0 * (place(start_m) - root).norm(), kStep_m);
    if (start_m + climb_m >= end) continue;
    std::vector<Vec3> points{root};
    std::vector<double> along_m{start_m};
    for (size_t k = 0; k < n && stream.along_m[k] <= end; ++k) {
      if (stream.along_m[k] <= start_m) continue;
      const Vec3 card = place(stream.along_m[k]);
      const double t = std::clamp((stream.along_m[k] - start_m) / climb_m, 0.0, 1.0);
      const double weight = t * t * (3 - 2 * t);
      if (weight >= 1) {
        points.push_back(card);  // past the climb: no foot to look up
      } else {
        const Vec3 foot = foot_of(card);
        points.push_back(foot + weight * (card - foot));
      }
      along_m.push_back(stream.along_m[k]);
    }
    append_true_strand(stream, stream_id, points, along_m, polylines, strand_stream, point_style);
  }
}

}  // namespace hair::synth
