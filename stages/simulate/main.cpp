// simulate: the guide strands of every simulated cluster per frame under a head motion,
// by style (paper section 5.2), from extract.h5, strands.h5 and styles.h5 -> guides.h5.
#include <spdlog/spdlog.h>

#include "hair/core/atomic_file.h"
#include "hair/core/stage_app.h"
#include "hair/h5/provenance.h"
#include "hair/h5/schema_validation.h"
#include "hair/sim/guides_io.h"
#include "hair/sim/hair_simulation.h"
#include "hair/sim/head_motion.h"
#include "hair/sim/simulation_params.h"

int main(int argc, char** argv) {
  hair::StageApp app("simulate",
                     "Simulates the grown strands by style under a head motion: fixed clusters "
                     "move with the head, normal and short ones by guide strands of the altitude "
                     "mass-spring model, braided ones by a wisp around a centre strand.");
  std::string extract_path, strands_path, styles_path, keyframes_path;
  app.cli().add_option("EXTRACT_H5", extract_path, "extract.h5 (the body)")->required();
  app.cli().add_option("STRANDS_H5", strands_path, "strands.h5 from the grow stage")->required();
  app.cli().add_option("STYLES_H5", styles_path, "styles.h5 from the classify stage")->required();
  app.cli().add_option("--keyframes", keyframes_path,
                       "head motion keyframes, CSV: time_s,yaw_deg,pitch_deg,roll_deg,"
                       "offset_x_m,offset_y_m,offset_z_m (replaces the motion parameter)");
  hair::SimulateStageParams params;
  hair::declare_simulation_params(app.params(), params);

  return app.run(argc, argv, [&] {
    hair::SimulationScene scene = hair::read_simulation_scene(
        hair::h5::File::open_read_only(extract_path), hair::h5::File::open_read_only(strands_path),
        hair::h5::File::open_read_only(styles_path));
    Eigen::Vector3d pivot = hair::head_pivot(scene.body_vertices, scene.head_height_m);
    hair::HeadMotion motion = keyframes_path.empty()
                                  ? hair::HeadMotion::preset(params.motion, pivot)
                                  : hair::HeadMotion::from_keyframes_csv(keyframes_path, pivot);
    hair::SimulationResult result = hair::simulate_hair(scene, motion, params.simulation);
    int integrated = 0;
    for (const hair::FrameStatistics& stats : result.statistics) integrated += stats.integrated;
    integrated -= 1;  // frame 0 is the rest state
    double ms_per_frame = integrated > 0 ? 1e3 * result.simulation_s / integrated : 0.0;
    double worst_stretch = 0, worst_penetration = 0;
    for (const hair::FrameStatistics& stats : result.statistics) {
      worst_stretch = std::max(worst_stretch, stats.max_stretch);
      worst_penetration = std::max(worst_penetration, stats.max_penetration_m);
    }
    spdlog::info(
        "{}: {} frames ({} integrated) of {} guides in {:.2f} s, {:.3f} ms per frame; "
        "{} fixed strands move with the head, {} braided ones follow wisps; largest "
        "stretch {:.4f}, deepest penetration {:.2f} mm",
        strands_path, result.frame_count, integrated, result.guides.size(), result.simulation_s,
        ms_per_frame, result.fixed_strands, result.braided_strands, worst_stretch,
        1e3 * worst_penetration);
    spdlog::info("{}: time by phase: {}", strands_path, result.profile.summary());

    hair::GuidesFileInfo info;
    info.head_height_m = scene.head_height_m;
    info.substeps = params.simulation.substeps;
    info.motion = motion.name();
    info.cluster_style = scene.cluster_style;
    if (!app.reproducible()) {
      info.guide_ms_per_frame = ms_per_frame;
      info.setup_s = result.setup_s;
    }
    std::vector<std::pair<std::string, std::filesystem::path>> inputs = {
        {"extract", extract_path}, {"strands", strands_path}, {"styles", styles_path}};
    if (!keyframes_path.empty()) inputs.emplace_back("keyframes", keyframes_path);
    hair::AtomicFile output(app.output_path());
    hair::h5::File file = hair::h5::File::create(output.temporary_path(), app.output_path());
    hair::write_guides_file(file, result, info);
    hair::write_provenance(
        file, hair::stage_provenance("simulate", app.params().effective_json().dump(), inputs,
                                     app.elapsed_s(), app.reproducible()));
    hair::h5::require_valid_output(file, hair::kGuidesSchema);
    file.close();
    output.commit();
  });
}
