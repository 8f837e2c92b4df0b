#pragma once
// Whether a simulation run stayed stable (bench/stability.sh): finite, the hair's stretch
// and the share left inside the body within bounds, the springs' deformation within
// 0.05 H, and no growth of the kinetic energy; from a guides.h5.

#include <string>

#include "hair/h5/file.h"

namespace hair {

/// A run's figures, read off guides.h5's per-frame statistics.
struct RunStability {
  int64_t frames = 0;
  bool finite = true;  ///< every guide point and per-frame energy
  double max_stretch = 0, max_penetration_m = 0, max_inside = 0, max_speed_m_s = 0;
  double first_total_j = 0, last_total_j = 0, max_total_j = 0;  ///< kinetic + elastic + gravity
  /// The largest kinetic energy over the middle and the last third of the frames, and
  /// their ratio (the first third holds the ramp and the swing building up).
  double middle_kinetic_j = 0, last_kinetic_j = 0, growth = 0;
  /// sqrt(2 E / (k M)) for the largest elastic energy E, k the hair segments' stiffness
  /// per kilogram ((2 pi stretch_frequency_hz)^2 times stiffness_scale) and M the
  /// simulated hair's mass (wisps by the strands they carry): how far the springs are
  /// from their rest lengths, whatever their stiffness.
  double deformation_m = 0;
  double head_height_m = 0;
  std::string verdict;  ///< "stable", or the first criterion that failed
};

/// The figures of the guides.h5 `file` (schema-checked), judged with the bounds on the
/// stretch and on the share of hair particles left inside the body.
RunStability run_stability(const h5::File& file, double stretch_bound = 0.011,
                           double inside_bound = 0.05);

}  // namespace hair
