#include "hair/sim/altitude_strand.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "hair/geom/barycentric.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;

/// Face (three corners) opposite corner `point` of a tetrahedron, in an order fixed per
/// corner so that the sign of its normal is too.
constexpr std::array<std::array<int, 3>, 4> kOppositeFace{
    {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}}};
/// The three pairs of opposite edges: (01, 23), (02, 13), (03, 12).
constexpr std::array<std::array<int, 4>, 3> kEdgePair{{{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2}}};

/// Parameters (s, t) in [0, 1] of the closest points of the segments a + s e1, c + t e2.
std::pair<double, double> closest_segment_parameters(const Vec3& a, const Vec3& e1, const Vec3& c,
                                                     const Vec3& e2) {
  Vec3 r = a - c;
  double a11 = e1.dot(e1), a22 = e2.dot(e2), a12 = e1.dot(e2);
  double b1 = e1.dot(r), b2 = e2.dot(r);
  double denominator = a11 * a22 - a12 * a12;
  double s = denominator > 0 ? std::clamp((a12 * b2 - a22 * b1) / denominator, 0.0, 1.0) : 0.0;
  double t = a22 > 0 ? std::clamp((a12 * s + b2) / a22, 0.0, 1.0) : 0.0;
  s = a11 > 0 ? std::clamp((a12 * t - b1) / a11, 0.0, 1.0) : 0.0;
  return {s, t};
}

/// The ghost beside the segment (from, to) that makes the worst of the tetrahedra it
/// closes, (p2, p1, p0, ghost) and (p1, p0, ghost, to), best; p0 is the last particle
/// (`from`), p1 and p2 the ones before it (absent for the ghost after the root). Of
/// twelve angles about the segment; ties go to a quarter turn on from the last ghost.
Vec3 place_ghost(const std::vector<Vec3>& sequence, const std::vector<uint8_t>& is_ghost,
                 const Vec3& to, double offset) {
  const Vec3& from = sequence.back();
  Vec3 axis = to - from;
  double length = axis.norm();
  axis /= length;
  const size_t n = sequence.size();
  // Angles are measured from the last ghost's direction off its segment, carried onto
  // this segment, so that where the quality ties (straight hair) each ghost turns a
  // quarter on from the last: a chain that bends alike every way. Without one, from a
  // direction the segment alone fixes.
  Vec3 u = Vec3::Zero();
  for (size_t back = 1; back <= 3 && back < n; ++back) {
    const size_t g = n - back;
    if (!is_ghost[g] || g == 0 || g + 1 >= n) continue;
    const Vec3 radial = sequence[g] - 0.5 * (sequence[g - 1] + sequence[g + 1]);
    u = radial - radial.dot(axis) * axis;
    break;
  }
  if (!(u.norm() > 1e-9 * length)) {
    const Vec3 helper = std::abs(axis.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
    u = axis.cross(helper);
  }
  u.normalize();
  const Vec3 v = axis.cross(u);
  const Vec3 middle = 0.5 * (from + to);
  Vec3 best = middle + offset * length * v;
  double best_score = -std::numeric_limits<double>::infinity();
  for (int k = 0; k < 12; ++k) {
    const double angle = k * std::numbers::pi / 6;
    const Vec3 ghost = middle + offset * length * (std::cos(angle) * u + std::sin(angle) * v);
    double score = 1;
    if (n >= 3) score = tetrahedron_quality(sequence[n - 3], sequence[n - 2], from, ghost);
    if (n >= 2) score = std::min(score, tetrahedron_quality(sequence[n - 2], from, ghost, to));
    // Ties go to the quarter turn on.
    score -= 1e-9 * std::abs(angle - std::numbers::pi / 2);
    if (score > best_score) {
      best_score = score;
      best = ghost;
    }
  }
  return best;
}

}  // namespace

double tetrahedron_quality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  double volume = std::abs((b - a).dot((c - a).cross(d - a))) / 6;
  double sum_squares = (b - a).squaredNorm() + (c - a).squaredNorm() + (d - a).squaredNorm() +
                       (c - b).squaredNorm() + (d - b).squaredNorm() + (d - c).squaredNorm();
  if (!(sum_squares > 0)) return 0;
  double rms = std::sqrt(sum_squares / 6);
  return 6 * std::numbers::sqrt2 * volume / (rms * rms * rms);
}

