#include "hair/sim/simulation_profile.h"

#include <array>
#include <cstdio>
#include <utility>

namespace hair {

SimulationProfile& SimulationProfile::operator+=(const SimulationProfile& other) {
  springs_s += other.springs_s;
  solve_s += other.solve_s;
  limits_s += other.limits_s;
  collisions_s += other.collisions_s;
  hair_hair_s += other.hair_hair_s;
  bundles_s += other.bundles_s;
  frames_s += other.frames_s;
  loop_s += other.loop_s;
  particle_steps += other.particle_steps;
  return *this;
}

double SimulationProfile::ns_per_particle_step() const {
  return particle_steps > 0 ? 1e9 * loop_s / static_cast<double>(particle_steps) : 0.0;
}

std::string SimulationProfile::summary() const {
  const std::array<std::pair<const char*, double>, 7> phases = {{{"springs", springs_s},
                                                                 {"solve", solve_s},
                                                                 {"limits", limits_s},
                                                                 {"collisions", collisions_s},
                                                                 {"hair-hair", hair_hair_s},
                                                                 {"bundles", bundles_s},
                                                                 {"frames", frames_s}}};
  double total = 0;
  for (const auto& phase : phases) total += phase.second;
  std::string text;
  char part[64];
  if (!(total > 0)) text = "phases not timed (profile_phases)";
  for (const auto& phase : phases) {
    if (!(total > 0)) break;
    std::snprintf(part, sizeof part, "%s%s %.1f%%", text.empty() ? "" : ", ", phase.first,
                  total > 0 ? 100 * phase.second / total : 0.0);
    text += part;
  }
  std::snprintf(part, sizeof part, "; %.1f ns per particle-step", ns_per_particle_step());
  return text + part;
}

}  // namespace hair
