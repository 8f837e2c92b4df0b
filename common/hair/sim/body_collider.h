#pragma once
// The body as the strand solver sees it while the head moves (simulate stage): a signed
// distance field in the body's rest frame, sampled through the head's transforms.

#include <Eigen/Core>

#include "hair/geom/body_sdf.h"
#include "hair/sim/head_motion.h"
#include "hair/sim/strand_dynamics.h"

namespace hair {

/// Moves `point_m` (in the field's frame, `distance_m` from the body) out to
/// `clearance_m` along the field's unit gradient, in at most three steps. Unlike
/// BodySdf::push_out's Newton steps, each step is no longer than the distance still to
/// go, so a weak gradient (at the edge of the field's band) cannot throw a point far. A
/// point deeper than the band (no gradient) stays where it is.
void push_out_along_gradient(const BodySdf& body, Eigen::Vector3d& point_m, double distance_m,
                             double clearance_m);

/// The body moving with the head over one step, from pose `start` to pose `end` (world
/// from rest): positions are taken into the body's rest frame at the end of the step,
/// pushed out there (push_out_along_gradient), and brought back; a particle deeper than
/// the field's band goes back to where it was on the body at the start of the step. The
/// surface velocity is that of the body's point over the step.
class BodyCollider : public StrandCollider {
 public:
  /// Keeps references to `body`, `start` and `end`: they must outlive the collider.
  BodyCollider(const BodySdf& body, const RigidTransform& start, const RigidTransform& end,
               double clearance_m, double dt_s)
      : body_(body), start_(start), end_(end), clearance_m_(clearance_m), dt_s_(dt_s) {}

  bool collide(Eigen::Vector3d& position_m, const Eigen::Vector3d& start_m, Eigen::Vector3d& normal,
               Eigen::Vector3d& surface_velocity_m_s) const override;
  /// Deepest a particle was inside the body, metres (0 if none was).
  double deepest_m() const { return deepest_m_; }

 private:
  const BodySdf& body_;
  const RigidTransform& start_;
  const RigidTransform& end_;
  double clearance_m_, dt_s_;
  mutable double deepest_m_ = 0;
};

}  // namespace hair