RobustAltitudes robust_altitudes(const std::array<Vec3, 4>& x) {
  // The six edges once; each size is then the cross product kOppositeFace or kEdgePair
  // names (e.g. face 0, corners 1 2 3: (x2 - x1) x (x3 - x1)).
  const Vec3 e01 = x[1] - x[0], e02 = x[2] - x[0], e03 = x[3] - x[0];
  const Vec3 e12 = x[2] - x[1], e13 = x[3] - x[1], e23 = x[3] - x[2];
  const std::array<double, 7> size{e12.cross(e13).squaredNorm(), e02.cross(e03).squaredNorm(),
                                   e01.cross(e03).squaredNorm(), e01.cross(e02).squaredNorm(),
                                   e01.cross(e23).squaredNorm(), e02.cross(e13).squaredNorm(),
                                   e03.cross(e12).squaredNorm()};
  RobustAltitudes found;
  for (int which = 0; which < 7; ++which) {
    const double here = size[static_cast<size_t>(which)];
    if (here > found.best_size) {
      found.second = found.best;
      found.second_size = found.best_size;
      found.best = which;
      found.best_size = here;
    } else if (here > found.second_size) {
      found.second = which;
      found.second_size = here;
    }
  }
  return found;
}

int most_robust_altitude(const std::array<Vec3, 4>& x) { return robust_altitudes(x).best; }

double second_altitude_share(double robustness_ratio) {
  const double from = 1 / kAltitudeBlendFactor;
  return 0.5 * std::clamp((robustness_ratio - from) / (1 - from), 0.0, 1.0);
}

Altitude tetrahedron_altitude(const std::array<Vec3, 4>& x, int which) {
  Altitude altitude;
  if (which < 4) {
    const auto& face = kOppositeFace[static_cast<size_t>(which)];
    const Vec3 &a = x[face[0]], &b = x[face[1]], &c = x[face[2]];
    Vec3 normal = (b - a).cross(c - a);
    altitude.robustness_m2 = normal.norm();
    if (altitude.robustness_m2 > 0) altitude.direction = normal / altitude.robustness_m2;
    auto barycentric = clamped_barycentric(x[which], a, b, c);
    altitude.weight[which] = 1;
    for (int i = 0; i < 3; ++i) altitude.weight[face[i]] = -barycentric[i];
  } else {
    const auto& pair = kEdgePair[static_cast<size_t>(which - 4)];
    const Vec3 &a = x[pair[0]], &c = x[pair[2]];
    Vec3 e1 = x[pair[1]] - a, e2 = x[pair[3]] - c;
    Vec3 normal = e1.cross(e2);
    altitude.robustness_m2 = normal.norm();
    if (altitude.robustness_m2 > 0) altitude.direction = normal / altitude.robustness_m2;
    auto [s, t] = closest_segment_parameters(a, e1, c, e2);
    altitude.weight[pair[0]] = 1 - s;
    altitude.weight[pair[1]] = s;
    altitude.weight[pair[2]] = -(1 - t);
    altitude.weight[pair[3]] = -t;
  }
  Vec3 combined = Vec3::Zero();
  for (int i = 0; i < 4; ++i) combined += altitude.weight[i] * x[i];
  altitude.length_m = altitude.direction.dot(combined);
  return altitude;
}

