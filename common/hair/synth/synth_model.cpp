#include "hair/synth/synth_model.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <numeric>
#include <random>

#include "hair/core/error.h"
#include "hair/geom/triangle_mesh_distance.h"
#include "hair/mesh/body_measures.h"
#include "hair/synth/synth_paint.h"

namespace hair::synth {

namespace {

using Vec3 = Eigen::Vector3d;
constexpr double kPi = std::numbers::pi;
constexpr double kStep_m = 0.004;  // spacing of centre-curve points
// The tightest a braid's axis bends: about the braid's width (twice braid_width_m).
constexpr double kBraidMinBendRadius_m = 0.03;

/// Random numbers from std::mt19937, whose output the standard fixes, with the
/// distributions written out here (the standard library's are implementation-defined),
/// so that a seed gives the same model everywhere.
class Rng {
 public:
  explicit Rng(uint32_t seed) : engine_(seed) {}
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) {
    return lo + (hi - lo) * (static_cast<double>(engine_()) / 4294967296.0);
  }
  /// Uniform integer in [lo, hi].
  int integer(int lo, int hi) {
    if (hi <= lo) return lo;
    return lo + static_cast<int>(engine_() % static_cast<uint32_t>(hi - lo + 1));
  }
  bool chance(double probability) { return uniform(0, 1) < probability; }
  /// Fisher-Yates shuffle.
  template <class T>
  void shuffle(std::vector<T>& values) {
    for (size_t i = values.size(); i > 1; --i)
      std::swap(values[i - 1], values[static_cast<size_t>(integer(0, static_cast<int>(i) - 1))]);
  }

 private:
  std::mt19937 engine_;
};

double radians(double degrees) { return degrees * kPi / 180.0; }

/// Unit direction at `azimuth_deg` around +Y from +Z (the face) towards +X and
/// `polar_deg` from +Y.
Vec3 direction(double azimuth_deg, double polar_deg) {
  double azimuth = radians(azimuth_deg), polar = radians(polar_deg);
  return {std::sin(polar) * std::sin(azimuth), std::cos(polar),
          std::sin(polar) * std::cos(azimuth)};
}

/// Polar angle of the front hairline at an azimuth: high on the forehead, low at the nape.
double hairline_polar_deg(double azimuth_deg) {
  return 45.0 + 70.0 * std::pow(std::abs(azimuth_deg) / 180.0, 0.8);
}

/// The body and its head, for placing roots and keeping hair off the body.
struct Head {
  Vec3 centre = Vec3::Zero();
  double radius_m = 0.1;
  TriangleMeshDistance body;

  /// The head surface in direction `dir` from the centre, and the outward normal there.
  std::pair<Vec3, Vec3> surface(const Vec3& dir) const {
    Vec3 probe = centre + dir.normalized() * 2.0 * radius_m;
    auto nearest = body.nearest(probe);
    Vec3 outward = (probe - nearest.closest_point).normalized();
    return {nearest.closest_point, outward};
  }

  /// `point` moved out to `clearance_m` off the body if it is nearer.
  Vec3 pushed_out(const Vec3& point, double clearance_m) const {
    auto nearest = body.nearest(point);
    if (nearest.distance >= clearance_m || nearest.distance <= 0) return point;
    return nearest.closest_point +
           (point - nearest.closest_point) * (clearance_m / nearest.distance);
  }

