#pragma once
// A human hair's material and geometry (SI units), what simulated strands are made of.

#include <numbers>

namespace hair {

/// One human hair, SI units. Defaults: Robbins, "Chemical and Physical Behavior of Human
/// Hair" (5th ed., 2012): Young's modulus 3.89e10 dyn/cm^2 and torsional (shear) modulus
/// 0.89e10 dyn/cm^2 at 65% relative humidity, density 1.32 g/cm^3; radius 35 um (a
/// diameter of 70 um, typical of European hair; 40-120 um across people).
struct HairFibre {
  double youngs_modulus_pa = 3.89e9;
  double shear_modulus_pa = 0.89e9;
  double radius_m = 35e-6;
  double density_kg_m3 = 1320;

  double area_m2() const { return std::numbers::pi * radius_m * radius_m; }
  /// I = pi r^4 / 4, for bending.
  double second_moment_m4() const { return area_m2() * radius_m * radius_m / 4; }
  /// J = pi r^4 / 2, for twist.
  double polar_moment_m4() const { return area_m2() * radius_m * radius_m / 2; }
  double mass_per_length_kg_m() const { return density_kg_m3 * area_m2(); }
  double bending_rigidity_n_m2() const { return youngs_modulus_pa * second_moment_m4(); }
  double twisting_rigidity_n_m2() const { return shear_modulus_pa * polar_moment_m4(); }
};

}  // namespace hair