AltitudeStrand build_altitude_strand(const std::vector<Vec3>& hair_points_m,
                                     double mass_per_length_kg_m,
                                     const AltitudeStrandOptions& options) {
  if (hair_points_m.size() < 2)
    throw std::invalid_argument("an altitude strand needs at least two hair particles");
  for (size_t i = 0; i < hair_points_m.size(); ++i) {
    if (!hair_points_m[i].allFinite())
      throw std::invalid_argument("an altitude strand's hair particle " + std::to_string(i) +
                                  " is not finite");
  }
  for (size_t i = 0; i + 1 < hair_points_m.size(); ++i) {
    if (!((hair_points_m[i + 1] - hair_points_m[i]).norm() > 1e-9))
      throw std::invalid_argument("an altitude strand has a zero-length segment");
  }
  AltitudeStrand strand;
  auto add = [&](const Vec3& point, bool ghost) {
    if (!ghost) strand.hair_particle.push_back(strand.particle_count());
    strand.rest_m.push_back(point);
    strand.is_ghost.push_back(ghost ? 1 : 0);
  };
  add(hair_points_m[0], false);
  for (size_t i = 1; i < hair_points_m.size(); ++i) {
    const Vec3& next = hair_points_m[i];
    size_t n = strand.rest_m.size();
    bool needs_ghost = i == 1;  // the root's ghost holds the root direction
    if (!needs_ghost && n >= 3) {
      needs_ghost =
          tetrahedron_quality(strand.rest_m[n - 3], strand.rest_m[n - 2], strand.rest_m[n - 1],
                              next) < options.min_tetrahedron_quality;
    }
    if (needs_ghost) add(place_ghost(strand.rest_m, strand.is_ghost, next, options.ghost_offset), true);
    add(next, false);
  }
  strand.kinematic_count = 2;  // the root and its ghost
  if (options.clamped_root) {
    // The ghost before the root: beside the first segment, a quarter turn about it from
    // the ghost after the root, so that the three held particles fix the root's frame.
    const Vec3 root = strand.rest_m[0], first = hair_points_m[1];
    const Vec3 middle = 0.5 * (root + first);
    const Vec3 axis = (first - root).normalized();
    const Vec3 leading = middle + axis.cross(strand.rest_m[1] - middle);
    strand.rest_m.insert(strand.rest_m.begin(), leading);
    strand.is_ghost.insert(strand.is_ghost.begin(), 1);
    for (int32_t& q : strand.hair_particle) ++q;
    strand.kinematic_count = 3;
  }

  // Masses: each hair segment's, shared by its hair particles and its ghost.
  int32_t count = strand.particle_count();
  strand.mass_kg.assign(static_cast<size_t>(count), 0.0);
  for (int32_t i = 0; i + 1 < strand.hair_count(); ++i) {
    double length =
        (hair_points_m[static_cast<size_t>(i) + 1] - hair_points_m[static_cast<size_t>(i)]).norm();
    strand.hair_segment_m.push_back(length);
    auto inner = static_cast<size_t>(strand.hair_particle[static_cast<size_t>(i)]);
    auto outer = static_cast<size_t>(strand.hair_particle[static_cast<size_t>(i) + 1]);
    double mass = length * mass_per_length_kg_m;
    if (outer - inner == 2) {  // a ghost between them
      strand.mass_kg[inner + 1] += options.ghost_mass_share * mass;
      mass *= 1 - options.ghost_mass_share;
    }
    strand.mass_kg[inner] += 0.5 * mass;
    strand.mass_kg[outer] += 0.5 * mass;
  }
  if (options.clamped_root) strand.mass_kg[0] = strand.mass_kg[2];  // held: any positive mass
  // Springs along the sequence, and the tetrahedra.
  for (int32_t q = 0; q < count; ++q) {
    for (int32_t reach = 1; reach <= 3 && q + reach < count; ++reach) {
      TwoParticleSpring spring;
      spring.a = q;
      spring.b = q + reach;
      spring.rest_length_m =
          (strand.rest_m[static_cast<size_t>(q + reach)] - strand.rest_m[static_cast<size_t>(q)])
              .norm();
      // By reach along the sequence (edge, bend, torsion), except that the spring
      // across a ghost between two hair particles is the hair segment itself: it is what
      // keeps the hair from stretching, so it is an edge.
      bool hair_segment = reach == 2 && !strand.is_ghost[static_cast<size_t>(q)] &&
                          strand.is_ghost[static_cast<size_t>(q + 1)] &&
                          !strand.is_ghost[static_cast<size_t>(q + 2)];
      hair_segment = hair_segment || (reach == 1 && !strand.is_ghost[static_cast<size_t>(q)] &&
                                      !strand.is_ghost[static_cast<size_t>(q + 1)]);
      spring.hair_segment = hair_segment;
      spring.kind = hair_segment ? SpringKind::edge : static_cast<SpringKind>(reach - 1);
      strand.springs.push_back(spring);
    }
  }
  for (int32_t q = 0; q + 3 < count; ++q) {
    ChainTetrahedron tetrahedron;
    std::array<Vec3, 4> corners;
    for (int i = 0; i < 4; ++i) {
      tetrahedron.particle[static_cast<size_t>(i)] = q + i;
      corners[static_cast<size_t>(i)] = strand.rest_m[static_cast<size_t>(q + i)];
    }
    for (int which = 0; which < 7; ++which)
      tetrahedron.rest_altitude_m[static_cast<size_t>(which)] =
          tetrahedron_altitude(corners, which).length_m;
    strand.tetrahedra.push_back(tetrahedron);
  }
  return strand;
}

}  // namespace hair