  /// Direction away from the head's vertical axis (below the centre) or its centre.
  Vec3 radial(const Vec3& point) const {
    Vec3 r = point - centre;
    if (point.y() < centre.y()) r.y() = 0;
    if (r.norm() < 1e-9) r = Vec3::UnitZ();
    return r.normalized();
  }
};

Head measure_head(const PolyMesh& body_m) {
  HeadMeasures measures = head_measures(body_m, "body");
  Triangles3i triangles = fan_triangulation(body_m.face_offsets, body_m.face_vertices);
  Head head{Vec3::Zero(), 0.5 * measures.head_width,
            TriangleMeshDistance(body_m.vertices, triangles)};
  Eigen::Vector3d low = Vec3::Constant(1e9), high = Vec3::Constant(-1e9);
  double floor_y = measures.neck_y + 0.35 * measures.head_height;
  for (Eigen::Index v = 0; v < body_m.vertices.rows(); ++v) {
    Vec3 p = body_m.vertices.row(v).cast<double>().transpose();
    if (p.y() < floor_y) continue;
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  head.radius_m = 0.5 * (high.x() - low.x());
  head.centre = {0.5 * (low.x() + high.x()), measures.head_top_y - head.radius_m,
                 0.5 * (low.z() + high.z())};
  return head;
}

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

/// `point`, near the head, moved to `lift_m` off the nearest point of the body (out of
/// the head if it was inside): hair lying on the scalp across a stream's whole width (a
/// flat 6 cm strip tangent to the head stands 5 mm off it at its edges).
Vec3 on_scalp(const Head& head, const Vec3& point, double lift_m) {
  auto nearest = head.body.nearest(point);
  Vec3 out = point - nearest.closest_point;
  if (out.norm() < 1e-9) out = point - head.centre;
  if (out.dot(point - head.centre) < 0) out = -out;
  return nearest.closest_point + lift_m * out.normalized();
}

void measure_arc_length(Stream& stream) {
  stream.along_m.assign(stream.points.size(), 0.0);
  for (size_t i = 1; i < stream.points.size(); ++i)
    stream.along_m[i] = stream.along_m[i - 1] + (stream.points[i] - stream.points[i - 1]).norm();
}

/// Frames along the curve: across = tangent x radial (the strip lies on the head's
/// surface, or flat around its vertical axis below it), unless `axis_normal` gives
/// the normal to keep facing (braid pieces facing out of the braid).
void frame_stream(Stream& stream, const Head& head,
                  const std::vector<Vec3>* axis_normal = nullptr) {
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

/// A hair grown from `root` in direction `start` for `length_m`: bending down under
/// gravity (radius of the bend about `bend_m`) and kept `clearance_m` off the body.
std::vector<Vec3> grown_curve(const Head& head, const Vec3& root, const Vec3& start,
                              double length_m, double bend_m, double clearance_m,
                              bool hug_scalp = false) {
  std::vector<Vec3> points{root};
  Vec3 dir = start.normalized();
  Vec3 p = root;
  int steps = std::max(2, static_cast<int>(std::ceil(length_m / kStep_m)));
  double step = length_m / steps;
  for (int i = 0; i < steps; ++i) {
    dir = (dir + (step / bend_m) * Vec3(0, -1, 0)).normalized();
    Vec3 next = head.pushed_out(p + step * dir, clearance_m);
    if (hug_scalp && next.y() > head.centre.y() - 0.2 * head.radius_m) {
      // Over the head, hair lies on the scalp (held by the hair under it) until it
      // falls off the head's sides and back.
      auto nearest = head.body.nearest(next);
      if (nearest.distance > clearance_m && nearest.distance > 0)
        next = nearest.closest_point +
               (next - nearest.closest_point) * (clearance_m / nearest.distance);
    }
    // Keep the step length: a push changes the direction, not the speed.
    Vec3 moved = next - p;
    if (moved.norm() > 1e-9) {
      dir = moved.normalized();
      next = p + step * dir;
    }
    p = next;
    points.push_back(p);
  }
  // Three passes of Laplacian smoothing, roots fixed, then pushed out again.
  for (int pass = 0; pass < 3; ++pass)
    for (size_t i = 1; i + 1 < points.size(); ++i)
      points[i] =
          head.pushed_out(0.5 * points[i] + 0.25 * (points[i - 1] + points[i + 1]), clearance_m);
  return points;
}

/// Rounds the creases out of `curve`: where it turns between consecutive segments by more
/// than a bend of radius `min_radius_m` allows, the point is moved towards its
/// neighbours' midpoint (and kept `clearance_m` off the body), pass after pass until no
/// point turns too sharply (at most `max_passes`). Ends stay; a curve that bends less
/// everywhere is returned unchanged. A braid's axis grown down onto a shoulder is pushed
/// off it within a step or two, a fold no braid a few centimetres wide makes.
void round_creases(const Head& head, std::vector<Vec3>& curve, double min_radius_m,
                   double clearance_m, int max_passes = 400) {
  for (int pass = 0; pass < max_passes; ++pass) {
    std::vector<size_t> creased;
    for (size_t i = 1; i + 1 < curve.size(); ++i) {
      Vec3 before = curve[i] - curve[i - 1], after = curve[i + 1] - curve[i];
      double turn = std::acos(std::clamp(before.normalized().dot(after.normalized()), -1.0, 1.0));
      if (turn > 0.5 * (before.norm() + after.norm()) / min_radius_m) creased.push_back(i);
    }
    if (creased.empty()) return;
    for (size_t i : creased)
      curve[i] =
          head.pushed_out(0.5 * curve[i] + 0.25 * (curve[i - 1] + curve[i + 1]), clearance_m);
  }
}

/// Lifts a hanging curve away from the head's vertical axis by up to `volume_m`: nothing at
/// the root, rising as a smoothstep over the first 40% of its length, falling back as one
/// over the last 25% (the tips turn in), as a bob's cards stand off the head below the
/// crown; kept `clearance_m` off the body.
void stand_off(const Head& head, std::vector<Vec3>& curve, double volume_m, double clearance_m) {
  std::vector<double> along(curve.size(), 0.0);
  for (size_t i = 1; i < curve.size(); ++i)
    along[i] = along[i - 1] + (curve[i] - curve[i - 1]).norm();
  if (curve.size() < 2 || along.back() <= 0) return;
  for (size_t i = 1; i < curve.size(); ++i) {
    auto smoothstep = [](double t) {
      t = std::clamp(t, 0.0, 1.0);
      return t * t * (3 - 2 * t);
    };
    double lift = volume_m * smoothstep(along[i] / (0.4 * along.back())) *
                  smoothstep((along.back() - along[i]) / (0.25 * along.back()));
    Vec3 outward = curve[i] - head.centre;
    outward.y() = 0;
    if (outward.norm() < 1e-9) continue;
    curve[i] = head.pushed_out(curve[i] + lift * outward.normalized(), clearance_m);
  }
}

/// Adds waves across the strip (amplitude fading in over the first 3 cm).
void add_waves(Stream& stream, double amplitude_m, double wavelength_m, double phase) {
  if (amplitude_m <= 0) return;
  for (size_t i = 0; i < stream.points.size(); ++i) {
    double s = stream.along_m[i];
    double fade = std::min(1.0, s / 0.03);
    stream.points[i] +=
        fade * amplitude_m * std::sin(2 * kPi * s / wavelength_m + phase) * stream.across[i];
  }
}

/// Winds the stream round its own curve in a helix of `radius_m` and `pitch_m` per turn
/// along it (fading in over the first 3 cm, as waves do), a corkscrew ringlet, kept
/// `clearance_m` off the body; then its arc lengths and frames are measured again.
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

/// Root directions spread evenly (a Fibonacci lattice) over the component's scalp
/// region below the hairline, jittered; `count` of them.
std::vector<Vec3> root_directions(const ComponentSpec& component, int count, Rng& rng) {
  auto in_region = [&](double azimuth_deg, double polar_deg) {
    return azimuth_deg >= component.azimuth_min_deg && azimuth_deg <= component.azimuth_max_deg &&
           polar_deg >= component.polar_min_deg && polar_deg <= component.polar_max_deg &&
           polar_deg <= hairline_polar_deg(azimuth_deg);
  };
  const double golden_deg = 180.0 * (3.0 - std::sqrt(5.0));
  auto lattice = [&](int size, std::vector<Vec3>* out) {
    int found = 0;
    for (int i = 0; i < size; ++i) {
      double polar_deg = std::acos(1.0 - (2.0 * i + 1.0) / size) * 180.0 / kPi;
      double azimuth_deg = std::fmod(i * golden_deg, 360.0);
      if (azimuth_deg > 180.0) azimuth_deg -= 360.0;
      if (!in_region(azimuth_deg, polar_deg)) continue;
      ++found;
      if (out) out->push_back(direction(azimuth_deg, polar_deg));
    }
    return found;
  };
  if (count <= 0) return {};
  int size = count;
  while (lattice(size, nullptr) < count && size < 200000) size += std::max(1, size / 50);
  std::vector<Vec3> directions;
  lattice(size, &directions);
  directions.resize(std::min<size_t>(directions.size(), static_cast<size_t>(count)));
  for (Vec3& d : directions) {
    d += Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)) * 0.03;
    d.normalize();
  }
  return directions;
}

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

/// Cuts [start, end] into `count` pieces with gaps (or overlaps) at the junctions.
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

/// Normal or short hair: one stream per root, cut into strips or cards.
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

/// Short hair lying on the head (short02, short03): cap grids fanning out from a crown
/// whorl (the band position: `band_azimuth_deg`, `band_polar_deg`), one per stream, side
/// by side around it. A grid's root lies `polar_min_deg` to `polar_max_deg` from the
/// whorl; from there it flows over the head away from the whorl (turning by up to 12
/// degrees, all grids alike: the swirl of a crown) down to the front hairline, lying on
/// the scalp (scalp_lift_m at the root, 1.5 times that at the tip) and widening with the
/// angle from the whorl so that the grids tile the scalp. A stream ends at the hairline,
/// or before it when its drawn length is shorter. No band, no continuation: a stream is
/// one grid (root-free), or a root piece and a tip piece when normal_pieces_max allows (a
/// layered cut); every piece is short.
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

/// How a cap's grids lie between their roots and the band: close over the head (the
/// default), or loose hair drawn low over the ears with volume (ComponentSpec::cap_volume_m,
/// cap_drape).
struct CapShape {
  double volume_m = 0;  ///< the grids stand up to this far off the head between root and band
  bool drape = false;   ///< the grids fall down the side of the head before sweeping back
};

/// Where a draped cap grid from `root_dir` passes on its way to the band: the side of the
/// head above the ear (polar 80 degrees), at the root's own azimuth, pushed at least 70
/// degrees from the face so the hair is swept off it.
Vec3 drape_direction(const Vec3& root_dir) {
  Vec3 r = root_dir.normalized();
  double azimuth_deg = std::atan2(r.x(), r.z()) * 180.0 / kPi;
  double polar_deg = std::acos(std::clamp(r.y(), -1.0, 1.0)) * 180.0 / kPi;
  double side = azimuth_deg < 0 ? -1.0 : 1.0;
  double via_azimuth = std::abs(azimuth_deg) < 70.0 ? side * 70.0 : azimuth_deg;
  return direction(via_azimuth, std::max(polar_deg, 80.0));
}

/// Unit directions from `from` to `to` (unit vectors) along the great circle, `steps` + 1 of
/// them, both ends included.
std::vector<Vec3> great_circle(const Vec3& from, const Vec3& to, int steps) {
  double angle = std::acos(std::clamp(from.dot(to), -1.0, 1.0));
  std::vector<Vec3> out;
  for (int i = 0; i <= steps; ++i) {
    double t = static_cast<double>(i) / steps;
    out.push_back(std::abs(std::sin(angle)) < 1e-6
                      ? from
                      : Vec3((std::sin((1 - t) * angle) * from + std::sin(t * angle) * to) /
                             std::sin(angle)));
  }
  return out;
}

/// A curve over the head from `root` to `band`: directions from the head centre
/// interpolated on the sphere (through the side of the head when `shape.drape`), each put
/// on the surface, lifted from `lift_root_m` at the root to the band's own height at the end
/// and, with volume, up to `shape.volume_m` more in between (sin(pi t), t the share of the
/// way: rising from the root, drawn in to the band at the end).
std::vector<Vec3> cap_curve(const Head& head, const Vec3& root_dir, const Vec3& band_end,
                            double lift_root_m, double clearance_m, const CapShape& shape = {}) {
  Vec3 band_dir = (band_end - head.centre).normalized();
  Vec3 from = root_dir.normalized();
  auto steps_for = [&](const Vec3& a, const Vec3& b) {
    double angle = std::acos(std::clamp(a.dot(b), -1.0, 1.0));
    return std::max(4, static_cast<int>(angle * head.radius_m / kStep_m));
  };
  std::vector<Vec3> directions;
  if (shape.drape) {
    Vec3 via = drape_direction(from);
    directions = great_circle(from, via, steps_for(from, via));
    std::vector<Vec3> second = great_circle(via, band_dir, steps_for(via, band_dir));
    directions.insert(directions.end(), second.begin() + 1, second.end());
  } else {
    directions = great_circle(from, band_dir, steps_for(from, band_dir));
  }
  // Where along the way each direction lies (0 at the root, 1 at the band), by angle.
  std::vector<double> along(directions.size(), 0.0);
  for (size_t i = 1; i < directions.size(); ++i)
    along[i] =
        along[i - 1] + std::acos(std::clamp(directions[i - 1].dot(directions[i]), -1.0, 1.0));
  std::vector<Vec3> points;
  auto [band_surface, band_outward] = head.surface(band_dir);
  double band_lift = (band_end - band_surface).norm();
  const size_t last = directions.size() - 1;
  for (size_t i = 0; i <= last; ++i) {
    // Along one great circle the directions are evenly spaced: i / last exactly.
    double t = !shape.drape       ? static_cast<double>(i) / static_cast<double>(last)
               : along.back() > 0 ? along[i] / along.back()
                                  : 1.0;
    auto [surface, outward] = head.surface(directions[i]);
    double lift = lift_root_m + (band_lift - lift_root_m) * t * t +
                  shape.volume_m * std::max(0.0, std::sin(kPi * t));
    points.push_back(i == last ? band_end
                               : head.pushed_out(surface + lift * outward, clearance_m * 0.5));
  }
  return points;
}

/// Appends `tail` (its first point excluded when it repeats the last) to `points`.
void append_points(std::vector<Vec3>& points, const std::vector<Vec3>& tail) {
  for (const Vec3& p : tail)
    if (points.empty() || (p - points.back()).norm() > 1e-9) points.push_back(p);
}

/// A band on the head: its point (lifted off the hair under it) and outward normal.
std::pair<Vec3, Vec3> band_point(const Head& head, const ComponentSpec& component) {
  auto [surface, outward] =
      head.surface(direction(component.band_azimuth_deg, component.band_polar_deg));
  return {surface + 0.012 * outward, outward};
}

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

/// A ponytail: cap grids from the hairline to a band (fixed), tail strips from the band
/// (normal), one stream per cap patch, a hidden gap at the band; with a bun radius, the
/// tails coil round the band (fixed).
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

/// A braid: three streams, each a cap grid from a third of the scalp region to the braid
/// top (fixed), then many short pieces along a stream interleaving with the other two
/// around a hanging axis (braided): offsets a sin(wt + phi_k) across and b sin(2(wt +
/// phi_k)) out of the braid, phi_k = 2 pi k / 3, the classic parametric three-strand braid.
/// As artists make braids: each lobe woven from braid_cards_per_lobe such streams side by
/// side, the braid narrowing to braid_tip_width_share at its tip, its top braid_lift_m
/// farther off the head than the band point.
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

/// The patch of `piece`: rows along the stream, `piece.rails` points across; returns
/// the patch and appends its vertex positions (x, y, z each) to `positions`, the arc
/// length of each vertex to `vertex_along_m`, its faces to `mesh` and their UVs to `uv`.
/// Draws a patch's vertex-order and triangulation defects (into `patch`) and returns, per
/// natural index r * columns + c, the vertex's id within the patch: natural, rows reversed
/// (numbered tip to root) or shuffled.
std::vector<int32_t> draw_vertex_ids(int rows, int columns, const DefectSpec& defects, Rng& rng,
                                     SynthPatch& patch) {
  const double draw = rng.uniform(0, 1);
  patch.order = draw < defects.reversed_share                            ? VertexOrder::reversed
                : draw < defects.reversed_share + defects.shuffled_share ? VertexOrder::shuffled
                                                                         : VertexOrder::natural;
  patch.triangulated = rng.chance(defects.triangulate_share);
  // Drawn only where asked for, so that models without it keep their random numbers.
  const bool shorter_diagonals =
      defects.shorter_diagonal_share > 0 && rng.chance(defects.shorter_diagonal_share);
  patch.shorter_diagonals = patch.triangulated && shorter_diagonals;
  std::vector<int32_t> id(static_cast<size_t>(rows * columns));  // natural index -> id in patch
  std::iota(id.begin(), id.end(), 0);
  if (patch.order == VertexOrder::reversed)
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < columns; ++c) id[r * columns + c] = (rows - 1 - r) * columns + c;
  if (patch.order == VertexOrder::shuffled) rng.shuffle(id);
  return id;
}

