#pragma once
// Spring constants of an altitude strand from the hair it stands for: a fibre's Young's
// and shear moduli, radius and density, and how many fibres the strand carries. The
// hair segments stretch as the fibres do (k = N E A / L); the other springs, which hold
// the chain's bending and twist, are scaled so that a straight chain bends with N E I and
// twists with N G J, by a measure of the discrete chain's rigidity (a pure moment and a
// pure torque on a reference chain, solved linearly). The derivation is in
// docs/simulate.md, "Physical parameters".

#include <map>
#include <mutex>

#include "hair/sim/altitude_strand.h"
#include "hair/sim/hair_fibre.h"
#include "hair/sim/strand_dynamics.h"

namespace hair {

/// Bending and twisting rigidity (N m^2) of a straight chain.
struct ChainRigidity {
  double bending_n_m2 = 0;      ///< mean of two perpendicular planes
  double twisting_n_m2 = 0;
  double bending_anisotropy = 1;  ///< the stiffer plane's over the softer's
};

/// Measures the rigidity of a straight altitude chain of 48 unit hair segments (a ghost
/// on each, as build_altitude_strand() places them) whose hair segments have stiffness
/// `hair_segment_n_m`, the other edge, bend and altitude springs `bend_group_n_m` and the
/// torsion springs (q_k to q_k+3) `torsion_n_m`, clamped at its root: a pure moment (a couple on
/// the last segment) in each of two perpendicular planes, read off the curvature of its
/// middle half, and a pure torque (the last ghost pushed about the axis against its two
/// hair neighbours), read off the twist of the middle half's ghosts, each one band solve
/// of the linear statics. For segments of length l the rigidity is this times l^3.
ChainRigidity measure_chain_rigidity(double bend_group_n_m, double torsion_n_m,
                                     double hair_segment_n_m = 1e6,
                                     const AltitudeStrandOptions& options = {});

/// Spring constants that give a chain of unit segments, whose hair segments have
/// stiffness `hair_segment_n_m`, unit bending rigidity and twisting rigidity
/// `twist_to_bend` (or as near as its springs can: `achieved_twist_to_bend`).
struct ChainCalibration {
  double bend_group_n_m = 0;
  double torsion_n_m = 0;
  double achieved_twist_to_bend = 0;
  double bending_anisotropy = 1;
};

/// Finds the ratio of torsion to bend-group springs whose measured rigidities come
/// nearest the ratio `twist_to_bend` (a grid over 1e-2 .. 1e2 in its logarithm), then
/// scales both to unit bending rigidity with hair segments of stiffness `hair_segment_n_m`
/// (for hair, E A l^2 / E I = 4 (l / r)^2: the bending springs act in series with the
/// segments, which matters where segments are under a few hundred radii). The altitude chain twists at most about 0.18
/// times as readily as it bends (hair: 2 G / E = 0.46), so for hair it takes the
/// torsion springs that come nearest, about a tenth of the bend group's.
ChainCalibration calibrate_chain(double twist_to_bend, double hair_segment_n_m = 1e6,
                                 const AltitudeStrandOptions& options = {});

/// What the strands of a simulation are made of, and how their springs follow from it.
/// Construct once, then assign() to each strand (the chain is calibrated per segment
/// length, and kept).
class StrandStiffness {
 public:
  /// A lock of `material.fibres_per_strand` (N) fibres: their masses add; it bends and
  /// twists with N (1 + cohesion (N - 1)) times one fibre's rigidity, from fibres free to
  /// slide on one another (`lock_cohesion` 0: N E I) to fibres bonded into one round
  /// bundle (1: N^2 E I, the bundle's second moment of area (N A)^2 / 4 pi). Its hair
  /// segments are held to length by the strain limit; their springs vibrate at
  /// `stretch_frequency_hz` (a numerical stiffness, not the hair's: see assign()).
  explicit StrandStiffness(const StrandMaterial& material,
                           const AltitudeStrandOptions& options = {});

  /// The bending rigidity, N m^2, of `strand_count` locks side by side (a wisp's centre
  /// stands for its strands): strand_count N (1 + cohesion (N - 1)) E I.
  double bending_rigidity_n_m2(double strand_count = 1) const;

  /// Mass per metre of a strand carrying `strand_count` strands' fibres.
  double mass_per_length_kg_m(double strand_count = 1) const;

  /// Sets the stiffness and damping of every spring of `strand` (built with
  /// mass_per_length_kg_m(strand_count)): the bending and torsion springs the
  /// calibration's constants times the lock's E I / l^3, l the strand's mean hair segment;
  /// the hair segments m (2 pi f)^2, m the mean mass of their two particles and f the
  /// stretch frequency, but at least 1000 E I / l^3 (a chord that does not give as the
  /// chain bends) and at most the hair's own E A / L. (Hair's own would vibrate at
  /// sqrt(E / rho) / 2 L, about 40 kHz for 2 cm: inextensible at any step, which the
  /// strain limit enforces anyway, and a linearised spring that stiff turns each step's
  /// rotation into spurious stretch energy.) Each spring damped at damping_ratio of
  /// critical for its particles' mean mass.
  void assign(AltitudeStrand& strand, double strand_count = 1) const;

  /// The chain's calibration for hair segments of stiffness `segment_stiffness` in units
  /// of the bending rigidity over the segment length cubed (worked out once per 1/64 of a
  /// decade; thread-safe).
  ChainCalibration calibration(double segment_stiffness) const;

 private:
  HairFibre fibre_;
  double fibres_ = 1, cohesion_ = 0, damping_ratio_ = 0, stretch_frequency_hz_ = 0;
  AltitudeStrandOptions options_;
  mutable std::mutex cache_mutex_;
  mutable std::map<double, ChainCalibration> cache_;
};

/// build_altitude_strand() with the springs of `stiffness` assigned.
AltitudeStrand build_hair_strand(const std::vector<Eigen::Vector3d>& hair_points_m,
                                 const StrandStiffness& stiffness, double strand_count = 1,
                                 const AltitudeStrandOptions& options = {});

}  // namespace hair
