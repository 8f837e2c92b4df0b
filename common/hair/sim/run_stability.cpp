#include "hair/sim/run_stability.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "hair/core/error.h"
#include "hair/h5/dataset.h"
#include "hair/h5/provenance.h"
#include "hair/sim/guides_io.h"

namespace hair {
namespace {

double largest(const std::vector<double>& values) {
  double most = -std::numeric_limits<double>::infinity();
  for (double v : values) most = std::max(most, v);
  return values.empty() ? 0 : most;
}

double largest_in(const std::vector<double>& values, size_t begin, size_t end) {
  double most = 0;
  for (size_t i = begin; i < end && i < values.size(); ++i) most = std::max(most, values[i]);
  return most;
}

}  // namespace

RunStability run_stability(const h5::File& file, double stretch_bound, double inside_bound) {
  const SimulatedGuides guides = read_simulated_guides(file);
  RunStability run;
  run.head_height_m = guides.head_height_m;
  const auto kinetic = h5::read_vector<double>(file, "/frames/kinetic_energy_j");
  const auto elastic = h5::read_vector<double>(file, "/frames/elastic_energy_j");
  const auto gravity = h5::read_vector<double>(file, "/frames/gravity_energy_j");
  const auto stretch = h5::read_vector<double>(file, "/frames/max_stretch");
  const auto depth = h5::read_vector<double>(file, "/frames/max_penetration_m");
  const auto inside = h5::read_vector<double>(file, "/frames/inside_fraction");
  const auto speed = h5::read_vector<double>(file, "/frames/max_speed_m_s");
  run.frames = static_cast<int64_t>(kinetic.size());
  for (float value : guides.guide_points_m) run.finite = run.finite && std::isfinite(value);
  std::vector<double> total(kinetic.size());
  for (size_t f = 0; f < total.size(); ++f) {
    total[f] = kinetic[f] + elastic[f] + gravity[f];
    run.finite = run.finite && std::isfinite(total[f]);
  }
  run.max_stretch = largest(stretch);
  run.max_penetration_m = largest(depth);
  run.max_inside = largest(inside);
  run.max_speed_m_s = largest(speed);
  if (!total.empty()) {
    run.first_total_j = total.front();
    run.last_total_j = total.back();
    run.max_total_j = largest(total);
  }
  const size_t n = total.size(), third = std::max<size_t>(1, n / 3);
  run.middle_kinetic_j = n > third ? largest_in(kinetic, third, 2 * third) : largest(kinetic);
  run.last_kinetic_j = n > 2 * third ? largest_in(kinetic, 2 * third, n) : run.middle_kinetic_j;
  run.growth = run.middle_kinetic_j > 0 ? run.last_kinetic_j / run.middle_kinetic_j
               : run.last_kinetic_j == 0 ? 0.0
                                         : std::numeric_limits<double>::infinity();

  // The simulated hair's mass, from the run's parameters.
  const nlohmann::json parameters = nlohmann::json::parse(read_provenance(file).parameters);
  auto number = [&](const char* name) {
    if (!parameters.contains(name) || !parameters[name].is_number())
      throw Error::bad_input(file.name(), std::string("no parameter ") + name +
                                                       " in the provenance (an earlier build's file?)");
    return parameters[name].get<double>();
  };
  const double fibre_mass_per_length = number("hair_density_kg_m3") * std::numbers::pi *
                                       std::pow(number("hair_radius_m"), 2);
  const auto mass_scale = h5::read_vector<double>(file, "/guides/mass_scale");
  double length = 0;
  const StrandSet& rest = guides.rest;
  for (int64_t g = 0; g < rest.strand_count(); ++g)
    for (int64_t row = rest.offsets[static_cast<size_t>(g)];
         row + 1 < rest.offsets[static_cast<size_t>(g) + 1]; ++row)
      length += mass_scale[static_cast<size_t>(g)] *
                (point_of(rest.points, row + 1) - point_of(rest.points, row)).norm();
  const double mass = length * number("fibres_per_guide") * fibre_mass_per_length;
  const double per_kg = std::pow(2 * std::numbers::pi * number("stretch_frequency_hz"), 2) *
                        number("stiffness_scale");
  run.deformation_m = mass > 0 ? std::sqrt(2 * std::max(0.0, largest(elastic)) / (per_kg * mass)) : 0.0;

  if (!run.finite)
    run.verdict = "non-finite";
  else if (run.max_stretch > stretch_bound)
    run.verdict = "stretch";
  else if (run.max_inside > inside_bound)
    run.verdict = "inside";
  else if (run.deformation_m > 0.05 * run.head_height_m)
    run.verdict = "deformation";
  else if (run.growth > 2 && run.last_kinetic_j > 1e-6)
    run.verdict = "energy-growth";
  else
    run.verdict = "stable";
  return run;
}

}  // namespace hair