/// Appends the cell between rows r, r + 1 and columns c, c + 1 as a quad, or as two
/// triangles (split from (r, c) to (r + 1, c + 1), or along the other diagonal with
/// `other_diagonal`); `corner(r, c)` gives a corner's vertex id and records its texture
/// coordinates, once per face corner, in the faces' corner order.
template <typename Corner>
void append_cell(PolyMesh& mesh, bool triangulated, Corner&& corner, int r, int c,
                 bool other_diagonal = false) {
  if (triangulated && other_diagonal) {
    std::vector<int32_t> first{corner(r, c), corner(r, c + 1), corner(r + 1, c)};
    mesh.append_face(first);
    std::vector<int32_t> second{corner(r, c + 1), corner(r + 1, c + 1), corner(r + 1, c)};
    mesh.append_face(second);
  } else if (triangulated) {
    std::vector<int32_t> first{corner(r, c), corner(r, c + 1), corner(r + 1, c + 1)};
    mesh.append_face(first);
    std::vector<int32_t> second{corner(r, c), corner(r + 1, c + 1), corner(r + 1, c)};
    mesh.append_face(second);
  } else {
    std::vector<int32_t> quad{corner(r, c), corner(r, c + 1), corner(r + 1, c + 1),
                              corner(r + 1, c)};
    mesh.append_face(quad);
  }
}

