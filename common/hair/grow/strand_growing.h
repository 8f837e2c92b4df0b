#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "hair/cluster/typeify.h"
#include "hair/core/strand_set.h"
#include "hair/geom/triangle_mesh_distance.h"

namespace hair {

/// How a segment of a grown strand was grown (paper section 4.4).
enum class GrowRule : int8_t {
  root = 0,          ///< the root point itself, on the scalp
  field = 1,         ///< along the orientation field of the root's cluster
  input_strand = 2,  ///< along the closest input strand of a middle or tip group (or any
                     ///< group, once the field is left)
  bridge = 3,        ///< across a gap, straight to the start of the next input strand
};
const char* grow_rule_name(GrowRule rule);

/// Parameters of grow_strands(); lengths are in head heights H unless they say _m.
struct GrowParams {
  int strand_count = 10000;  ///< roots sampled on the scalp
  int seed = 1;              ///< of the root sampling
  /// Scalp triangles (extract.h5 /body/scalp_triangle) whose centre lies within this
  /// distance of a point of a root-type input strand carry roots.
  double scalp_cover_h = 0.05;
  /// Where the scalp triangles that root-type strands cover (as above) are less than this
  /// share of the area that strands of any type cover, the types do not say where the
  /// roots are (hair of tiny cards typed middle but for a handful): roots then take any
  /// input strand, as when no group is root-type. 0 turns this off
  /// (docs/decisions/grow-typed-root-share.md).
  double min_typed_root_scalp_share = 0.1;
  /// ...but where that point's strand stands off the scalp (rises at more than 45 degrees
  /// to the triangle), only within this distance of it along the scalp: a card standing on
  /// the head (a spike, a mohawk) grows from its base, not from a disc around it.
  double standing_cover_h = 0.02;
  double step_h = 0.02;         ///< growing step (RK2 along the field, or along a strand)
  double field_voxel_h = 0.02;  ///< orientation-field grid spacing
  double field_band_h = 0.06;   ///< the field reaches this far from its cluster's strands
  /// The faces whose paint is clear (GrowInput::hair_triangle_flow) seed their cluster's
  /// field along their strokes, as the input strands do, each signed by its group's input
  /// strands (painted_field_seeds.h): between a cap's streamlines, around its crown whorl,
  /// the field follows the paint instead of an average of the lines on either side.
  bool field_paint_seeds = true;
  /// Where the hair lies off the head farther than the field's band (a bob's shell, a cap
  /// puffed out over the crown), its cluster's field is seeded under it too, level by level
  /// down to the body with the direction of the hair above (shell_field_seeds.h), and the
  /// scalp under it carries roots: the hair is rooted under the shell and rises to it,
  /// instead of growing only from where the mesh comes down to the head.
  bool field_shell_seeds = true;
  /// ...under the points of root-carrying strands at most this high above the body.
  double shell_max_height_h = 0.3;
  /// Grown hair lies where the mesh has hair: a strand whose field phase runs farther than
  /// this (H) through air (farther than `air_distance_h` from every hair triangle, and no
  /// hair straight out from the body over it within `air_covered_reach_h`: a card's edge,
  /// a shell's rim, the field running on past a card's tip) is taken back to where it left
  /// the hair, and the input strands take over, as where the field ends early. 0 turns it off.
  double field_air_stop_h = 0.04;
  /// ...air: farther than this (H) from every hair triangle (about twice a card layer's
  /// thickness, so that the space between two layers is hair)...
  double air_distance_h = 0.04;
  /// ...and no hair within air_distance_h of the way straight out from the body through the
  /// point, up to this far (H): hair under a card layer or inside a shell is not air.
  double air_covered_reach_h = 0.5;
  /// The field phase ends once a strand is this many times as long as what remains of the
  /// input strand nearest its root (from that strand's nearest point to its tip).
  double length_factor = 1.0;
  /// No step turns a strand by more than this from its last step, whichever rule takes it:
  /// hair does not fold back on itself where nothing folds it, and such a turn is two
  /// pieces of hair read in opposite senses meeting (a field whose sense flips between
  /// oppositely read input strands, a braid's crossing pieces, cards read from either end,
  /// a bridge back to a card behind). Along the field, the input strands take over there,
  /// as where the field ends early; along a card or a bridge, the strand ends. 180
  /// switches it off.
  double max_turn_deg = 90;
  /// At the end of an input strand, the next one must begin (or end, read backwards)
  /// within this distance...
  double continue_radius_h = 0.08;
  /// ...and leave within this angle of the current direction.
  double continue_max_angle_deg = 60;
  /// A root-type group that continues another (one whose cluster does not start at the
  /// root: cluster-all's split_continued_roots) is entered from within this distance, the
  /// reach of cluster-all's connections (f1_max): typeify typed it root because nothing
  /// lay within its own reach before it, so the gap to it is wider than continue_radius_h.
  double continued_root_radius_h = 0.25;
  /// ...and entered turning by up to this angle: hair gathered by a band turns there, the
  /// strands from the sides of the head most (about a right angle where side strands run
  /// back level and the tail hangs down).
  double continued_root_max_angle_deg = 120;
  /// Leaving the cluster it is rooted in, a strand enters the start of any strand of a
  /// cluster that does not start at the root (whatever its type) the same way, when that
  /// strand's tip hangs farther than this from the scalp: a tail or a braid after its
  /// band. (A cap's own cards and what is stacked on it end over the scalp.)
  double continued_tip_off_scalp_h = 0.15;
  /// Where the hair continues into a cluster that does not start at the root (a
  /// ponytail's tail after its band; the lower part of some layered cuts), a strand whose
  /// card ends before it (cards stacked on a cap end anywhere) joins the nearest card that
  /// feeds it, running its way, within continue_radius_h and continue_max_angle_deg.
  /// false: it ends where its card does. Off by default: more strands reach a tail with it,
  /// but the style classifiers retrained with it do worse on the real meshes held out, and
  /// interpolate must bridge the cap strands it sends into a braid (it does:
  /// InterpolationParams::wisp_bridge_length_m); docs/decisions/grow-join-and-gather-off.md.
  bool join_continued_flow = false;
  /// A strand of a cap that gathers into a band (its root cluster has a group feeding a
  /// continuation) whose card ends on the cap with nothing to continue into goes on along
  /// its cluster's field, by at most this far, until the start of a tail or braid hanging
  /// off the scalp lies within continued_root_radius_h (crown cards that end under the
  /// cards wrapping round to a braid); 0: it ends where its card does. Off by default: more
  /// cap strands reach the braid with it, but the style classifiers retrained with it call
  /// such a braid normal and hold out worse on the real meshes
  /// (docs/decisions/grow-join-and-gather-off.md).
  double gather_along_field_h = 0;
  /// A strand following an input strand's group is lost (and looks for the next group)
  /// farther than this from the group's rails.
  double follow_radius_h = 0.08;
  /// A strand following a group drifts back towards its nearest rail where it lies farther
  /// than follow_keep_h from it, by at most follow_pull steps per step (0: it keeps the
  /// offset it entered with).
  double follow_keep_h = 0.02;
  double follow_pull = 0.5;
  /// Across a gap, hair goes on ahead: a bridge into the next input strand goes to the
  /// first of its points (read its way, no farther than its start) that lies within a step
  /// or ahead within this angle of the strand's direction, and a strand none of whose
  /// points lies so is not continued into (a tail after its band excepted: it is entered
  /// as continued_root_max_angle_deg allows). Where cards overlap (stacked spikes, layers)
  /// the next starts behind or beside the end of the last: bridged to its start, the
  /// strand ran back across the hair and on again, or hopped sideways from card to card
  /// (stacked spikes chained so round a crown).
  /// 0: to the start of any strand next_entry() finds.
  double bridge_max_angle_deg = 45;
  /// Nor does a bridge cut across the painted hair: where the face of the hair mesh nearest
  /// the middle of a gap (within follow_radius_h) has clear paint
  /// (GrowInput::hair_triangle_flow), a strand whose way across the gap runs more than this
  /// angle off the strokes there is not continued into that strand. Hair that runs on
  /// past the end of its card into the next runs along the hair painted between them;
  /// spikes stacked over a cap at every angle end tip against base, and strands would hop
  /// from one to the next across the cap's strokes. From card to card only: out of its field, a strand may rise across
  /// the hair it leaves into a card stacked on it (a tuft on a cap that no other hair
  /// reaches). 30: within what hair-grow-report counts as along the flow. 0: no check.
  double bridge_paint_max_angle_deg = 30;
  /// Where the input gives the hair mesh's faces (GrowInput::hair_triangles), a strand
  /// following a group also drifts back towards the nearest point of that group's own
  /// faces (its card's surface) where it lies farther than follow_card_keep_h from them,
  /// by at most follow_card_pull steps per step, across its direction only: a strand
  /// over a card comes down onto it and keeps its place across the card's width, so the
  /// strands of a card lie spread over it. 0: no such hold.
  double follow_card_keep_h = 0.001;
  double follow_card_pull = 0.25;
  /// Grown points are kept this far outside the body (its signed distance field).
  double body_clearance_h = 0.004;
  double body_voxel_h = 0.01;  ///< spacing of the body's signed distance field
  /// Layers of hair (a bob's outer strips lie 0.05-0.15 H off the head, over inner ones):
  /// a root's reference input strand (which gives its length limit, and the height its
  /// strand keeps above the body along the field) is drawn, by a hash of the root, among
  /// the strands of the root's cluster that carry roots and pass within this distance of
  /// it. 0: the nearest strand, and strands follow the field at whatever height it takes
  /// them.
  double layer_radius_h = 0.1;
  /// Along the field, each step moves a strand towards its reference strand's height above
  /// the body (at the same arc length) by at most this share of a step.
  double layer_pull = 0.5;
  /// ...except over the first this much of its length (H): a strand rooted under its
  /// layer climbs to it at an even slope, the height it has to climb at its first step over
  /// this length, gently under hair lying on the head (a cap 7 mm up: about 20 degrees)
  /// and steeply under a shell standing off it (2-4 cm: 45-65 degrees),
  /// as hair with volume at its roots does. 0: layer_pull from the root on.
  double layer_climb_h = 0.08;
  /// Over the first this much of its length along the field (H), a strand heads over the
  /// scalp the way the paint runs on the hair face nearest it (within follow_radius_h,
  /// where the paint is clear and within 60 degrees of the field): near the scalp the
  /// field is an average of seeds 5-10 mm above, in voxels of field_voxel_h, and the paint
  /// of the hair right over a root says best which way the hair there leaves it. Its rise
  /// off the scalp stays the field's and the climb's (layer_climb_h). 0: the field alone.
  double root_heading_paint_h = 0.06;
  int max_points_per_strand = 2000;
  /// No strand grows longer than this (a guard against strands that wander from group to
  /// group; hair to the waist is about 3.5 H long).
  double max_length_h = 6;
};

/// What grow_strands() reads of extract.h5, types.h5 and clusters.h5.
struct GrowInput {
  StrandSet input_strands;             ///< root first; strand_attributes "group"
  std::vector<GroupType> group_type;   ///< per group
  std::vector<int32_t> group_cluster;  ///< per group, final clusters
  /// Per final cluster (clusters.h5 /clusters/starts_at_root): whether it starts at the
  /// root. Empty: every cluster with a root-type group does.
  std::vector<uint8_t> cluster_starts_at_root;
  Points3f body_vertices;
  Triangles3i body_triangles;
  std::vector<uint8_t> scalp_triangle;  ///< per body triangle
  /// The hair mesh as triangles, with each triangle's group (extract.h5 /mesh, faces
  /// fanned); empty when not given (GrowParams::follow_card_keep_h then does nothing).
  Points3f hair_vertices;
  Triangles3i hair_triangles;
  std::vector<int32_t> hair_triangle_group;
  /// Per triangle of hair_triangles: its face's painted flow axis (extract.h5
  /// /mesh/face_flow) where the paint is clear (coherence at least kClearFlowCoherence),
  /// else zero; empty: no paint seeds the fields (GrowParams::field_paint_seeds).
  Points3f hair_triangle_flow;
  double head_height_m = 0;
  std::string source;  ///< names the input in errors
};

/// Per cluster of the input: what growing did with it.
struct GrownCluster {
  int64_t strand_count = 0;       ///< strands rooted in it
  int64_t field_voxel_count = 0;  ///< 0: no field built (no roots, or no root-type strands)
  int64_t field_seeded_voxels = 0;
};

struct GrowResult {
  /// Grown strands, root first. strand_attributes: "cluster" (int32, the root's),
  /// "root_triangle" (int32, body triangle), "root_normal" (#strands x 3).
  /// point_attributes (int32): "cluster", the cluster each point belongs to: the root's
  /// along the root and the field, then the cluster of the group followed or bridged to,
  /// so that a strand can run through several clusters (a ponytail's cap, then its tail);
  /// "group", the input group followed or bridged to, -1 at the root and along the field.
  StrandSet strands;
  /// Per point: how the segment ending there was grown (GrowRule::root at roots).
  std::vector<GrowRule> point_rule;
  std::vector<GrownCluster> clusters;  ///< per input cluster
  int64_t scalp_triangles_used = 0;
  double scalp_area_m2 = 0;
  double root_spacing_m = 0;      ///< smallest distance between two roots
  int64_t points_pushed_out = 0;  ///< grown points moved out of the body
  int64_t continuations_same_cluster = 0;
  int64_t continuations_other_cluster = 0;
  /// Strands whose card ended on the cap and that joined the cards feeding a cluster that
  /// does not start at the root (GrowParams::join_continued_flow).
  int64_t strands_joining_continued_flow = 0;
  /// Strands that ended where a step, pushed back out of the body, hardly advanced: the
  /// card they followed, or their field, dives into the skin there.
  int64_t strands_ended_at_body = 0;
  /// Strands that ended where their next step off the field would have turned them by more
  /// than GrowParams::max_turn_deg (the field phase hands over to the cards instead).
  int64_t strands_ended_at_fold = 0;
  /// Strands whose field phase ran farther than GrowParams::field_air_stop_h through air
  /// and was taken back to where it left the hair.
  int64_t strands_stopped_at_air = 0;
  /// Roots took any input strand: no root-type group, or they covered too little of the
  /// scalp (GrowParams::min_typed_root_scalp_share).
  bool roots_from_any_type = false;
  /// Area of the scalp root-type strands cover over the area strands of any type cover
  /// (0 with no root-type strand; 1 when not measured: the share check turned off).
  double typed_root_scalp_share = 1.0;
};

/// Grows strands from the scalp (paper section 4.4, Figure 7):
///  1. roots: blue noise over the scalp triangles that root-type input strands of clusters
///     that start at the root cover, each in the cluster of the nearest such strand (a
///     root-type group that continues another, in a cluster that does not start at the
///     root, carries no roots);
///  2. one orientation field per cluster that has roots, from its root-type strands;
///  3. each strand follows its cluster's field (RK2) until it leaves the field or has
///     grown as long as the input strand nearest its root; then it follows the closest
///     input strand of the group it reaches, and at that strand's end the next input
///     strand that continues it (same cluster first, then the others), bridging gaps;
///     where none does and the hair continues into a cluster that does not start at the
///     root (groups whose cards end at its start: a ponytail's tail after its band), it
///     joins the nearest card running its way that feeds it, so that such hair does not
///     end on the cap;
///  4. no point enters the body: points are pushed out along the body's signed distance.
/// Deterministic whatever the thread count.
GrowResult grow_strands(const GrowInput& input, const GrowParams& params);

}  // namespace hair
