#pragma once
// Tails that hold together: the guides of one simulated cluster that hang from a band
// (each starts from the end of fixed hair) or that gather (somewhere along their middle
// at most 0.6 times as spread as at their roots: a ponytail whose strands run from the
// scalp through the band; or passing close to one point at any arc fraction: a low tail
// whose strands meet its band at different lengths) are a bundle. Each
// hair particle is drawn back towards the bundle's centre line where it strays farther
// from it than at rest, by a one-sided spring per kilogram: the bundle swings and twists
// as one (its centre line moves freely), its guides do not fan out, and the hair-hair
// repulsion still keeps them apart. The spring is damped, as the friction between a
// tail's hairs damps their motion against one another: beyond its rest distance a
// particle's speed away from the centre line, relative to the centre line's own velocity
// (the members' mean), is resisted at a fraction of the spring's critical damping. At
// rest it exerts nothing. Derivation and figures in docs/simulate.md, "Tails that hold
// together".

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "hair/sim/hair_simulation.h"
#include "hair/sim/simulation_setup.h"

namespace hair {

class BundleCohesion {
 public:
  /// Finds the bundles among `guides` (at least `min_guides` strand guides of one cluster,
  /// hanging from a band or gathered) and their rest centre lines; `stiffness_per_s2` 0
  /// turns the cohesion off; `damping_ratio` is the spring's damping, a fraction of
  /// critical (0: undamped).
  BundleCohesion(const std::vector<SimulatedGuide>& guides,
                 const std::vector<RunningStrand>& running, double stiffness_per_s2,
                 double damping_ratio = 0, int min_guides = 3);

  /// The cohesion's acceleration of every particle of the bundles' strands (ghosts get
  /// none), from their positions now, for a step of `dt_s`: written into
  /// `acceleration_m_s2[g]` for each member g (sized to its particles; the others are left
  /// alone). The spring is explicit, so its stiffness is held to at most 1 / dt^2
  /// (`stiffness_for_step`). The same as sample_all(), update_centres() and
  /// acceleration() for each member.
  void accelerations(const std::vector<RunningStrand>& running, double dt_s,
                     std::vector<std::vector<Eigen::Vector3d>>& acceleration_m_s2);

  /// The step's pieces, for a loop that steps the strands in parallel: sample(g) records
  /// member g's polyline at its positions now (any member on any thread, each once);
  /// update_centres() then makes each bundle's centre line of them (serial, cheap);
  /// acceleration(g) gives member g's cohesion against it (any thread). Not a member:
  /// sample() does nothing, acceleration() gives zeros.
  void sample(size_t g, const std::vector<RunningStrand>& running);
  void sample_all(const std::vector<RunningStrand>& running);
  void update_centres();
  void acceleration(size_t g, const std::vector<RunningStrand>& running, double dt_s,
                    std::vector<Eigen::Vector3d>& acceleration_m_s2) const;

  /// The stiffness per kg used for a step of `dt_s`: the set one, but at most 1 / dt^2.
  /// A spring applied explicitly (from the positions at the start of the step) in the
  /// semi-implicit Euler step is stable while k dt^2 < 4, undamped; held to k dt^2 <= 1
  /// it keeps a margin for the other forces and pulls a stray particle at most all the
  /// way back in one step, never past the centre. At the default 1/60 s step (k dt^2 =
  /// 0.44 for 1600/s^2) it is the set stiffness.
  double stiffness_for_step(double dt_s) const;

  /// The damping per second used for a step of `dt_s`: `damping_ratio` times the critical
  /// 2 sqrt(k) of stiffness_for_step(dt_s), at most 1 / dt. The explicit damped spring
  /// in the semi-implicit Euler step, with a = k dt^2 and b = c dt, maps (x, v dt) by a
  /// matrix of trace 2 - a - b and determinant 1 - b: stable while 0 <= b < 2 and
  /// a < 4 - 2 b, so k dt^2 <= 1 and c dt <= 1 keep it stable (at both bounds it stops a
  /// stray particle's excess in one step). At the default 1/60 s step and 1600/s^2 the
  /// critical 80/s is held to 60/s.
  double damping_for_step(double dt_s) const;

  bool active() const { return stiffness_per_s2_ > 0 && !bundles_.empty(); }
  /// Whether running strand `g` belongs to a bundle (only those get accelerations).
  bool member(size_t g) const { return g < bundle_of_.size() && bundle_of_[g] >= 0; }
  int64_t bundle_count() const { return static_cast<int64_t>(bundles_.size()); }
  int64_t guide_count() const;
  /// Guides of other clusters that hang inside a bundle and follow it (add_followers()).
  int64_t follower_count() const;

 private:
  struct Bundle {
    int32_t cluster = 0;
    std::vector<size_t> members;  ///< running strand indices
    /// Strand guides of other clusters, in no bundle, that hang inside this one: drawn
    /// back like the members, but not part of the centre line.
    std::vector<size_t> followers;
    /// Per member, then per follower, per hair particle: its rest distance from the rest
    /// centre line.
    std::vector<std::vector<double>> rest_radius_m;
    std::vector<Eigen::Vector3d> centre;  ///< the centre line now (update_centres())
    std::vector<Eigen::Vector3d> centre_velocity;  ///< its velocity: the members' mean
  };

  /// A strand guide in no bundle whose lower three quarters lie, as a root mean square of
  /// their rest offsets from a bundle's centre line, no farther out than the bundle's
  /// widest member's follows that bundle (the nearest such): a cluster too small to be a
  /// bundle of its own, hanging in a tail (one guide of a small cluster beside a tail would
  /// swing alone to the other shoulder).
  void add_followers(const std::vector<SimulatedGuide>& guides,
                     const std::vector<RunningStrand>& running);

  double stiffness_per_s2_ = 0;
  double damping_ratio_ = 0;
  std::vector<Bundle> bundles_;
  std::vector<int32_t> bundle_of_;  ///< per running strand: its bundle, or -1
  std::vector<int32_t> slot_of_;    ///< per running strand: its index among the members
  /// Per running strand (members only): its polyline at kCentreSamples arc fractions.
  std::vector<Eigen::Vector3d> samples_;
  std::vector<Eigen::Vector3d> velocity_samples_;  ///< their velocities
};

}  // namespace hair