SynthPatch build_patch(const Stream& stream, const Piece& piece, const DefectSpec& defects,
                       const Head& head, Rng& rng, std::vector<float>& positions, PolyMesh& mesh,
                       std::vector<float>& uv, std::vector<float>& vertex_along_m) {
  SynthPatch patch;
  patch.style = piece.style;
  patch.rails = std::max(2, piece.rails);
  patch.start_m = piece.start_m;
  patch.end_m = piece.end_m;
  int columns = patch.rails;
  int rows = std::max(
      2,
      static_cast<int>(std::lround((piece.end_m - piece.start_m) / defects.segment_length_m)) + 1);
  int count = rows * columns;
  const std::vector<int32_t> id = draw_vertex_ids(rows, columns, defects, rng, patch);
  // Drawn from a generator of its own, seeded by the patch's first vertex: a spec with
  // tucked tips draws every other defect as the same spec without them.
  patch.tucked = defects.tucked_share > 0 && !stream.scalp_lift_m.empty() &&
                 piece.end_m >= stream.length_m() - 1e-9 &&
                 Rng(static_cast<uint32_t>(vertex_along_m.size()) * 2654435761u ^ 0x7f4a7c15u)
                     .chance(defects.tucked_share);
  const double tuck_start_m = piece.end_m - defects.tuck_length_m;

  auto base = static_cast<int32_t>(vertex_along_m.size());
  patch.first_vertex = base;
  patch.vertex_count = count;
  patch.first_face = mesh.face_count();
  positions.resize(3 * static_cast<size_t>(base + count));
  vertex_along_m.resize(static_cast<size_t>(base + count));
  for (int r = 0; r < rows; ++r) {
    double s = piece.start_m + (piece.end_m - piece.start_m) * r / (rows - 1);
    Vec3 centre = stream.point_at(s), across = stream.across_at(s);
    double width = stream.width_at(s);
    for (int c = 0; c < columns; ++c) {
      double u = static_cast<double>(c) / (columns - 1) - 0.5;
      Vec3 jitter(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
      Vec3 p = centre + u * width * across;
      if (!stream.scalp_lift_m.empty()) {
        double lift_m = stream.scalp_lift_at(s);
        if (patch.tucked && s > tuck_start_m) {
          const double t = std::min(1.0, (s - tuck_start_m) / defects.tuck_length_m);
          lift_m = (1 - t) * lift_m - t * defects.tuck_depth_m;
        }
        p = on_scalp(head, p, lift_m);
      }
      p += defects.jitter_m * jitter;
      int32_t v = base + id[static_cast<size_t>(r * columns + c)];
      for (int k = 0; k < 3; ++k)
        positions[3 * static_cast<size_t>(v) + static_cast<size_t>(k)] = static_cast<float>(p[k]);
      vertex_along_m[static_cast<size_t>(v)] = static_cast<float>(s);
    }
  }
  auto corner = [&](int r, int c) {
    uv.push_back(static_cast<float>(c) / static_cast<float>(columns - 1));
    uv.push_back(static_cast<float>(r) / static_cast<float>(rows - 1));
    return base + id[static_cast<size_t>(r * columns + c)];
  };
  const auto position = [&](int r, int c) {
    const auto v = static_cast<size_t>(base + id[static_cast<size_t>(r * columns + c)]);
    return Vec3(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
  };
  for (int r = 0; r + 1 < rows; ++r)
    for (int c = 0; c + 1 < columns; ++c) {
      const bool other = patch.shorter_diagonals &&
                         (position(r, c + 1) - position(r + 1, c)).squaredNorm() <
                             (position(r, c) - position(r + 1, c + 1)).squaredNorm();
      append_cell(mesh, patch.triangulated, corner, r, c, other);
    }
  patch.face_count = mesh.face_count() - patch.first_face;
  return patch;
}

/// A piece meshed as a closed tube of `sides` sides round the stream's centre (diameter
/// the stream's width), as artists model ringlets: vertex (r, c) at row r along the piece
/// and angle 2 pi c / sides round it, quads between neighbouring rows and sides, the last
/// side joined to the first. Texture u runs round (0 to 1), v from the piece's root (0) to
/// its tip (1). Vertex order, triangulation and jitter as build_patch.
SynthPatch build_tube_patch(const Stream& stream, const Piece& piece, int sides,
                            const DefectSpec& defects, Rng& rng, std::vector<float>& positions,
                            PolyMesh& mesh, std::vector<float>& uv,
                            std::vector<float>& vertex_along_m) {
  SynthPatch patch;
  patch.style = piece.style;
  patch.rails = sides;
  patch.start_m = piece.start_m;
  patch.end_m = piece.end_m;
  int rows = std::max(
      2,
      static_cast<int>(std::lround((piece.end_m - piece.start_m) / defects.segment_length_m)) + 1);
  int count = rows * sides;
  const std::vector<int32_t> id = draw_vertex_ids(rows, sides, defects, rng, patch);
  auto base = static_cast<int32_t>(vertex_along_m.size());
  patch.first_vertex = base;
  patch.vertex_count = count;
  patch.first_face = mesh.face_count();
  positions.resize(3 * static_cast<size_t>(base + count));
  vertex_along_m.resize(static_cast<size_t>(base + count));
  for (int r = 0; r < rows; ++r) {
    double s = piece.start_m + (piece.end_m - piece.start_m) * r / (rows - 1);
    Vec3 centre = stream.point_at(s), across = stream.across_at(s), normal = stream.normal_at(s);
    double radius = 0.5 * stream.width_at(s);
    for (int c = 0; c < sides; ++c) {
      double angle = 2 * kPi * c / sides;
      Vec3 jitter(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
      Vec3 p = centre + radius * (std::cos(angle) * across + std::sin(angle) * normal) +
               defects.jitter_m * jitter;
      int32_t v = base + id[static_cast<size_t>(r * sides + c)];
      for (int k = 0; k < 3; ++k)
        positions[3 * static_cast<size_t>(v) + static_cast<size_t>(k)] = static_cast<float>(p[k]);
      vertex_along_m[static_cast<size_t>(v)] = static_cast<float>(s);
    }
  }
  auto corner = [&](int r, int c) {
    uv.push_back(static_cast<float>(c) / static_cast<float>(sides));
    uv.push_back(static_cast<float>(r) / static_cast<float>(rows - 1));
    return base + id[static_cast<size_t>(r * sides + c % sides)];
  };
  const auto position = [&](int r, int c) {
    const auto v = static_cast<size_t>(base + id[static_cast<size_t>(r * sides + c % sides)]);
    return Vec3(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
  };
  for (int r = 0; r + 1 < rows; ++r)
    for (int c = 0; c < sides; ++c) {
      const bool other = patch.shorter_diagonals &&
                         (position(r, c + 1) - position(r + 1, c)).squaredNorm() <
                             (position(r, c) - position(r + 1, c + 1)).squaredNorm();
      append_cell(mesh, patch.triangulated, corner, r, c, other);
    }
  patch.face_count = mesh.face_count() - patch.first_face;
  return patch;
}

/// A piece meshed as a closed pouch (ComponentSpec::folded_shell_thickness_m): rows run
/// down the piece's front sheet (half the thickness out along the stream's normal) from
/// its start to its end, the fold's row on the centre at the end, then back up the back
/// sheet (half the thickness in) to the start; `rails` columns across the strip's width.
/// Texture u runs across (0 to 1), v from the piece's start (0) to its end (1) on both
/// sheets. Vertex order, triangulation and jitter as build_patch.
SynthPatch build_folded_patch(const Stream& stream, const Piece& piece, double thickness_m,
                              const DefectSpec& defects, Rng& rng, std::vector<float>& positions,
                              PolyMesh& mesh, std::vector<float>& uv,
                              std::vector<float>& vertex_along_m) {
  SynthPatch patch;
  patch.style = piece.style;
  patch.rails = std::max(2, piece.rails);
  patch.start_m = piece.start_m;
  patch.end_m = piece.end_m;
  const int columns = patch.rails;
  const int sheet_rows = std::max(
      2,
      static_cast<int>(std::lround((piece.end_m - piece.start_m) / defects.segment_length_m)) + 1);
  const int rows = 2 * sheet_rows - 1;  // the fold's row is shared by both sheets
  const int count = rows * columns;
  const std::vector<int32_t> id = draw_vertex_ids(rows, columns, defects, rng, patch);
  auto base = static_cast<int32_t>(vertex_along_m.size());
  patch.first_vertex = base;
  patch.vertex_count = count;
  patch.first_face = mesh.face_count();
  positions.resize(3 * static_cast<size_t>(base + count));
  vertex_along_m.resize(static_cast<size_t>(base + count));
  // Row r lies at the piece's fraction along() and on the sheet side() (+1 front, -1 back).
  const auto along = [&](int r) {
    const int k = r < sheet_rows ? r : rows - 1 - r;
    return static_cast<double>(k) / (sheet_rows - 1);
  };
  const auto side = [&](int r) { return r + 1 < sheet_rows ? 1.0 : r + 1 == sheet_rows ? 0.0 : -1.0; };
  for (int r = 0; r < rows; ++r) {
    const double s = piece.start_m + (piece.end_m - piece.start_m) * along(r);
    const Vec3 centre = stream.point_at(s), across = stream.across_at(s),
               normal = stream.normal_at(s);
    const double width = stream.width_at(s);
    for (int c = 0; c < columns; ++c) {
      const double u = static_cast<double>(c) / (columns - 1) - 0.5;
      const Vec3 jitter(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
      const Vec3 p = centre + u * width * across + 0.5 * thickness_m * side(r) * normal +
                     defects.jitter_m * jitter;
      const int32_t v = base + id[static_cast<size_t>(r * columns + c)];
      for (int k = 0; k < 3; ++k)
        positions[3 * static_cast<size_t>(v) + static_cast<size_t>(k)] = static_cast<float>(p[k]);
      vertex_along_m[static_cast<size_t>(v)] = static_cast<float>(s);
    }
  }
  auto corner = [&](int r, int c) {
    uv.push_back(static_cast<float>(c) / static_cast<float>(columns - 1));
    uv.push_back(static_cast<float>(along(r)));
    return base + id[static_cast<size_t>(r * columns + c)];
  };
  const auto position = [&](int r, int c) {
    const auto v = static_cast<size_t>(base + id[static_cast<size_t>(r * columns + c)]);
    return Vec3(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
  };
  for (int r = 0; r + 1 < rows; ++r)
    for (int c = 0; c + 1 < columns; ++c) {
      const bool other = patch.shorter_diagonals &&
                         (position(r, c + 1) - position(r + 1, c)).squaredNorm() <
                             (position(r, c) - position(r + 1, c + 1)).squaredNorm();
      append_cell(mesh, patch.triangulated, corner, r, c, other);
    }
  patch.face_count = mesh.face_count() - patch.first_face;
  return patch;
}

/// One patch for the streams `stream_ids` of a short cap meshed in rings (a wig cap):
/// vertex (k, r) on stream k at arc length r * segment_length_m, quads between
/// neighbouring streams (the last joined to the first) for rows both reach. Texture u runs
/// around, v from the whorl (0) to the longest stream's end (1), as on the other patches.
SynthPatch build_ring_patch(const std::vector<Stream>& streams,
                            const std::vector<int32_t>& stream_ids, const DefectSpec& defects,
                            const Head& head, Rng& rng, std::vector<float>& positions,
                            PolyMesh& mesh, std::vector<float>& uv,
                            std::vector<float>& vertex_along_m) {
  SynthPatch patch;
  patch.stream = stream_ids.front();
  patch.style = HairStyle::short_hair;
  patch.type = GroupType::root_free;
  patch.rails = static_cast<int32_t>(stream_ids.size());
  const auto count = static_cast<int>(stream_ids.size());
  double longest = 0;
  for (int32_t id : stream_ids)
    longest = std::max(longest, streams[static_cast<size_t>(id)].length_m());
  const int rows = static_cast<int>(std::floor(longest / defects.segment_length_m)) + 1;
  patch.end_m = longest;
  auto base = static_cast<int32_t>(vertex_along_m.size());
  patch.first_vertex = base;
  patch.first_face = mesh.face_count();
  // Vertex ids, natural order: stream by stream, root outwards; -1 beyond a stream's end.
  std::vector<std::vector<int32_t>> id(static_cast<size_t>(count));
  int32_t next = base;
  for (int k = 0; k < count; ++k) {
    const Stream& stream = streams[static_cast<size_t>(stream_ids[static_cast<size_t>(k)])];
    for (int r = 0; r < rows; ++r) {
      const double s = r * defects.segment_length_m;
      if (s > stream.length_m()) break;
      Vec3 jitter(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
      Vec3 p =
          on_scalp(head, stream.point_at(s), stream.scalp_lift_at(s)) + defects.jitter_m * jitter;
      for (int c = 0; c < 3; ++c) positions.push_back(static_cast<float>(p[c]));
      vertex_along_m.push_back(static_cast<float>(s));
      id[static_cast<size_t>(k)].push_back(next++);
    }
  }
  patch.vertex_count = next - base;
  auto corner = [&](int k, int r, double u) {
    uv.push_back(static_cast<float>(u));
    uv.push_back(static_cast<float>(r * defects.segment_length_m / longest));
    return id[static_cast<size_t>(k % count)][static_cast<size_t>(r)];
  };
  auto reaches = [&](int k, int r) {
    return r < static_cast<int>(id[static_cast<size_t>(k % count)].size());
  };
  for (int k = 0; k < count; ++k)
    for (int r = 0; r + 1 < rows; ++r) {
      if (!reaches(k, r + 1) || !reaches(k + 1, r + 1)) continue;
      const double u0 = static_cast<double>(k) / count, u1 = static_cast<double>(k + 1) / count;
      std::vector<int32_t> quad{corner(k, r, u0), corner(k + 1, r, u1), corner(k + 1, r + 1, u1),
                                corner(k, r + 1, u0)};
      mesh.append_face(quad);
    }
  patch.face_count = mesh.face_count() - patch.first_face;
  return patch;
}

/// One patch for the streams `stream_ids` of a short cap meshed as one piece in a grid of
/// latitudes and longitudes round the head's vertical axis (rows `segment_length_m` apart
/// in polar angle from the crown, 36 columns of azimuth), as a wig cap modelled without
/// regard to how its hair runs: neither family of edges follows the hair. Faces are kept
/// where every corner lies within 1.5 cm of a stream's centre, nearest to it between its
/// ends (the hair's region, no farther than its roots and tips); the row next to the crown
/// is of triangles round the pole. Texture v is the arc length along the nearest stream
/// over the longest stream's length and u runs round the streams (the nearest stream's
/// index plus how far the point lies towards the next nearest neighbour, over the stream
/// count), so that the painted strokes, along v, follow the streams. Vertex ids run row by
/// row from the crown.
SynthPatch build_grid_patch(const std::vector<Stream>& streams,
                            const std::vector<int32_t>& stream_ids, const DefectSpec& defects,
                            const Head& head, std::vector<float>& positions, PolyMesh& mesh,
                            std::vector<float>& uv, std::vector<float>& vertex_along_m) {
  SynthPatch patch;
  patch.stream = stream_ids.front();
  patch.style = HairStyle::short_hair;
  patch.type = GroupType::root_free;
  const auto count = static_cast<int>(stream_ids.size());
  patch.rails = count;
  double longest = 0;
  for (int32_t id : stream_ids)
    longest = std::max(longest, streams[static_cast<size_t>(id)].length_m());
  patch.end_m = longest;
  // Where a point lies against the streams: the nearest centre point of each.
  struct Nearest {
    double distance_m = std::numeric_limits<double>::infinity();
    double along_m = 0;
    bool interior = false;
  };
  auto nearest_on = [&](int k, const Vec3& p) {
    const Stream& stream = streams[static_cast<size_t>(stream_ids[static_cast<size_t>(k)])];
    Nearest best;
    for (size_t i = 0; i < stream.points.size(); ++i) {
      const double d = (stream.points[i] - p).norm();
      if (d < best.distance_m) best = {d, stream.along_m[i], i > 0 && i + 1 < stream.points.size()};
    }
    return best;
  };
  constexpr int kColumns = 36;
  const double row_deg = defects.segment_length_m / head.radius_m * 180.0 / kPi;
  const int rows = static_cast<int>(std::ceil(150.0 / row_deg)) + 1;
  // Row 0 is the crown's pole, one vertex; row r > 0 has kColumns.
  struct GridVertex {
    Vec3 position;
    double u = 0, v = 0;
    bool in_hair = false;
    int32_t id = -1;
  };
  std::vector<std::vector<GridVertex>> grid(static_cast<size_t>(rows));
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < (r == 0 ? 1 : kColumns); ++c) {
      const auto [surface, outward] = head.surface(direction(c * 360.0 / kColumns, r * row_deg));
      GridVertex vertex;
      std::vector<Nearest> by_stream(static_cast<size_t>(count));
      int k_best = 0;
      for (int k = 0; k < count; ++k) {
        by_stream[static_cast<size_t>(k)] = nearest_on(k, surface);
        if (by_stream[static_cast<size_t>(k)].distance_m <
            by_stream[static_cast<size_t>(k_best)].distance_m)
          k_best = k;
      }
      const Nearest& best = by_stream[static_cast<size_t>(k_best)];
      vertex.in_hair = best.interior && best.distance_m < 0.015;
      const int before = (k_best + count - 1) % count, after = (k_best + 1) % count;
      const bool towards_after = by_stream[static_cast<size_t>(after)].distance_m <=
                                 by_stream[static_cast<size_t>(before)].distance_m;
      const double d_other =
          by_stream[static_cast<size_t>(towards_after ? after : before)].distance_m;
      const double share = best.distance_m / std::max(1e-12, best.distance_m + d_other);
      vertex.u = (k_best + (towards_after ? share : -share)) / count;
      vertex.u -= std::floor(vertex.u);
      vertex.v = std::clamp(best.along_m / longest, 0.0, 1.0);
      const double lift = defects.scalp_lift_m * (1.0 + 0.5 * vertex.v);
      vertex.position = surface + lift * outward;
      grid[static_cast<size_t>(r)].push_back(vertex);
    }
  patch.first_vertex = static_cast<int64_t>(vertex_along_m.size());
  patch.first_face = mesh.face_count();
  auto id_of = [&](GridVertex& vertex) {
    if (vertex.id < 0) {
      vertex.id = static_cast<int32_t>(vertex_along_m.size());
      for (int k = 0; k < 3; ++k) positions.push_back(static_cast<float>(vertex.position[k]));
      vertex_along_m.push_back(static_cast<float>(vertex.v * longest));
    }
    return vertex.id;
  };
  // The faces kept, then their vertices numbered row by row from the crown, round each
  // row from the face (azimuth 0), as a modelling tool numbers a sphere's.
  auto kept = [](const std::vector<GridVertex*>& corners) {
    return std::all_of(corners.begin(), corners.end(),
                       [](const GridVertex* corner) { return corner->in_hair; });
  };
  std::vector<std::vector<GridVertex*>> faces;
  for (int r = 0; r + 1 < rows; ++r)
    for (int c = 0; c < kColumns; ++c) {
      auto& upper = grid[static_cast<size_t>(r)];
      auto& lower = grid[static_cast<size_t>(r + 1)];
      GridVertex* a = &lower[static_cast<size_t>(c)];
      GridVertex* b = &lower[static_cast<size_t>((c + 1) % kColumns)];
      std::vector<GridVertex*> corners =
          r == 0 ? std::vector<GridVertex*>{&upper[0], a, b}
                 : std::vector<GridVertex*>{&upper[static_cast<size_t>(c)], a, b,
                                            &upper[static_cast<size_t>((c + 1) % kColumns)]};
      if (kept(corners)) faces.push_back(std::move(corners));
    }
  for (auto& row : grid)
    for (GridVertex& vertex : row)
      for (const auto& corners : faces)
        if (std::find(corners.begin(), corners.end(), &vertex) != corners.end()) {
          id_of(vertex);
          break;
        }
  auto face_of = [&](const std::vector<GridVertex*>& corners) {
    std::vector<int32_t> face;
    const double u0 = corners.front()->u;
    for (GridVertex* corner : corners) {
      face.push_back(id_of(*corner));
      double u = corner->u;  // unwrapped next to the first corner's
      if (u - u0 > 0.5) u -= 1;
      if (u0 - u > 0.5) u += 1;
      uv.push_back(static_cast<float>(u));
      uv.push_back(static_cast<float>(corner->v));
    }
    mesh.append_face(face);
  };
  for (const auto& corners : faces) face_of(corners);
  patch.vertex_count = static_cast<int64_t>(vertex_along_m.size()) - patch.first_vertex;
  patch.face_count = mesh.face_count() - patch.first_face;
  return patch;
}

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

/// Dense true strands of a stream: `count` strands at fixed places across the stream's
/// width and thickness (a third of its width; on the scalp: from half to 1.5 times its
/// lift; a tube: over its round section), following its centre; the style of every point is
/// appended to `point_style`.
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

/// True strands rooted on the scalp under `stream` (ComponentSpec::rooted_under_volume). A
/// root's place along the stream, s0, is drawn evenly over the stretches whose foot (the body
/// point nearest them, `lift_m` out) lies on the scalp above the hairline; its place across the
/// stream's width and thickness as add_true_strands() draws one. The strand leaves the foot
/// of that place at s0 and rises to the place itself over twice its height there (each point
/// the smoothstep blend of the card point and its foot, so that it leaves the scalp along the
/// card), then runs on along the stream to its (trimmed) tip. `count` strands for a stream
/// over the scalp all along, in proportion for one over it on part of its length.
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

}  // namespace

const std::vector<std::string>& painted_preset_names() {
  static const std::vector<std::string> names = {
      "ring_cap", "cap_over_layer", "mohawk", "low_tail",  "face_locks",
      "bun",      "ringlets",       "bob",    "swirl_cap", "volume_bob", "shell_tail"};
  return names;
}

bool in_training_corpus(const std::string& name) {
  // The bob's clusters come out shorter than a real bob's (0.54 H against bob02's
  // 0.86 H), and trained on, they pulled short03's cap to normal (docs/synth.md).
  return name != "bob" && name != "swirl_cap" && name != "volume_bob" && name != "shell_tail";
}

const std::vector<std::string>& preset_names() {
  static const std::vector<std::string> names = {
      "long_straight", "long_wavy", "medium_straight", "medium_wavy", "short",  "short_cap",
      "ponytail",      "braid",     "normal_braid",    "two_braids",  "half_up"};
  return names;
}

namespace {

/// The painted presets (painted_preset_names()), of the kinds community meshes come in.
HairStyleSpec painted_preset(const std::string& name) {
  using Kind = ComponentSpec::Kind;
  HairStyleSpec spec;
  spec.name = name;
  ComponentSpec normal;
  normal.kind = Kind::normal;
  if (name == "ring_cap") {
    // A one-piece wig cap, as short03: quads in rings around the crown whorl, its texture
    // unwrapped so that the painted strokes run from the whorl to the hairline.
    ComponentSpec cap;
    cap.kind = Kind::short_cap;
    cap.one_piece_rings = true;
    cap.stream_count = 28;
    cap.length_min_m = 0.16;
    cap.length_max_m = 0.24;
    cap.strip_width_m = 0.02;
    cap.band_azimuth_deg = 180;
    cap.band_polar_deg = 20;
    cap.polar_min_deg = 8;
    cap.polar_max_deg = 8;
    spec.defects.scalp_lift_m = 0.003;
    spec.defects.painted_texture = true;
    spec.components = {cap};
  } else if (name == "cap_over_layer") {
    // A one-piece cap in rings over the top of the head, and under its back edge a longer
    // layer of strips hanging to the shoulders (a layered cut whose back layer a cap hides).
    ComponentSpec cap = preset("ring_cap").components.front();
    cap.length_min_m = 0.12;
    cap.length_max_m = 0.16;
    ComponentSpec left = normal, right = normal;
    left.azimuth_min_deg = 110;
    left.azimuth_max_deg = 180;
    right.azimuth_min_deg = -180;
    right.azimuth_max_deg = -110;
    for (ComponentSpec* layer : {&left, &right}) {
      layer->polar_min_deg = 75;
      layer->stream_count = 12;
      layer->length_min_m = 0.20;
      layer->length_max_m = 0.28;
    }
    spec.defects.scalp_lift_m = 0.003;
    spec.defects.painted_texture = true;
    spec.components = {cap, left, right};
  } else if (name == "mohawk") {
    // Spike cards standing up along the middle of the head, front to back, the sides bare.
    ComponentSpec front;
    front.kind = Kind::short_cards;
    front.stream_count = 10;
    front.length_min_m = 0.05;
    front.length_max_m = 0.09;
    front.strip_width_m = 0.02;
    front.azimuth_min_deg = -12;
    front.azimuth_max_deg = 12;
    ComponentSpec back_left = front, back_right = front;
    back_left.azimuth_min_deg = 168;
    back_left.azimuth_max_deg = 180;
    back_right.azimuth_min_deg = -180;
    back_right.azimuth_max_deg = -168;
    back_left.stream_count = back_right.stream_count = 6;
    spec.defects.rails_max = 3;
    spec.defects.painted_texture = true;
    spec.components = {front, back_left, back_right};
  } else if (name == "low_tail") {
    // Hair pulled back under a band low at the nape into a tail (the cap's grids run from
    // the hairline back and down to the band).
    ComponentSpec tail;
    tail.kind = Kind::ponytail;
    tail.stream_count = 12;
    tail.band_polar_deg = 105;
    tail.length_min_m = 0.22;
    tail.length_max_m = 0.30;
    tail.strip_width_m = 0.05;
    spec.defects.painted_texture = true;
    spec.components = {tail};
  } else if (name == "face_locks") {
    // Medium hair with two longer locks framing the face, from the temples down past the
    // chin in front of the ears.
    normal.length_min_m = 0.14;
    normal.length_max_m = 0.20;
    normal.stream_count = 35;
    normal.azimuth_min_deg = -150;
    normal.azimuth_max_deg = 150;
    ComponentSpec left = normal, right = normal;
    left.azimuth_min_deg = 40;
    left.azimuth_max_deg = 70;
    right.azimuth_min_deg = -70;
    right.azimuth_max_deg = -40;
    for (ComponentSpec* lock : {&left, &right}) {
      lock->stream_count = 4;
      lock->length_min_m = 0.26;
      lock->length_max_m = 0.32;
      lock->polar_min_deg = 60;
    }
    spec.defects.normal_pieces_max = 2;
    spec.defects.painted_texture = true;
    spec.components = {normal, left, right};
  } else if (name == "bun") {
    // An up-do: hair pulled up and back from the whole hairline to a band high on the back
    // of the crown, its ends coiled round the band into a bun lying against the head.
    ComponentSpec up_do;
    up_do.kind = Kind::ponytail;
    up_do.stream_count = 24;
    up_do.polar_min_deg =
        35;  // roots towards the hairline: the strips cover the scalp as they converge
    up_do.band_polar_deg = 60;
    up_do.length_min_m = 0.26;
    up_do.length_max_m = 0.32;
    up_do.strip_width_m = 0.05;
    up_do.bun_radius_m = 0.03;
    spec.defects.painted_texture = true;
    spec.components = {up_do};
  } else if (name == "ringlets") {
    // A one-piece cap in rings over the top of the head and, from under its edge at the
    // sides and back, corkscrew ringlets meshed as tubes hanging to the shoulders.
    ComponentSpec cap = preset("ring_cap").components.front();
    cap.length_min_m = 0.12;
    cap.length_max_m = 0.16;
    ComponentSpec curls = normal;
    curls.stream_count = 20;
    curls.polar_min_deg = 70;
    curls.azimuth_min_deg = -160;
    curls.azimuth_max_deg = 160;
    curls.length_min_m = 0.18;
    curls.length_max_m = 0.26;
    curls.strip_width_m = 0.01;
    curls.ringlet_radius_m = 0.008;
    curls.ringlet_pitch_m = 0.035;
    curls.tube_sides = 6;
    spec.defects.scalp_lift_m = 0.003;
    // Rings 6 mm apart along the hair, twelve a turn of the curl (a 1.5 cm quad would cut
    // across a 3.5 cm turn by 37 degrees).
    spec.defects.segment_length_m = 0.006;
    spec.defects.painted_texture = true;
    spec.components = {cap, curls};
  } else if (name == "bob") {
    // Hair cut level at the jaw, as bob01 and bob02: a few wide cards, each one piece from
    // its root to the cut, lying on the head and hanging close to it (no layers, no
    // pieces to chain).
    normal.length_min_m = 0.18;
    normal.length_max_m = 0.24;
    normal.stream_count = 12;
    normal.strip_width_m = 0.06;
    normal.polar_max_deg = 45;  // roots round the crown: the cards cover the head
    normal.hang_volume_m = 0.012;  // standing off the head below the crown, as bob01's and bob02's
    normal.rooted_under_volume = true;  // and the scalp under the cards carries hair
    // Parted in the middle: no card roots over the face (it would hang over it).
    ComponentSpec left = normal, right = normal;
    left.azimuth_min_deg = 45;
    left.azimuth_max_deg = 180;
    right.azimuth_min_deg = -180;
    right.azimuth_max_deg = -45;
    spec.defects.normal_pieces_max = 1;
    spec.defects.painted_texture = true;
    spec.components = {left, right};
  } else if (name == "volume_bob") {
    // The bob with its cards standing off the head as far as bob01's shell does (2-4 cm off
    // the back of the head): up to 3 cm more below the crown, its truth rooted all over the
    // scalp under them. Extract's scalp has to reach that far under hair for the roots.
    spec = painted_preset("bob");
    spec.name = name;
    for (ComponentSpec& component : spec.components) component.hang_volume_m = 0.03;
  } else if (name == "shell_tail") {
    // A ponytail whose tail is a closed shell, as game artists model one (Mozilla Hubs'
    // ponytails): each tail strip a pouch 1.5 cm thick, its rails running down the front,
    // round the tip and back up the back to the band.
    ComponentSpec tail;
    tail.kind = Kind::ponytail;
    tail.stream_count = 12;
    tail.band_polar_deg = 80;
    tail.length_min_m = 0.30;
    tail.length_max_m = 0.38;
    tail.strip_width_m = 0.05;
    tail.folded_shell_thickness_m = 0.015;
    spec.defects.normal_pieces_max = 1;
    spec.defects.painted_texture = true;
    spec.components = {tail};
  } else if (name == "swirl_cap") {
    // A one-piece wig cap as ring_cap, but meshed in a grid of latitudes and longitudes
    // that pays no heed to its hair (short01's and short03's caps), its hair swirling round
    // the whorl (turned by 50-80 degrees 90 degrees from it, so that it runs level round
    // the sides of the head), and its texture tiled, not fading to the tips: extract traces
    // streamlines along the paint, which gives each face's axis but not which way the hair
    // runs, so each streamline is oriented by its own ends (the higher is the root), which
    // a level or rising stretch of the swirl can read either way; the streamlines around it
    // say which (extract's group sense).
    ComponentSpec cap = preset("ring_cap").components.front();
    cap.one_piece_rings = false;
    cap.one_piece_grid = true;
    cap.swirl_min_deg = 50;
    cap.swirl_max_deg = 80;
    cap.band_polar_deg = 30;
    spec.defects.scalp_lift_m = 0.003;
    spec.defects.painted_texture = true;
    spec.defects.painted_fade = false;
    spec.components = {cap};
  }
  return spec;
}

}  // namespace

HairStyleSpec preset(const std::string& name) {
  using Kind = ComponentSpec::Kind;
  HairStyleSpec spec;
  spec.name = name;
  ComponentSpec normal;
  normal.kind = Kind::normal;
  if (name == "long_straight" || name == "long_wavy") {
    normal.length_min_m = 0.30;
    normal.length_max_m = 0.42;
    normal.stream_count = 45;
    if (name == "long_wavy") normal.wave_amplitude_m = 0.01;
    spec.defects.normal_pieces_max = 3;
    spec.components = {normal};
  } else if (name == "medium_straight" || name == "medium_wavy") {
    normal.length_min_m = 0.14;
    normal.length_max_m = 0.22;
    normal.stream_count = 45;
    if (name == "medium_wavy") normal.wave_amplitude_m = 0.008;
    normal.wavelength_m = 0.06;
    spec.defects.normal_pieces_max = 2;
    spec.components = {normal};
  } else if (name == "short") {
    ComponentSpec cards;
    cards.kind = Kind::short_cards;
    cards.stream_count = 60;
    cards.length_min_m = 0.03;
    cards.length_max_m = 0.07;
    cards.strip_width_m = 0.025;
    spec.defects.rails_max = 3;
    spec.components = {cards};
  } else if (name == "short_cap") {
    // Like short02: the scalp covered by grids from the crown to the hairline, 3-4.5 mm
    // off it; the hairline ends most grids before their drawn length does (0.4-0.7 H).
    ComponentSpec cap;
    cap.kind = Kind::short_cap;
    cap.stream_count = 9;
    cap.length_min_m = 0.12;
    cap.length_max_m = 0.24;
    cap.strip_width_m = 0.07;
    cap.band_azimuth_deg = 180;  // the crown whorl, at the back of the top of the head
    cap.band_polar_deg = 20;
    cap.polar_min_deg = 3;  // roots 3-12 degrees from the whorl
    cap.polar_max_deg = 12;
    spec.defects.cap_rails = 6;
    spec.defects.scalp_lift_m = 0.003;
    spec.components = {cap};
  } else if (name == "ponytail") {
    ComponentSpec tail;
    tail.kind = Kind::ponytail;
    tail.stream_count = 10;
    tail.length_min_m = 0.35;
    tail.length_max_m = 0.45;
    tail.strip_width_m = 0.05;
    spec.components = {tail};
  } else if (name == "braid") {
    ComponentSpec braid;
    braid.kind = Kind::braid;
    braid.length_min_m = 0.25;
    braid.length_max_m = 0.32;
    braid.strip_width_m = 0.014;
    braid.azimuth_min_deg = -170;
    braid.azimuth_max_deg = 170;
    spec.components = {braid};
  } else if (name == "normal_braid") {
    ComponentSpec braid;
    braid.kind = Kind::braid;
    braid.length_min_m = 0.22;
    braid.length_max_m = 0.28;
    braid.strip_width_m = 0.014;
    braid.azimuth_min_deg = 120;
    braid.azimuth_max_deg = 180;
    braid.band_polar_deg = 80;
    normal.length_min_m = 0.18;
    normal.length_max_m = 0.26;
    normal.stream_count = 30;
    normal.azimuth_min_deg = -120;
    normal.azimuth_max_deg = 120;
    spec.defects.normal_pieces_max = 2;
    spec.components = {normal, braid};
  } else if (name == "two_braids") {
    ComponentSpec left;
    left.kind = Kind::braid;
    left.length_min_m = 0.22;
    left.length_max_m = 0.30;
    left.strip_width_m = 0.013;
    left.azimuth_min_deg = 0;
    left.azimuth_max_deg = 180;
    left.band_azimuth_deg = 120;
    left.band_polar_deg = 85;
    ComponentSpec right = left;
    right.azimuth_min_deg = -180;
    right.azimuth_max_deg = 0;
    right.band_azimuth_deg = -120;
    spec.components = {left, right};
  } else if (name == "half_up") {
    ComponentSpec tail;
    tail.kind = Kind::ponytail;
    tail.stream_count = 8;
    tail.polar_max_deg = 60;
    tail.band_polar_deg = 55;
    tail.length_min_m = 0.25;
    tail.length_max_m = 0.32;
    tail.strip_width_m = 0.05;
    tail.band_gap_m = 0.045;  // a large hidden gap at the band
    normal.polar_min_deg = 62;
    normal.stream_count = 25;
    normal.length_min_m = 0.18;
    normal.length_max_m = 0.26;
    spec.components = {tail, normal};
  } else if (std::find(painted_preset_names().begin(), painted_preset_names().end(), name) !=
             painted_preset_names().end()) {
    return painted_preset(name);
  } else {
    std::string known;
    for (const std::string& n : preset_names()) known += (known.empty() ? "" : ", ") + n;
    for (const std::string& n : painted_preset_names()) known += ", " + n;
    throw Error::usage("unknown preset '" + name + "'; presets: " + known);
  }
  return spec;
}

HairStyleSpec varied_spec(HairStyleSpec spec, uint32_t seed, bool artists_families) {
  Rng rng(seed ^ 0x9e3779b9u);
  for (ComponentSpec& component : spec.components) {
    int preset_stream_count = component.stream_count;
    if (component.kind != ComponentSpec::Kind::braid)
      component.stream_count = std::max(
          3, static_cast<int>(std::lround(component.stream_count * rng.uniform(0.75, 1.25))));
    double scale = rng.uniform(0.85, 1.15);
    component.length_min_m *= scale;
    component.length_max_m *= scale;
    component.strip_width_m *= rng.uniform(0.85, 1.15);
    // A short cap's grids share the scalp: fewer grids, wider ones.
    if (component.kind == ComponentSpec::Kind::short_cap)
      component.strip_width_m *= static_cast<double>(preset_stream_count) / component.stream_count;
    if (component.wave_amplitude_m > 0) component.wave_amplitude_m *= rng.uniform(0.7, 1.3);
    if (component.kind == ComponentSpec::Kind::braid)
      component.braid_period_m *= rng.uniform(0.85, 1.15);
  }
  DefectSpec& defects = spec.defects;
  defects.rails_min = rng.integer(2, 3);
  defects.rails_max = std::max(defects.rails_min, std::min(defects.rails_max, rng.integer(3, 4)));
  defects.gap_m = rng.uniform(0.002, 0.008);
  defects.overlap_share = rng.uniform(0.0, 0.4);
  defects.jitter_m = rng.uniform(0.0, 0.0015);
  defects.triangulate_share = rng.chance(0.5) ? 0.0 : rng.uniform(0.05, 0.4);
  defects.reversed_share = rng.uniform(0.0, 0.3);
  defects.shuffled_share = rng.uniform(0.0, 0.1);
  // A third of the short caps are layered cuts, each grid cut into a root and a tip
  // piece (drawn last: the other presets' knobs stay as they were).
  if (std::any_of(spec.components.begin(), spec.components.end(),
                  [](const ComponentSpec& c) { return c.kind == ComponentSpec::Kind::short_cap; }))
    defects.normal_pieces_max = rng.chance(1.0 / 3.0) ? 2 : 1;
  if (!artists_families) return spec;
  // Families of artists' meshes the presets alone miss (issue 26), drawn after all else so
  // the knobs above stay as they were: a third of the short caps are swept back, their
  // whorl moved to the top of the forehead so the grids run from the front over the head
  // (as short04); half the braids hang to the waist (as braid01's, 2-2.5 H).
  for (ComponentSpec& component : spec.components) {
    if (component.kind == ComponentSpec::Kind::short_cap && rng.chance(1.0 / 3.0)) {
      component.band_azimuth_deg = rng.uniform(-30.0, 30.0);
      component.band_polar_deg = rng.uniform(35.0, 50.0);
    }
    if (component.kind == ComponentSpec::Kind::braid && rng.chance(0.5)) {
      double long_braid = rng.uniform(1.5, 2.0);
      component.length_min_m *= long_braid;
      component.length_max_m *= long_braid;
    }
  }
  // Half the tails and braids gathered from the whole head are loose hair drawn back low
  // with volume (as braid01's cap): the band moved down to the nape, the cap's grids
  // falling from their roots over the ears before they sweep back to it, standing 1.5-4.5
  // cm off the head. Drawn after the families above so their draws stay as they were.
  for (ComponentSpec& component : spec.components) {
    bool gathered_from_whole_head =
        (component.kind == ComponentSpec::Kind::braid ||
         (component.kind == ComponentSpec::Kind::ponytail && component.bun_radius_m == 0)) &&
        component.polar_max_deg >= 100.0;
    if (!gathered_from_whole_head || !rng.chance(0.5)) continue;
    component.band_polar_deg = rng.uniform(95.0, 110.0);
    component.cap_volume_m = rng.uniform(0.015, 0.045);
    component.cap_drape = true;
  }
  // Braids as artists make them (as braid01's), drawn last so every draw above stays as it
  // was: where loose hair with volume gathers, the braid's top stands out by about that
  // volume and the braid leaves it backwards; half the braids narrow down to the tie; half
  // are woven from the cap's cards, 3-5 side by side in each lobe, cut into pieces of one or
  // two crossings (5-10 cm), the lobes swinging wide enough to hold their cards.
  bool woven_cards = false;
  for (ComponentSpec& component : spec.components) {
    if (component.kind != ComponentSpec::Kind::braid) continue;
    if (component.cap_volume_m > 0)
      component.braid_lift_m = component.cap_volume_m * rng.uniform(0.5, 1.0);
    if (rng.chance(0.5)) component.braid_tip_width_share = rng.uniform(0.4, 0.7);
    if (rng.chance(0.5)) {
      component.braid_cards_per_lobe = rng.integer(3, 5);
      double lobe_width_m = (component.braid_cards_per_lobe + 1) * 0.5 * component.strip_width_m;
      component.braid_width_m = std::max(component.braid_width_m, 0.4 * lobe_width_m);
      component.braid_depth_m = std::max(component.braid_depth_m, 0.2 * lobe_width_m);
      woven_cards = true;
    }
  }
  if (woven_cards) defects.braid_piece_length_m = rng.uniform(0.05, 0.1);
  return spec;
}

std::vector<CorpusEntry> corpus_plan(int count, uint32_t base_seed, bool with_painted) {
  std::vector<std::string> names = preset_names();
  if (with_painted)
    for (const std::string& name : painted_preset_names())
      if (in_training_corpus(name)) names.push_back(name);
  std::vector<CorpusEntry> plan;
  for (int i = 0; i < count; ++i) {
    CorpusEntry entry;
    entry.preset = names[static_cast<size_t>(i) % names.size()];
    entry.seed = base_seed * 1000u + static_cast<uint32_t>(i);
    entry.spec = varied_spec(preset(entry.preset), entry.seed, with_painted);
    char index[16];
    std::snprintf(index, sizeof index, "%03d", i);
    entry.name = entry.preset + "_" + index;
    plan.push_back(std::move(entry));
  }
  return plan;
}

SynthModel generate_model(const HairStyleSpec& spec, const PolyMesh& body_m, uint32_t seed,
                          int strands_per_stream) {
  Rng rng(seed);
  Head head = measure_head(body_m);
  std::vector<Stream> streams;
  for (size_t c = 0; c < spec.components.size(); ++c) {
    const ComponentSpec& component = spec.components[c];
    int index = static_cast<int>(c);
    switch (component.kind) {
      case ComponentSpec::Kind::normal:
      case ComponentSpec::Kind::short_cards:
        add_loose_streams(component, index, spec.defects, head, rng, streams);
        break;
      case ComponentSpec::Kind::ponytail:
        add_ponytail(component, index, spec.defects, head, rng, streams);
        break;
      case ComponentSpec::Kind::braid:
        add_braid(component, index, spec.defects, head, rng, streams);
        break;
      case ComponentSpec::Kind::short_cap:
        add_short_cap(component, index, spec.defects, head, rng, streams);
        break;
    }
  }

  SynthModel model;
  model.name = spec.name;
  model.seed = seed;
  model.spec = spec;
  // The true strands draw from their own generator, so that their count leaves the mesh as it is.
  Rng strand_rng(seed ^ 0x5bd1e995u);
  std::vector<float> uv, positions;
  std::vector<Points3f> centres, strand_polylines;
  std::vector<int32_t> strand_stream;
  std::vector<std::vector<int32_t>> ring_streams(spec.components.size());
  for (size_t s = 0; s < streams.size(); ++s) {
    const Stream& stream = streams[s];
    auto stream_id = static_cast<int32_t>(s);
    const ComponentSpec& component = spec.components[static_cast<size_t>(stream.component)];
    const bool in_rings = component.one_piece_rings || component.one_piece_grid;
    if (in_rings) ring_streams[static_cast<size_t>(stream.component)].push_back(stream_id);
    int pieces = in_rings ? 0 : static_cast<int>(stream.pieces.size());
    for (int k = 0; k < pieces; ++k) {
      const Piece& piece = stream.pieces[static_cast<size_t>(k)];
      const bool folded = component.folded_shell_thickness_m > 0 && piece.style != HairStyle::fixed &&
                          stream.scalp_lift_m.empty();
      SynthPatch patch =
          component.tube_sides > 0
              ? build_tube_patch(stream, piece, component.tube_sides, spec.defects, rng, positions,
                                 model.mesh, uv, model.vertex_along_m)
          : folded ? build_folded_patch(stream, piece, component.folded_shell_thickness_m,
                                        spec.defects, rng, positions, model.mesh, uv,
                                        model.vertex_along_m)
                   : build_patch(stream, piece, spec.defects, head, rng, positions, model.mesh, uv,
                                 model.vertex_along_m);
      patch.stream = stream_id;
      patch.index_in_stream = k;
      // Algorithm 1 of the paper: no preceding group and no following one: root-free; no
      // preceding one: root (connected); no following one: tip; otherwise middle.
      patch.type = pieces == 1       ? GroupType::root_free
                   : k == 0          ? GroupType::root_connected
                   : k + 1 == pieces ? GroupType::tip
                                     : GroupType::middle;
      model.patches.push_back(patch);
    }
    Points3f centre(static_cast<Eigen::Index>(stream.points.size()), 3);
    for (size_t i = 0; i < stream.points.size(); ++i)
      centre.row(static_cast<Eigen::Index>(i)) = stream.points[i].cast<float>().transpose();
    centres.push_back(std::move(centre));
    model.stream_style.push_back(stream.style);
    model.stream_component.push_back(stream.component);
    add_true_strands(stream, stream_id, head, strands_per_stream, strand_rng, strand_polylines,
                     strand_stream, model.strand_point_style);
  }
  // Hair rooted under cards that stand off the head, from a generator of its own, after every
  // other true strand: those stay as they are.
  Rng under_rng(seed ^ 0x27d4eb2fu);
  for (size_t s = 0; s < streams.size(); ++s)
    if (spec.components[static_cast<size_t>(streams[s].component)].rooted_under_volume)
      add_true_strands_under_volume(streams[s], static_cast<int32_t>(s), head, strands_per_stream,
                                    spec.defects.scalp_lift_m, under_rng, strand_polylines,
                                    strand_stream, model.strand_point_style);
  for (size_t c = 0; c < ring_streams.size(); ++c) {
    const std::vector<int32_t>& ids = ring_streams[c];
    if (ids.empty()) continue;
    model.patches.push_back(spec.components[c].one_piece_grid
                                ? build_grid_patch(streams, ids, spec.defects, head, positions,
                                                   model.mesh, uv, model.vertex_along_m)
                                : build_ring_patch(streams, ids, spec.defects, head, rng, positions,
                                                   model.mesh, uv, model.vertex_along_m));
  }
  model.mesh.vertices = Eigen::Map<const Points3f>(
      positions.data(), static_cast<Eigen::Index>(positions.size() / 3), 3);
  model.mesh.corner_uv =
      Eigen::Map<const Uv2f>(uv.data(), static_cast<Eigen::Index>(uv.size() / 2), 2);
  if (spec.defects.painted_texture) {
    model.mesh.materials = {painted_hair_material(seed, spec.defects.painted_fade)};
    model.mesh.face_material.assign(static_cast<size_t>(model.mesh.face_count()), 0);
  }
  model.stream_centres = strand_set_from_polylines(centres);
  model.strands = strand_set_from_polylines(strand_polylines);
  model.strands.strand_attributes["stream"] = strand_stream;
  return model;
}

}  // namespace hair::synth
