#pragma once
// Tails that hold together: the guides of one simulated cluster that hang from a band
// (each starts from the end of fixed hair) or that gather (somewhere along their middle
// at most 0.6 times as spread as at their roots: a ponytail whose strands run from the
// scalp through the band) are a bundle. Each
// hair particle is drawn back towards the bundle's centre line where it strays farther
// from it than at rest, by a one-sided spring per kilogram: the bundle swings and twists
// as one (its centre line moves freely), its guides do not fan out, and the hair-hair
// repulsion still keeps them apart. At rest it exerts nothing. Derivation and figures in
// docs/simulate.md, "Tails that hold together".

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
  /// turns the cohesion off.
  BundleCohesion(const std::vector<SimulatedGuide>& guides,
                 const std::vector<RunningStrand>& running, double stiffness_per_s2,
                 int min_guides = 3);

  /// The cohesion's acceleration of every particle of the bundles' strands (ghosts get
  /// none), from their positions now: written into `acceleration_m_s2[g]` for each
  /// member g (sized to its particles; the others are left alone).
  void accelerations(const std::vector<RunningStrand>& running,
                     std::vector<std::vector<Eigen::Vector3d>>& acceleration_m_s2) const;

  bool active() const { return stiffness_per_s2_ > 0 && !bundles_.empty(); }
  /// Whether running strand `g` belongs to a bundle (only those get accelerations).
  bool member(size_t g) const { return g < member_.size() && member_[g] != 0; }
  int64_t bundle_count() const { return static_cast<int64_t>(bundles_.size()); }
  int64_t guide_count() const;

 private:
  struct Bundle {
    int32_t cluster = 0;
    std::vector<size_t> members;  ///< running strand indices
    /// Per member, per hair particle: its rest distance from the rest centre line.
    std::vector<std::vector<double>> rest_radius_m;
  };
  /// The centre line of `bundle` at kCentreSamples arc fractions (the mean of its
  /// members' polylines there), from positions `position_of(member, hair particle)`, into
  /// `centre`; `samples` is scratch (members x samples).
  template <typename PositionOf>
  void centre_line(const Bundle& bundle, const std::vector<RunningStrand>& running,
                   PositionOf&& position_of, std::vector<Eigen::Vector3d>& samples,
                   std::vector<Eigen::Vector3d>& centre) const;

  double stiffness_per_s2_ = 0;
  std::vector<Bundle> bundles_;
  std::vector<uint8_t> member_;  ///< per running strand
  mutable std::vector<Eigen::Vector3d> samples_, centre_;  ///< scratch of accelerations()
};

}  // namespace hair
