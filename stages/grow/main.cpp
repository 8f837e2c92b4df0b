// grow: strands grown from the scalp through the clusters of clusters.h5 (paper
// section 4.4, Figure 7), from extract.h5, types.h5 and clusters.h5 -> strands.h5.
#include <spdlog/spdlog.h>

#include "hair/core/atomic_file.h"
#include "hair/core/stage_app.h"
#include "hair/grow/grow_io.h"
#include "hair/h5/provenance.h"
#include "hair/h5/schema_validation.h"

int main(int argc, char** argv) {
  hair::StageApp app("grow",
                     "Grows strands from roots sampled on the scalp: along one orientation field "
                     "per cluster, then along the input strands of the groups they reach.");
  std::string extract_path, types_path, clusters_path;
  app.cli().add_option("EXTRACT_H5", extract_path, "extract.h5 from the extract stage")->required();
  app.cli().add_option("TYPES_H5", types_path, "types.h5 from the typeify stage")->required();
  app.cli()
      .add_option("CLUSTERS_H5", clusters_path, "clusters.h5 from the cluster-all stage")
      ->required();
  hair::GrowParams params;
  hair::ParamSet& p = app.params();
  p.add("strand_count", params.strand_count, "strands to grow: roots sampled on the scalp",
        hair::ParamRange::closed(1, 1'000'000));
  p.add("seed", params.seed, "seed of the root sampling", hair::ParamRange::at_least(0));
  p.add("scalp_cover_h", params.scalp_cover_h,
        "scalp triangles within this distance of a root-type input strand carry roots, in H",
        hair::ParamRange::above(0));
  p.add("min_typed_root_scalp_share", params.min_typed_root_scalp_share,
        "where root-type strands cover less than this share of the scalp that strands of any "
        "type cover, roots take any strand (the types do not say where the roots are); 0 "
        "turns this off",
        hair::ParamRange::closed(0, 1));
  p.add("standing_cover_h", params.standing_cover_h,
        "...but where that strand stands off the scalp (over 45 degrees), only within this "
        "distance of it along the scalp (a spike grows from its base), in H",
        hair::ParamRange::above(0));
  p.add("step_h", params.step_h, "growing step, in H", hair::ParamRange::closed(0.001, 0.1));
  p.add("field_voxel_h", params.field_voxel_h, "orientation-field voxel size, in H",
        hair::ParamRange::closed(0.002, 0.2));
  p.add("field_band_h", params.field_band_h,
        "the field reaches this far from its cluster's input strands, in H",
        hair::ParamRange::above(0));
  p.add("field_paint_seeds", params.field_paint_seeds,
        "faces whose painted strokes are clear seed their cluster's orientation field along "
        "them, signed by their group's input strands (false: the input strands alone)");
  p.add("field_shell_seeds", params.field_shell_seeds,
        "where the hair lies off the head beyond the field's band, its field is seeded under it "
        "down to the body and the scalp under it carries roots (false: only near the strands)");
  p.add("shell_max_height_h", params.shell_max_height_h,
        "...under strand points at most this high above the body, in H",
        hair::ParamRange::closed(0, 1));
  p.add("length_factor", params.length_factor,
        "the field phase ends at this many times the remaining length of the input strand "
        "nearest the root",
        hair::ParamRange::above(0));
  p.add("max_turn_deg", params.max_turn_deg,
        "no step turns a strand by more than this from its last: along the field the cards "
        "take over there, along a card or a bridge the strand ends (180: never)",
        hair::ParamRange::closed(0, 180));
  p.add("continue_radius_h", params.continue_radius_h,
        "at an input strand's end, the next one must start within this distance, in H",
        hair::ParamRange::above(0));
  p.add("continue_max_angle_deg", params.continue_max_angle_deg,
        "...and leave within this angle of the current direction",
        hair::ParamRange::closed(0, 180));
  p.add("continued_root_radius_h", params.continued_root_radius_h,
        "a root-type group that continues another (its cluster does not start at the root) is "
        "entered from this far, in H",
        hair::ParamRange::above(0));
  p.add("continued_root_max_angle_deg", params.continued_root_max_angle_deg,
        "...turning by up to this angle (hair turns where a band gathers it)",
        hair::ParamRange::closed(0, 180));
  p.add("continued_tip_off_scalp_h", params.continued_tip_off_scalp_h,
        "...and so is any strand of such a cluster whose tip hangs farther than this from the "
        "scalp (a tail or braid after its band), by a strand leaving its root's cluster, in H",
        hair::ParamRange::above(0));
  p.add("join_continued_flow", params.join_continued_flow,
        "where the hair continues into a cluster that does not start at the root (a tail after "
        "its band), a strand whose card ends before it joins the nearest card running its way "
        "into it (false: it ends with its card)");
  p.add("gather_along_field_h", params.gather_along_field_h,
        "a strand of a cap gathered into a band whose card ends on the cap goes on along its "
        "cluster's field by at most this far, until a tail or braid after the band is within "
        "reach, in H (0: it ends with its card)",
        hair::ParamRange::at_least(0));
  p.add("follow_radius_h", params.follow_radius_h,
        "a strand following an input strand is lost farther than this from its group, in H",
        hair::ParamRange::above(0));
  p.add("follow_keep_h", params.follow_keep_h,
        "a strand following a group drifts back towards its nearest rail beyond this, in H",
        hair::ParamRange::at_least(0));
  p.add("follow_pull", params.follow_pull, "...by at most this share of a step per step (0: never)",
        hair::ParamRange::closed(0, 1));
  p.add("bridge_max_angle_deg", params.bridge_max_angle_deg,
        "a bridge into the next input strand goes to its first point ahead within this angle "
        "of the strand's direction, not behind or beside it (0: always to its start)",
        hair::ParamRange::closed(0, 90));
  p.add("bridge_paint_max_angle_deg", params.bridge_paint_max_angle_deg,
        "...nor one whose way across the gap runs more than this angle off the clear paint of "
        "the hair face nearest its middle (0: no such check)",
        hair::ParamRange::closed(0, 90));
  p.add("follow_card_keep_h", params.follow_card_keep_h,
        "...and towards the surface of its own card (the group's faces) beyond this, in H "
        "(0: no such hold)",
        hair::ParamRange::at_least(0));
  p.add("follow_card_pull", params.follow_card_pull,
        "...by at most this share of a step per step (0: never)", hair::ParamRange::closed(0, 1));
  p.add("body_clearance_h", params.body_clearance_h,
        "grown points are kept this far outside the body, in H", hair::ParamRange::at_least(0));
  p.add("body_voxel_h", params.body_voxel_h, "spacing of the body's signed distance field, in H",
        hair::ParamRange::closed(0.001, 0.1));
  p.add("layer_radius_h", params.layer_radius_h,
        "a root's reference strand (its length, and the height its strand keeps above the "
        "body) is drawn among the strands within this distance of it, in H; 0: the nearest",
        hair::ParamRange::at_least(0));
  p.add("layer_pull", params.layer_pull,
        "along the field a strand moves towards its reference strand's height by at most this "
        "share of a step",
        hair::ParamRange::closed(0, 1));
  p.add("layer_climb_h", params.layer_climb_h,
        "a strand rooted under its layer climbs to it at an even slope within this length of "
        "its root, in H; 0: by at most layer_pull of a step per step",
        hair::ParamRange::at_least(0));
  p.add("root_heading_paint_h", params.root_heading_paint_h,
        "over the first this much of its length (H), a strand heads over the scalp along the "
        "clear paint of the hair face nearest it, where that runs within 60 degrees of its "
        "field (0: the field alone)",
        hair::ParamRange::at_least(0));
  p.add("max_length_h", params.max_length_h, "no strand grows longer than this, in H",
        hair::ParamRange::above(0));
  p.add("max_points_per_strand", params.max_points_per_strand,
        "growing stops at this many points per strand", hair::ParamRange::closed(2, 100'000));

  return app.run(argc, argv, [&] {
    hair::GrowInput input = hair::read_grow_input(hair::h5::File::open_read_only(extract_path),
                                                  hair::h5::File::open_read_only(types_path),
                                                  hair::h5::File::open_read_only(clusters_path));
    hair::GrowResult result = hair::grow_strands(input, params);
    spdlog::info(
        "{}: {} strands, {} points, {} pushed out of the body, {} continuations ({} "
        "into another cluster); {} strands joined the cards feeding a continued cluster; {} "
        "ended where the card they followed dives into the body, {} where the next step would "
        "fold them back; roots from {} (root-type "
        "strands cover {:.0f}% of the scalp under the hair)",
        extract_path, result.strands.strand_count(), result.strands.point_count(),
        result.points_pushed_out,
        result.continuations_same_cluster + result.continuations_other_cluster,
        result.continuations_other_cluster, result.strands_joining_continued_flow,
        result.strands_ended_at_body, result.strands_ended_at_fold,
        result.roots_from_any_type ? "strands of any type" : "root-type strands",
        100 * result.typed_root_scalp_share);

    hair::AtomicFile output(app.output_path());
    hair::h5::File file = hair::h5::File::create(output.temporary_path(), app.output_path());
    hair::write_strands_file(file, result, params, input.head_height_m);
    hair::write_provenance(
        file, hair::stage_provenance(
                  "grow", app.params().effective_json().dump(),
                  {{"extract", extract_path}, {"types", types_path}, {"clusters", clusters_path}},
                  app.elapsed_s(), app.reproducible()));
    hair::h5::require_valid_output(file, hair::kStrandsSchema);
    file.close();
    output.commit();
  });
}
