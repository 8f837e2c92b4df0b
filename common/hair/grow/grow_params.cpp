#include "hair/grow/grow_params.h"

namespace hair {
namespace {

/// The roots and the field phase.
void declare_root_and_field_params(ParamSet& p, GrowParams& params) {
  p.add("strand_count", params.strand_count, "strands to grow: roots sampled on the scalp",
        ParamRange::closed(1, 1'000'000));
  p.add("seed", params.seed, "seed of the root sampling", ParamRange::at_least(0));
  p.add("scalp_cover_h", params.scalp_cover_h,
        "scalp triangles within this distance of a root-type input strand carry roots, in H",
        ParamRange::above(0));
  p.add("min_typed_root_scalp_share", params.min_typed_root_scalp_share,
        "where root-type strands cover less than this share of the scalp that strands of any "
        "type cover, roots take any strand (the types do not say where the roots are); 0 "
        "turns this off",
        ParamRange::closed(0, 1));
  p.add("standing_cover_h", params.standing_cover_h,
        "...but where that strand stands off the scalp (over 45 degrees), only within this "
        "distance of it along the scalp (a spike grows from its base), in H",
        ParamRange::above(0));
  p.add("step_h", params.step_h, "growing step, in H", ParamRange::closed(0.001, 0.1));
  p.add("field_voxel_h", params.field_voxel_h, "orientation-field voxel size, in H",
        ParamRange::closed(0.002, 0.2));
  p.add("field_band_h", params.field_band_h,
        "the field reaches this far from its cluster's input strands, in H",
        ParamRange::above(0));
  p.add("field_paint_seeds", params.field_paint_seeds,
        "faces whose painted strokes are clear seed their cluster's orientation field along "
        "them, signed by their group's input strands (false: the input strands alone)");
  p.add("field_shell_seeds", params.field_shell_seeds,
        "where the hair lies off the head beyond the field's band, its field is seeded under it "
        "down to the body and the scalp under it carries roots (false: only near the strands)");
  p.add("shell_max_height_h", params.shell_max_height_h,
        "...under strand points at most this high above the body, in H",
        ParamRange::closed(0, 1));
  p.add("field_air_stop_h", params.field_air_stop_h,
        "grown hair lies where the mesh has hair: a strand whose field phase runs this far "
        "through air is taken back to where it left the hair and the input strands take over, "
        "in H (0: never)",
        ParamRange::at_least(0));
  p.add("air_distance_h", params.air_distance_h,
        "...air: farther than this from every hair triangle, in H...", ParamRange::above(0));
  p.add("air_covered_reach_h", params.air_covered_reach_h,
        "...and no hair over it within this distance straight out from the body, in H",
        ParamRange::at_least(0));
  p.add("length_factor", params.length_factor,
        "the field phase ends at this many times the remaining length of the input strand "
        "nearest the root",
        ParamRange::above(0));
  p.add("max_turn_deg", params.max_turn_deg,
        "no step turns a strand by more than this from its last: along the field the cards "
        "take over there, along a card or a bridge the strand ends (180: never)",
        ParamRange::closed(0, 180));
}

/// The input strands followed after the field, the bridges between them, the body, the
/// layers and the limits.
void declare_following_params(ParamSet& p, GrowParams& params) {
  p.add("continue_radius_h", params.continue_radius_h,
        "at an input strand's end, the next one must start within this distance, in H",
        ParamRange::above(0));
  p.add("continue_max_angle_deg", params.continue_max_angle_deg,
        "...and leave within this angle of the current direction",
        ParamRange::closed(0, 180));
  p.add("continued_root_radius_h", params.continued_root_radius_h,
        "a root-type group that continues another (its cluster does not start at the root) is "
        "entered from this far, in H",
        ParamRange::above(0));
  p.add("continued_root_max_angle_deg", params.continued_root_max_angle_deg,
        "...turning by up to this angle (hair turns where a band gathers it)",
        ParamRange::closed(0, 180));
  p.add("continued_tip_off_scalp_h", params.continued_tip_off_scalp_h,
        "...and so is any strand of such a cluster whose tip hangs farther than this from the "
        "scalp (a tail or braid after its band), by a strand leaving its root's cluster, in H",
        ParamRange::above(0));
  p.add("join_continued_flow", params.join_continued_flow,
        "where the hair continues into a cluster that does not start at the root (a tail after "
        "its band), a strand whose card ends before it joins the nearest card running its way "
        "into it (false: it ends with its card)");
  p.add("gather_along_field_h", params.gather_along_field_h,
        "a strand of a cap gathered into a band whose card ends on the cap goes on along its "
        "cluster's field by at most this far, until a tail or braid after the band is within "
        "reach, in H (0: it ends with its card)",
        ParamRange::at_least(0));
  p.add("follow_radius_h", params.follow_radius_h,
        "a strand following an input strand is lost farther than this from its group, in H",
        ParamRange::above(0));
  p.add("follow_keep_h", params.follow_keep_h,
        "a strand following a group drifts back towards its nearest rail beyond this, in H",
        ParamRange::at_least(0));
  p.add("follow_pull", params.follow_pull, "...by at most this share of a step per step (0: never)",
        ParamRange::closed(0, 1));
  p.add("bridge_max_angle_deg", params.bridge_max_angle_deg,
        "a bridge into the next input strand goes to its first point ahead within this angle "
        "of the strand's direction, not behind or beside it (0: always to its start)",
        ParamRange::closed(0, 90));
  p.add("bridge_paint_max_angle_deg", params.bridge_paint_max_angle_deg,
        "...nor one whose way across the gap runs more than this angle off the clear paint of "
        "the hair face nearest its middle (0: no such check)",
        ParamRange::closed(0, 90));
  p.add("follow_card_keep_h", params.follow_card_keep_h,
        "...and towards the surface of its own card (the group's faces) beyond this, in H "
        "(0: no such hold)",
        ParamRange::at_least(0));
  p.add("follow_card_pull", params.follow_card_pull,
        "...by at most this share of a step per step (0: never)", ParamRange::closed(0, 1));
  p.add("body_clearance_h", params.body_clearance_h,
        "grown points are kept this far outside the body, in H", ParamRange::at_least(0));
  p.add("body_voxel_h", params.body_voxel_h, "spacing of the body's signed distance field, in H",
        ParamRange::closed(0.001, 0.1));
  p.add("layer_radius_h", params.layer_radius_h,
        "a root's reference strand (its length, and the height its strand keeps above the "
        "body) is drawn among the strands within this distance of it, in H; 0: the nearest",
        ParamRange::at_least(0));
  p.add("layer_pull", params.layer_pull,
        "along the field a strand moves towards its reference strand's height by at most this "
        "share of a step",
        ParamRange::closed(0, 1));
  p.add("layer_climb_h", params.layer_climb_h,
        "a strand rooted under its layer climbs to it at an even slope within this length of "
        "its root, in H; 0: by at most layer_pull of a step per step",
        ParamRange::at_least(0));
  p.add("root_heading_paint_h", params.root_heading_paint_h,
        "over the first this much of its length (H), a strand heads over the scalp along the "
        "clear paint of the hair face nearest it, where that runs within 60 degrees of its "
        "field (0: the field alone)",
        ParamRange::at_least(0));
  p.add("max_length_h", params.max_length_h, "no strand grows longer than this, in H",
        ParamRange::above(0));
  p.add("max_points_per_strand", params.max_points_per_strand,
        "growing stops at this many points per strand", ParamRange::closed(2, 100'000));
}

}  // namespace

void declare_grow_params(ParamSet& p, GrowParams& params) {
  declare_root_and_field_params(p, params);
  declare_following_params(p, params);
}

void check_grow_params(const GrowParams& params) { check_params(params, declare_grow_params); }

}  // namespace hair
