#include "hair/sim/hair_simulation.h"

#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <optional>
#include <string>

#include "hair/core/error.h"
#include "hair/sim/simulation_loop.h"
#include "hair/sim/simulation_params.h"
#include "hair/sim/simulation_setup.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;

/// Holds `p` to the ranges the simulate stage declares (declare_simulation_params()).
void check_declared_params(const SimulationParams& p) {
  SimulateStageParams stage;
  stage.simulation = p;
  check_params(stage, declare_simulation_params);
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
  check_declared_params(params);
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
