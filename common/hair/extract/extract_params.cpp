#include "hair/extract/extract_params.h"

namespace hair {
namespace {

/// How the meshes are read and their triangles paired into quads, how a region's rails are
/// chosen (chain length, the painted flow), which patches are traced along their paint,
/// and the alpha fade that tells root from tip.
void declare_reading_and_paint_params(ParamSet& params, ExtractStageParams& values) {
  ExtractParams& p = values.extract;
  params.add("unit_scale", p.unit_scale,
             "metres per unit of the source meshes (MakeHuman: decimetres, 0.1)",
             ParamRange::above(0));
  params.add("head_height_m", p.head_height_m,
             "head height H in metres; 0 measures it on the body (crown to the neck's waist)",
             ParamRange::at_least(0));
  params.add("mesh_reader", values.mesh_reader,
             "how meshes are read: auto (native OBJ reader keeping vertex order, assimp for "
             "other formats) or assimp (assimp for every format)",
             {"auto", "assimp"});
  params.add("max_mesh_triangles", values.max_mesh_triangles,
             "the most triangles a hair or body mesh may have (a polygon of n corners counts "
             "n - 2); a larger mesh is refused before it is processed (extract needs about 0.6 kB "
             "a triangle)",
             ParamRange::at_least(1));
  params.add("max_quad_corner_deviation_deg", p.max_quad_corner_deviation_deg,
             "worst corner angle off 90 degrees for two triangles to be paired into a quad",
             ParamRange::closed(0, 90));
  params.add("along_length_ratio", p.along_length_ratio,
             "ratio of mean chain lengths of a patch's two edge families above which the "
             "longer runs along the hair whatever the texture says",
             ParamRange::at_least(1));
  params.add("along_circling_min_share", p.along_circling_min_share,
             "hair does not go round the head: where the paint is not clear, before chain length, "
             "a family whose chains run round the axis from the head's centre through their "
             "region on at least this share of their length...",
             ParamRange::closed(0.5, 1));
  params.add("along_circling_min_sweep_deg", p.along_circling_min_sweep_deg,
             "...winding round it by at least this many degrees on average, is a shell's "
             "rings, and the other family (running round the axis on at most 1 - "
             "along_circling_min_share of its length) is the rails...",
             ParamRange::closed(0, 360));
  params.add("along_circling_other_min_length_h", p.along_circling_other_min_length_h,
             "...when its chains are at least this long (H): strands, not the width of a braid "
             "wound round the head",
             ParamRange::at_least(0));
  params.add("paint_guides_strands", p.paint_guides_strands,
             "the flow painted in the mesh's textures chooses rails, traces patches whose rails "
             "cross it and orients strands; false reads the mesh as if untextured (the flow is "
             "still measured and written)");
  params.add("along_paint_min_judged_share", p.along_paint_min_judged_share,
             "the painted flow chooses a region's rails when both its edge families lie this "
             "share of their length beside faces whose paint is clear...",
             ParamRange::closed(0, 1));
  params.add("along_paint_min_gap", p.along_paint_min_gap,
             "...and one family runs along the paint on this much more of its length than the "
             "other (shares, 0 to 1)",
             ParamRange::closed(0, 1));
  params.add("streamline_max_along_share", p.streamline_max_along_share,
             "a patch whose rails run along its clear paint on less than this share of their "
             "length is cut into strands traced along the paint instead",
             ParamRange::closed(0, 1));
  params.add("streamline_rails_min_along_share", p.streamline_rails_min_along_share,
             "a traced patch's streamlines take their sense from its rails only where those run "
             "along the paint on at least this share of their length (rails that mostly cross "
             "the hair say nothing of which way it runs)",
             ParamRange::closed(0, 1));
  params.add("streamline_max_head_distance_h", p.streamline_max_head_distance_h,
             "...when it lies on the head: the median distance of its vertices from the head "
             "at most this, in H (caps and wigs; hanging cards and braid pieces keep their "
             "rails)",
             ParamRange::at_least(0));
  params.add("streamline_tube_max_extent_ratio", p.streamline_tube_max_extent_ratio,
             "...a tube among them (quads closed on themselves across the rails: a shell, or "
             "a braid piece) only where its longest streamline is at most this many times "
             "the patch's extent (the strokes painted round a braid piece wind round it)...",
             ParamRange::at_least(0));
  params.add("streamline_tube_min_length_share", p.streamline_tube_min_length_share,
             "...and its streamlines' mean length at least this share of its rails' (a "
             "braid's lobes turn the strokes within a few faces)",
             ParamRange::at_least(0));
  params.add("alpha_fade_min_fall", p.alpha_fade_min_fall,
             "mean fall of the painted alpha along a region's rails (0 to 1 across a face) "
             "from which the fade tells root from tip",
             ParamRange::above(0));
  params.add("alpha_fade_min_rail_fall", p.alpha_fade_min_rail_fall,
             "...or mean fall along a whole rail, end to end (0 to 1), from which it does too "
             "(rails of many small faces fade by little per face)",
             ParamRange::above(0));
}

/// The rails kept, the cues that decide their direction, continuation and the parting of
/// draped and folded rails.
void declare_orientation_params(ParamSet& params, ExtractParams& p) {
  params.add("min_rail_length_share", p.min_rail_length_share,
             "along-chains shorter than this share of their region's longest are dropped "
             "as fragments",
             ParamRange::closed(0, 1));
  params.add("ordered_rail_fraction", p.ordered_rail_fraction,
             "a rail votes on vertex order when this share of its steps go the same way",
             ParamRange::closed(0.5, 1));
  params.add("vertex_order_min_vote", p.vertex_order_min_vote,
             "agreement of a patch's ordered rails (|grow - fall| / total) for vertex order "
             "to decide",
             ParamRange::closed(0, 1));
  params.add("scalp_distance_min_slope", p.scalp_distance_min_slope,
             "change of distance to the head per unit of rail length for the head distance "
             "to decide",
             ParamRange::above(0));
  params.add("scalp_distance_lean_slope", p.scalp_distance_lean_slope,
             "...and for it to lean: leaning one way, with a decisive height slope "
             "(height_min_slope) the same way, it overrules vertex order",
             ParamRange::at_least(0));
  params.add("height_min_slope", p.height_min_slope,
             "height change per unit of rail length that settles vertex order against head "
             "distance when they disagree (the higher end is the root)...",
             ParamRange::closed(0, 1));
  params.add("height_min_head_distance_h", p.height_min_head_distance_h,
             "...for regions whose rail ends all lie at least this far from the head, in H",
             ParamRange::at_least(0));
  params.add("continuation_radius_h", p.continuation_radius_h,
             "distance, in H, within which another patch's strand continues a rail",
             ParamRange::above(0));
  params.add("uv_min_growth", p.uv_min_growth,
             "growth of texture v along the rails for the texture to decide",
             ParamRange::closed(0, 1));
  params.add("convention_min_agreement", p.convention_min_agreement,
             "share of a mesh's clear patches that must agree on a texture convention",
             ParamRange::closed(0.5, 1));
  params.add("parting_min_side_share", p.parting_min_side_share,
             "a rail is parted at its highest or lowest inner point when each side is at least "
             "this share of it...",
             ParamRange::closed(0, 0.5));
  params.add("parting_min_side_drop", p.parting_min_side_drop,
             "...each side falls away from that point by this share of its length...", ParamRange::closed(0, 1));
  params.add("parting_min_end_distance_h", p.parting_min_end_distance_h,
             "...and the tips (draped ends, a fold) hang off the head by this distance, in H", ParamRange::at_least(0));
}

/// The scalp, and how the painted flow is read off the mesh's textures.
void declare_scalp_and_flow_params(ParamSet& params, ExtractParams& p) {
  params.add("scalp_distance_h", p.scalp_distance_h,
             "body triangles above the neck within this distance of the hair mesh, in H, "
             "form the scalp",
             ParamRange::above(0));
  params.add("scalp_under_hair_h", p.scalp_under_hair_h,
             "...and so do those not facing forward under hair that stands off the head up to "
             "this far along their normal, in H (0: only the distance decides)",
             ParamRange::closed(0, 1));
  params.add("scalp_under_hair_min_height_h", p.scalp_under_hair_min_height_h,
             "...on triangles at least this far above the neck, in H (lower, hair standing "
             "off the head hangs past it: a tail, long hair)",
             ParamRange::closed(0, 1));
  params.add(
      "scalp_face_below_top_h", p.scalp_face_below_top_h,
      "...but never the face: triangles lower than this under the crown, in H, where the "
      "body round them faces forward (+Z); 1 or more: no face, the neck lies 1 H under the crown",
      ParamRange::closed(0, 2));
  params.add("flow_min_alpha", p.painted_flow.min_alpha,
             "painted flow: texels with at least this alpha are painted hair",
             ParamRange::closed(0, 1));
  params.add("flow_window_px", p.painted_flow.window_px,
             "painted flow: Gaussian window of the texture's structure tensor, texels",
             ParamRange::above(0));
  params.add("flow_stroke_scale_px", p.painted_flow.stroke_scale_px,
             "painted flow: detail finer than this Gaussian sigma, texels, counts as strokes "
             "(broader shading and highlight bands are left out)",
             ParamRange::above(0));
  params.add("flow_samples_per_side", p.painted_flow.samples_per_side,
             "painted flow: texture samples per side of each triangle of a face",
             ParamRange::closed(1, 16));
  params.add("flow_min_painted_share", p.painted_flow.min_painted_share,
             "painted flow: share of a face's samples that must be painted for it to have a flow",
             ParamRange::closed(0, 1));
}

}  // namespace

void declare_extract_params(ParamSet& params, ExtractStageParams& values) {
  declare_reading_and_paint_params(params, values);
  declare_orientation_params(params, values.extract);
  declare_scalp_and_flow_params(params, values.extract);
}

void check_extract_params(const ExtractParams& params) {
  ExtractStageParams stage;
  stage.extract = params;
  check_params(stage, declare_extract_params);
}

}  // namespace hair
