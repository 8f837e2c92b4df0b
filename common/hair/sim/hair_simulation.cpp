#include "hair/sim/hair_simulation.h"

#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <optional>
#include <string>

#include "hair/core/error.h"
#include "hair/sim/simulation_loop.h"
#include "hair/sim/simulation_setup.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;

void check_params(const SimulationParams& p) {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw Error::usage(what);
  };
  require(p.fps > 0 && std::isfinite(p.fps), "fps must be positive");
  require(p.duration_s >= 0 && std::isfinite(p.duration_s), "duration_s must be 0 or positive");
  require(p.substeps >= 1, "substeps must be at least 1");
  require(p.guide_count >= 0, "guide_count must be 0 or more");
  require(p.segment_length_h > 0, "segment_length_h must be positive");
  require(p.short_segment_factor > 0 && p.wisp_segment_factor > 0,
          "segment factors must be positive");
  const HairFibre& fibre = p.material.fibre;
  require(fibre.youngs_modulus_pa > 0 && fibre.shear_modulus_pa > 0,
          "youngs_modulus_pa and shear_modulus_pa must be positive");
  require(fibre.radius_m > 0 && fibre.density_kg_m3 > 0,
          "hair_radius_m and hair_density_kg_m3 must be positive");
  require(p.material.fibres_per_strand >= 1, "fibres_per_guide must be at least 1");
  require(p.material.lock_cohesion >= 0 && p.material.lock_cohesion <= 1,
          "lock_cohesion must be within 0 and 1");
  require(p.material.stiffness_scale > 0, "stiffness_scale must be positive");
  require(p.material.stretch_frequency_hz > 0, "stretch_frequency_hz must be positive");
  require(p.body_voxel_h > 0 && p.body_clearance_h >= 0, "body field spacing must be positive");
  require(p.density_cell_h > 0, "density_cell_h must be positive");
  require(p.bundle_cohesion_per_s2 >= 0, "bundle_cohesion_per_s2 must be 0 or positive");
  require(p.bundle_damping_ratio >= 0, "bundle_damping_ratio must be 0 or positive");
  require(p.repulsion_interval_frames >= 1, "repulsion_interval_frames must be at least 1");
}

}  // namespace

Vec3 head_pivot(const Points3f& body_vertices, double head_height_m) {
  if (body_vertices.rows() == 0) return Vec3::Zero();
  double top = body_vertices.col(1).maxCoeff();
  Vec3 sum = Vec3::Zero();
  int64_t count = 0;
  for (Eigen::Index v = 0; v < body_vertices.rows(); ++v) {
    if (body_vertices(v, 1) < top - head_height_m) continue;
    sum += body_vertices.row(v).cast<double>().transpose();
    ++count;
  }
  Vec3 centre = sum / static_cast<double>(count);
  return Vec3(centre.x(), top - head_height_m, centre.z());
}

SimulationResult simulate_hair(const SimulationScene& scene, const HeadMotion& motion,
                               const SimulationParams& params) {
  check_params(params);
  check_strand_set(scene.strands, 1);  // names a strand with a non-finite point
  auto setup_start = std::chrono::steady_clock::now();
  SimulationResult result;
  result.fps = params.fps;

  // Setup: the styles, the body, the plan of guides and wisps, the simulated strands.
  result.simulated_style = styles_to_simulate(scene.cluster_style, params.by_style);
  const std::optional<BodySdf> body =
      body_field_over_hair(scene, result.simulated_style, params);
  const WispCentres centres = plan_simulation(scene, params, body, result);
  const StrandStiffness stiffness(params.material);
  std::vector<RunningStrand> running = build_strand_guides(scene, params, stiffness, body, result);
  build_wisps(scene, stiffness, centres, result, running);
  if (params.sag_free) make_rests_sag_free(params, motion, scene.source, running);

  // Frame 0, then the frames.
  SimulationLoop loop(scene, motion, params, body, std::move(running), result);
  loop.start();
  result.setup_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - setup_start).count();
  int64_t ghosts = 0;
  for (const SimulatedGuide& guide : result.guides) ghosts += guide.ghost_count;
  spdlog::info(
      "{}: {} guides ({} ghost particles), {} wisps, {} frames of {} steps of {:.2f} ms",
      scene.source, result.guides.size(), ghosts, result.wisp_guide.size(), result.frame_count,
      params.substeps, 1e3 * (1.0 / (params.fps * params.substeps)));
  auto simulation_start = std::chrono::steady_clock::now();
  loop.run();
  result.simulation_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - simulation_start).count();
  return result;
}

}  // namespace hair
