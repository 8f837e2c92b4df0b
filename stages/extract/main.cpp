// extract: the input strands of a hair mesh (paper section 4.1), its strand groups
// (one per patch), the body with its head height H and scalp -> extract.h5.
#include <spdlog/spdlog.h>

#include "hair/core/atomic_file.h"
#include "hair/core/stage_app.h"
#include "hair/extract/extract.h"
#include "hair/extract/extract_io.h"
#include "hair/extract/extract_params.h"
#include "hair/h5/provenance.h"
#include "hair/h5/schema_validation.h"
#include "hair/mesh/mesh_io.h"

int main(int argc, char** argv) {
  hair::StageApp app("extract",
                     "Reads the input strands of a hair mesh, one strand group per patch, "
                     "oriented root to tip, and measures the body's head and scalp.");
  std::string hair_path, body_path;
  app.cli()
      .add_option("HAIR_MESH", hair_path, "hair mesh: OBJ, glTF/GLB, FBX, ... (what assimp reads)")
      ->required();
  app.cli().add_option("--body", body_path, "body mesh the hair is fitted on")->required();
  hair::ExtractStageParams params;
  hair::declare_extract_params(app.params(), params);

  return app.run(argc, argv, [&] {
    hair::PolyMesh hair_mesh = hair::read_mesh(hair_path, params.reader(), params.mesh_limit());
    hair::PolyMesh body_mesh = hair::read_mesh(body_path, params.reader(), params.mesh_limit());
    const hair::PaintedTextures textures =
        hair::load_painted_textures(hair_mesh.materials, params.extract.painted_flow, hair_path);
    hair::ExtractResult result = hair::extract_strands(
        std::move(hair_mesh), std::move(body_mesh), params.extract, hair_path, body_path, textures);
    const hair::ExtractStats& stats = result.stats;
    const auto scalp_triangles =
        std::count(result.scalp_triangle.begin(), result.scalp_triangle.end(), 1);
    spdlog::info("{}: {} groups, {} strands, {} points; H = {:.3f} m; {} scalp triangles",
                 hair_path, result.group_count(), result.strands.strand_count(),
                 result.strands.point_count(), result.head.head_height, scalp_triangles);
    spdlog::info(
        "{}: orientation rules: vertex_order {}, scalp_distance {}, continuation {}, uv {}, "
        "height {}, parting {}, alpha_fade {} ({} regions' vertex ids and {} continuations "
        "overruled by their paint; {} regions' vertex ids or head distance overruled by the hair "
        "running on through their ends; {} regions' vertex ids overruled by their height and "
        "texture; {} regions' head distance by their ids and texture)",
        hair_path, stats.groups_by_rule[0], stats.groups_by_rule[1], stats.groups_by_rule[2],
        stats.groups_by_rule[3], stats.groups_by_rule[4], stats.groups_by_rule[5],
        stats.groups_by_rule[6], stats.paint_overruled_ids, stats.paint_overruled_continuation,
        stats.continuation_overruled_ids, stats.height_and_texture_overruled_ids,
        stats.ids_and_texture_overruled_head_distance);
    spdlog::info(
        "{}: rails chosen by chain length in {} regions, texture axis {}, painted flow {} "
        "({} of them across the longer chains), across rings round the head {}; {} patches "
        "traced along the paint ({} of them tubes; {} tubes on the head kept on their rails, "
        "the strokes painted round them)",
        hair_path, stats.regions_by_along_rule[0], stats.regions_by_along_rule[1],
        stats.regions_by_along_rule[2], stats.regions_turned_by_paint,
        stats.regions_by_along_rule[3], stats.patches_traced_along_paint,
        stats.tubes_traced_along_paint, stats.tubes_kept_on_rails);
    if (const int64_t painted = result.painted_flow.painted_face_count(); painted > 0) {
      int64_t segments = 0;
      const double along = hair::painted_flow_agreement(
          result.hair_mesh, result.painted_flow, result.strands, hair::kClearFlowCoherence,
          hair::kFlowAgreementAngleDeg, 0.1 * result.head.head_height, segments);
      spdlog::info(
          "{}: painted flow on {} of {} faces; {:.1f}% of {} input strand segments run along "
          "it (within {} degrees, where it is clear)",
          hair_path, painted, result.hair_mesh.face_count(), 100 * along, segments,
          hair::kFlowAgreementAngleDeg);
    }
    if (scalp_triangles == 0)
      spdlog::warn(
          "{}: the hair mesh does not reach the head of {}: no scalp (wrong body, or "
          "unit_scale?)",
          hair_path, body_path);
    spdlog::debug(
        "{} degenerate faces removed, {} triangles paired, {} left, {} rails parted, "
        "{} fragments dropped, {} strands turned to run with their group",
        stats.degenerate_faces_removed, stats.triangles_paired, stats.triangles_left,
        stats.rails_parted, stats.fragments_dropped, stats.strands_turned_to_their_group);
    if (result.head.head_height < 0.1 || result.head.head_height > 0.5)
      spdlog::warn("head height {:.3f} m is not a human head's: is unit_scale right?",
                   result.head.head_height);

    hair::AtomicFile output(app.output_path());
    hair::h5::File file = hair::h5::File::create(output.temporary_path(), app.output_path());
    hair::write_extract_file(file, result, params.extract);
    hair::write_provenance(
        file, hair::stage_provenance("extract", app.params().effective_json().dump(),
                                     {{"hair_mesh", hair_path}, {"body_mesh", body_path}},
                                     app.elapsed_s(), app.reproducible()));
    hair::h5::require_valid_output(file, hair::kExtractSchema);
    file.close();
    output.commit();
  });
}
