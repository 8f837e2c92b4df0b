#pragma once

#include <string>
#include <vector>

#include "hair/core/strand_set.h"
#include "hair/extract/painted_flow.h"
#include "hair/extract/strand_orientation.h"
#include "hair/geom/triangle_mesh_distance.h"
#include "hair/mesh/body_measures.h"
#include "hair/mesh/patch_rails.h"
#include "hair/mesh/poly_mesh.h"

namespace hair {

/// Settings of the extract stage (pipelines/default/extract.toml documents each).
struct ExtractParams {
  /// Source units to metres (MakeHuman meshes are in decimetres: 0.1).
  double unit_scale = 1.0;
  /// Head height H in metres; 0 measures it on the body (see head_measures()).
  double head_height_m = 0.0;
  /// Worst corner angle off 90 degrees for two triangles to be paired into a quad.
  double max_quad_corner_deviation_deg = 60.0;
  /// Ratio of mean chain lengths of the two edge families above which the longer
  /// family is taken as running along the hair, whatever the texture says.
  double along_length_ratio = 1.5;
  /// Hair does not go round the head: where the paint is not clear, before chain length, a
  /// family whose chains run round the axis from the head's centre through their region
  /// (circling_rails.h) on at least this share of their length...
  double along_circling_min_share = 0.7;
  /// ...winding round it by at least this much on average (degrees), is a shell's rings;
  /// the other family is the rails when it runs round the axis on at most 1 -
  /// along_circling_min_share of its length...
  double along_circling_min_sweep_deg = 120;
  /// ...and its chains are at least this long (H): strands, not a wound braid's width.
  double along_circling_other_min_length_h = 0.25;
  /// Whether the painted flow chooses rails, traces patches and orients strands; false
  /// reads the mesh as if it had no textures (the flow is still measured and written).
  bool paint_guides_strands = true;
  /// The painted flow chooses a region's rails, before chain length, when both its edge
  /// families lie this share of their length beside faces whose paint is clear...
  double along_paint_min_judged_share = 0.5;
  /// ...and one runs along the paint on this much more of its length than the other.
  double along_paint_min_gap = 0.25;
  /// A patch whose chosen rails run along its clear paint on less than this share of
  /// their length is cut into strands traced along the paint instead.
  double streamline_max_along_share = 0.8;
  /// A traced patch's streamlines take their sense from its rails (their vertex ids,
  /// their parting, their height) only where those rails run along the paint on at least
  /// this share of their judged length: rails that mostly cross the hair (rings round a
  /// cap, a grid that pays no heed to it) say which way they run, not the hair.
  double streamline_rails_min_along_share = 0.5;
  /// ...when it lies on the head: the median distance of its vertices from the head at
  /// most this, in H (caps and wigs; hanging cards and braid pieces keep their rails).
  double streamline_max_head_distance_h = 0.1;
  /// A tube lying on the head is traced like a cap only where its streamlines are hair
  /// (tube_streamlines.h): the longest at most this many times the patch's extent (longer
  /// ones wind round a braid piece)...
  double streamline_tube_max_extent_ratio = 3;
  /// ...and their mean length at least this share of its rails' (the strokes of a braid's
  /// lobes turn within a few faces).
  double streamline_tube_min_length_share = 0.5;
  /// Mean fall of the painted alpha along a region's rails, per face crossed (alpha
  /// 0 to 1), from which the fade decides root from tip (OrientationRule::alpha_fade).
  double alpha_fade_min_fall = 0.05;
  /// ...or mean fall along a whole rail, from one end to the other, from which it decides
  /// too: a rail of many small faces (a tube, a finely cut card) fades by little per face.
  double alpha_fade_min_rail_fall = 0.3;
  /// A rail votes on vertex order when at least this fraction of its steps go the
  /// same way (ids growing or falling).
  double ordered_rail_fraction = 0.95;
  /// Orientation thresholds (see OrientationThresholds).
  double vertex_order_min_vote = 0.8;
  double scalp_distance_min_slope = 0.2;
  double scalp_distance_lean_slope = 0.05;
  double uv_min_growth = 0.3;
  double height_min_slope = 0.3;
  double height_min_head_distance_h = 0.05;
  /// Share of confidently decided regions that must agree on a texture convention
  /// (v axis along the hair; v growing root to tip) for the mesh to use it.
  double convention_min_agreement = 0.85;
  /// A rail is parted at its highest point (a card draped over the head) or its lowest
  /// (a shell tail folded at its tip) when each side is at least this share of its length...
  double parting_min_side_share = 0.25;
  /// ...and each side's end lies lower (higher) than that point by this share of the
  /// side's length.
  double parting_min_side_drop = 0.25;
  /// ...and the tips (the ends of a draped rail, the fold of a folded one) hang off the
  /// head by more than this fraction of H.
  double parting_min_end_distance_h = 0.1;
  /// Along-chains shorter than this share of their region's longest are fragments
  /// (colouring conflicts around poles) and are dropped.
  double min_rail_length_share = 0.25;
  /// Continuation: confident strands of other patches starting (or ending) within this
  /// distance, as a fraction of H, of a rail's end tell that end is distal (proximal).
  double continuation_radius_h = 0.08;
  /// Body triangles above the neck within this distance of the hair mesh, as a
  /// fraction of H, form the scalp.
  double scalp_distance_h = 0.06;
  /// ...and so do those under hair that stands off the head up to this far (H): hair
  /// within scalp_distance_h of the line along the triangle's outward normal (a bob's
  /// shell 2-4 cm off the back of the head is rooted all over the scalp under it), except
  /// where the triangle faces forward (normal's +Z above 0.5: hair hanging over the face is
  /// rooted above it). 0: only the distance decides. 0.15 (hair up to 0.18 H, 4.3 cm, out):
  /// a bob's shell stands up to 0.15 H off the upper back along the scalp's normal.
  double scalp_under_hair_h = 0.15;
  /// ...on triangles at least this far above the neck (H). Lower, at the bottom of the nape
  /// and under the ears, hair standing off the head hangs past it from above: a tail hangs
  /// 2-4 cm off the nape there, where the mesh has no hair on the head.
  double scalp_under_hair_min_height_h = 0.1;
  /// The face is never scalp: below this far under the crown (H; 0.4: the eyes of the
  /// MakeHuman body lie 0.47-0.56 H under it), where the body round a triangle faces
  /// forward (scalp.h). A fringe hanging over the eyes lies within scalp_distance_h of them.
  /// 1 or more: no face (the neck lies 1 H under the crown).
  double scalp_face_below_top_h = 0.4;
  /// How the painted flow is read off the mesh's textures (painted_flow.h).
  PaintedFlowParams painted_flow;
};

/// How the along family of a quad region was chosen.
enum class AlongRule : int8_t {
  chain_length = 0,  ///< the family with clearly longer chains
  texture_axis = 1,  ///< the texture axis the mesh's clear regions run along
  painted_flow = 2,  ///< the family that runs along the strokes painted on its faces
  across_rings = 3,  ///< the family across the other, which circles the head (rings)
};

/// Counts for the log and the closing report.
struct ExtractStats {
  int64_t degenerate_faces_removed = 0;
  int64_t triangles_paired = 0;
  int64_t triangles_left = 0;
  int64_t rails_parted = 0;  ///< closed, draped or folded rails cut in two
  int64_t fragments_dropped = 0;  ///< along-chains too short to be rails
  int64_t family_conflicts = 0;
  std::array<int64_t, 7> groups_by_rule{};         ///< indexed by OrientationRule
  std::array<int64_t, 4> regions_by_along_rule{};  ///< indexed by AlongRule
  /// Regions whose rails the paint chose against what chain length alone would choose.
  int64_t regions_turned_by_paint = 0;
  /// Patches cut into strands along the paint (their rails crossed it).
  int64_t patches_traced_along_paint = 0;
  /// Of them, tubes (shells meshed as tubes); and tubes on the head whose streamlines
  /// wound round them or came out short (braid pieces), which keep their rails.
  int64_t tubes_traced_along_paint = 0, tubes_kept_on_rails = 0;
  std::array<int64_t, 5> groups_by_kind{};  ///< indexed by PatchKind
  bool vertex_order_trusted = true;
  int uv_growth_sign = 0;  ///< the mesh's texture convention: +1, -1, or 0 for none
  /// Regions whose vertex ids were overruled by their paint (v and alpha fade agreeing).
  int64_t paint_overruled_ids = 0;
  /// Regions continuation decided whose paint said the other way twice over (the same
  /// test), turned after continuation: continuation still runs from the regions as they
  /// were, since on layered cards it carries a reading on too far.
  int64_t paint_overruled_continuation = 0;
  /// Regions off the head decided by one cue (their vertex ids with the head distance
  /// silent, or their head distance against their ids), turned because the hair running
  /// on through their rails' ends said the other way.
  int64_t continuation_overruled_ids = 0;
  /// Regions off the head whose vertex ids decided with the head distance silent, turned
  /// because their height and their texture's v both said the other way.
  int64_t height_and_texture_overruled_ids = 0;
  /// Regions off the head whose head distance (with the height or without) decided
  /// against their vertex ids, turned because their ids and their texture's v both said
  /// the other way.
  int64_t ids_and_texture_overruled_head_distance = 0;
  /// Strands that ran against the other strands of their group, turned round
  /// (group_sense.h).
  int64_t strands_turned_to_their_group = 0;
};

/// Everything extract.h5 holds (schemas/extract.json), in metres.
struct ExtractResult {
  /// Input strands, root first. Strand attributes "group" and "rail"; point
  /// attribute "source_vertex" (id in hair_mesh).
  StrandSet strands;
  std::vector<int32_t> group_first_strand{0};  ///< #groups + 1
  std::vector<PatchKind> group_kind;           ///< #groups
  std::vector<OrientationRule> group_rule;     ///< #groups
  std::vector<float> group_confidence;         ///< #groups
  std::vector<int32_t> group_face_count;       ///< #groups

