#include "hair/sim/body_collider.h"

namespace hair {

using Vec3 = Eigen::Vector3d;

void push_out_along_gradient(const BodySdf& body, Vec3& point_m, double distance_m,
                             double clearance_m) {
  for (int step = 0; step < 3 && distance_m < clearance_m; ++step) {
    Vec3 gradient = body.gradient(point_m);
    double norm = gradient.norm();
    if (!(norm > 1e-6)) return;  // deeper than the band: no direction to go
    point_m += (clearance_m - distance_m + 0.01 * body.voxel_m()) * gradient / norm;
    distance_m = body.distance(point_m);
  }
}

bool BodyCollider::collide(Vec3& position_m, const Vec3& start_m, Vec3& normal,
                           Vec3& surface_velocity_m_s) const {
  Vec3 rest = end_.apply_inverse(position_m);
  if (body_.certainly_farther_than(rest, clearance_m_)) return false;
  double distance = body_.distance(rest);
  if (distance >= clearance_m_) return false;
  deepest_m_ = std::max(deepest_m_, -distance);
  push_out_along_gradient(body_, rest, distance, clearance_m_);
  if (body_.distance(rest) < 0) {
    // Deeper than the field's band (no gradient to follow): back where it was on the
    // body at the start of the step, which was outside.
    Vec3 where_it_was = start_.apply_inverse(start_m);
    if (body_.distance(where_it_was) > body_.distance(rest)) rest = where_it_was;
  }
  Vec3 gradient = body_.gradient(rest);
  normal = gradient.norm() > 1e-6 ? end_.rotate(gradient.normalized()) : Vec3::Zero();
  position_m = end_.apply(rest);
  surface_velocity_m_s = (position_m - start_.apply(rest)) / dt_s_;
  return true;
}

}  // namespace hair
