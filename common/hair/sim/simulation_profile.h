#pragma once
// Where a simulation's time goes, by phase (bench/simulate_scaling.sh prints it). The
// phases are timed only when asked (SimulationParams::profile_phases: two clock reads per
// phase and strand step); the frames' wall time and the particle-steps always are. The
// per-strand phases are summed over the threads that ran them (thread-seconds); the
// serial ones are wall time of the one thread that runs them.

#include <chrono>
#include <cstdint>
#include <string>

namespace hair {

/// Seconds spent in each phase of the frames of a simulation.
struct SimulationProfile {
  double springs_s = 0;     ///< per strand: inertia, springs and anchors into the band system
  double solve_s = 0;       ///< per strand: the banded Cholesky solve for the velocities
  double limits_s = 0;      ///< per strand: positions advanced, strain limiting, ghosts
  double collisions_s = 0;  ///< per strand: pushed out of the body, with friction
  double hair_hair_s = 0;   ///< the density grid (serial) and each particle's repulsion
  double bundles_s = 0;     ///< tails' cohesion: centre lines (serial) and each member's pull
  double frames_s = 0;      ///< serial: recording each frame and its statistics
  double loop_s = 0;        ///< wall time of all frames, every phase included
  int64_t particle_steps = 0;  ///< particles (hair and ghosts) times substeps integrated

  SimulationProfile& operator+=(const SimulationProfile& other);
  /// Wall time per particle and substep, in nanoseconds (0 before any step).
  double ns_per_particle_step() const;
  /// "springs 31%, solve 22%, ..." of the phases' sum (or that they were not timed), and
  /// the ns per particle-step.
  std::string summary() const;
};

/// Adds the time from its construction to its end to `*seconds`; with none, reads no clock.
class PhaseTimer {
 public:
  explicit PhaseTimer(double* seconds) : seconds_(seconds) {
    if (seconds_) start_ = std::chrono::steady_clock::now();
  }
  ~PhaseTimer() {
    if (seconds_)
      *seconds_ +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  PhaseTimer(const PhaseTimer&) = delete;
  PhaseTimer& operator=(const PhaseTimer&) = delete;

 private:
  double* seconds_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace hair