  PolyMesh hair_mesh;               ///< cleaned, scaled, triangles paired into quads
  std::vector<int32_t> face_group;  ///< #faces of hair_mesh
  /// The flow painted in the mesh's textures, per face of hair_mesh (painted_flow(); all
  /// zero for a mesh without textures).
  PaintedFlow painted_flow;

  Points3f body_vertices;               ///< #body vertices x 3
  Triangles3i body_triangles;           ///< #body triangles x 3
  std::vector<uint8_t> scalp_triangle;  ///< #body triangles, 1 = scalp
  HeadMeasures head;                    ///< in metres

  ExtractStats stats;

  int32_t group_count() const { return static_cast<int32_t>(group_kind.size()); }
};

/// Reads the input strands of a hair mesh (paper section 4.1): one strand group per
/// patch, one strand per rail, every strand oriented root to tip; and measures the
/// body: its head height H, the head region and the scalp. `textures` are the hair
/// mesh's materials' images (load_painted_textures() of hair_mesh.materials; empty for
/// none): their painted flow chooses rails and tells roots from tips where it is clear.
/// Pure: no file access; the file names only label errors. Deterministic for any thread
/// count.
///
/// Throws hair::Error (bad_input) for empty or degenerate meshes and non-finite
/// coordinates, naming the file.
ExtractResult extract_strands(PolyMesh hair_mesh, PolyMesh body_mesh, const ExtractParams& params,
                              const std::string& hair_file, const std::string& body_file,
                              const PaintedTextures& textures = {});

}  // namespace hair
