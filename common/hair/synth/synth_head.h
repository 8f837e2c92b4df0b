#pragma once
// The head synthetic hair grows on: directions over it, its hairline, its measures and the
// body the hair is kept off, and the directions of roots in a region of its scalp.

#include <Eigen/Core>
#include <numbers>
#include <utility>
#include <vector>

#include "hair/geom/triangle_mesh_distance.h"
#include "hair/mesh/poly_mesh.h"
#include "hair/synth/synth_model.h"
#include "hair/synth/synth_rng.h"

namespace hair::synth {

/// A point or direction in metres, +Y up, the face towards +Z.
using Vec3 = Eigen::Vector3d;
/// Pi, for angles in radians.
inline constexpr double kPi = std::numbers::pi;

/// `degrees` in radians.
double radians(double degrees);

/// Unit direction at `azimuth_deg` around +Y from +Z (the face) towards +X and
/// `polar_deg` from +Y.
Vec3 direction(double azimuth_deg, double polar_deg);

/// Polar angle of the front hairline at an azimuth: high on the forehead, low at the nape.
double hairline_polar_deg(double azimuth_deg);

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

/// The head of `body_m` (a body mesh in metres, +Y up, face towards +Z): its centre and
/// radius, measured on the body above the neck, and the body's distance.
Head measure_head(const PolyMesh& body_m);

/// `point`, near the head, moved to `lift_m` off the nearest point of the body (out of
/// the head if it was inside): hair lying on the scalp across a stream's whole width (a
/// flat 6 cm strip tangent to the head stands 5 mm off it at its edges).
Vec3 on_scalp(const Head& head, const Vec3& point, double lift_m);

/// Root directions spread evenly (a Fibonacci lattice) over the component's scalp
/// region below the hairline, jittered; `count` of them.
std::vector<Vec3> root_directions(const ComponentSpec& component, int count, Rng& rng);

}  // namespace hair::synth
