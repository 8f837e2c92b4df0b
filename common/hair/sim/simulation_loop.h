#pragma once
// The frames of simulate_hair() (hair_simulation.h): frame 0 at rest, then each frame's
// substeps over every simulated strand, the hair-hair repulsion, the recorded positions
// and wisp frames, the statistics, and the settling of a still head. Internal to sim/.

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "hair/geom/body_sdf.h"
#include "hair/sim/bundle_cohesion.h"
#include "hair/sim/hair_density_field.h"
#include "hair/sim/hair_simulation.h"
#include "hair/sim/simulation_setup.h"

namespace hair {

class SimulationLoop {
 public:
  /// Runs `running` (the strands built from result.guides, in that order) under `motion`
  /// and writes the frames into `result`; the references must outlive the loop.
  SimulationLoop(const SimulationScene& scene, const HeadMotion& motion,
                 const SimulationParams& params, const std::optional<BodySdf>& body,
                 std::vector<RunningStrand> running, SimulationResult& result);

  /// Frame 0: the rest shape where the head is at time 0, at rest; the frame count, the
  /// output arrays and the rest density that the repulsion compares with.
  void start();
  /// Frames 1 on: each integrated in substeps, or, once a still head has settled, a
  /// repeat of the last. Throws Error::runtime naming the frame and guide where a
  /// position becomes non-finite.
  void run();

 private:
  /// run()'s frames, timed by phase.
  void run_frames();
  /// One frame's substeps over every strand, from the head's pose at the frame before to
  /// `pose`.
  void integrate_frame(int32_t frame, const RigidTransform& pose);
  /// One substep of guide g, from the head at `from` to `to`; marks it failed where a
  /// position becomes non-finite. Called in parallel over the guides.
  void step_strand(size_t g, int step, bool repel, const RigidTransform& from,
                   const RigidTransform& to);
  /// Repulsion on hair particle i of `strand`, from the other strands' hair.
  Eigen::Vector3d repulsion(const RunningStrand& strand, int32_t i,
                            const RigidTransform& pose) const;
  /// The hair particles' positions of every strand, in order, into hair_positions_.
  void gather_hair();
  /// The guides' hair particles and the wisps' tetrahedra frames at `frame`.
  void record_frame(int32_t frame, const RigidTransform& pose);
  /// The frame's figures, each strand's share in parallel and summed in strand order (so
  /// they do not depend on the thread count); the springs' elastic energy is left pending.
  FrameStatistics frame_statistics(double time_s, const RigidTransform& pose);
  /// The pending frame's elastic energy from the springs' energy the next step read off.
  void settle_pending_energy();
  /// The pending frame's elastic energy at the present positions, where no step follows.
  void spring_energy_now();

  /// A strand's share of a frame's statistics.
  struct StrandShare {
    double kinetic_j = 0, gravity_j = 0, anchor_j = 0, max_speed_m_s = 0, strain = 0,
           penetration_m = 0;
    int64_t inside = 0, hair = 0;
  };

  const SimulationScene& scene_;
  const HeadMotion& motion_;
  const SimulationParams& params_;
  const std::optional<BodySdf>& body_;
  SimulationResult& result_;
  std::vector<RunningStrand> running_;
  const double h_;
  const double clearance_m_;
  const double dt_s_;
  const Eigen::Vector3d gravity_;
  size_t hair_points_ = 0;  ///< hair particles of all strands: a frame's points
  int32_t tetrahedra_ = 0;  ///< of all wisps
  HairDensityField density_;
  HairDensityField rest_density_;
  double reference_density_ = 0;
  std::vector<Eigen::Vector3d> hair_positions_;
  std::vector<StrandStepper> steppers_;  ///< one per thread
  BundleCohesion cohesion_;              ///< tails that hold together
  /// Per strand: what a bundle member's step applies (repulsion and cohesion summed).
  std::vector<std::vector<Eigen::Vector3d>> applied_m_s2_;
  RigidTransform previous_;              ///< the head at the last step's end
  std::vector<StrandShare> shares_;
  std::vector<double> spring_j_;
  /// The frame whose statistics wait for their springs' energy (shares_[g].anchor_j kept
  /// for it), or -1. The elastic energy's share of a strand's springs (anchors excluded)
  /// is what the next frame's first step evaluates its springs at, so it is read off
  /// that step (StrandStepper::start_spring_energy_j(), bit for bit) rather than
  /// evaluated again; it is worked out at once where no step follows (the last frame, a
  /// settled head).
  int32_t pending_energy_frame_ = -1;
  SimulationProfile profile_;  ///< the serial phases' time; the steppers hold the rest
  /// `seconds` of profile_ where the phases are timed, else none.
  double* serial_phase(double SimulationProfile::*seconds) {
    return params_.profile_phases ? &(profile_.*seconds) : nullptr;
  }
};

}  // namespace hair
