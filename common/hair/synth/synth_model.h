#pragma once
// Synthetic hair meshes with ground truth (issue 3): hair built the way artists build
// it (strips and cards of 2-4 rails, caps as grids, braids as many short disjoint
// patches along three interleaved streams), fitted on a body, with the truth of every
// patch (stream, group type, style), every stream's centre curve and dense true strands.

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "hair/core/strand_set.h"
#include "hair/mesh/poly_mesh.h"
#include "hair/style/hair_style.h"

namespace hair::synth {

/// Group types of the paper's Algorithm 1 (section 4.1), in the truth's enum order.
enum class GroupType : int8_t { root_free = 0, root_connected = 1, middle = 2, tip = 3 };

/// Styles of the paper's section 5.1 (the truth's enum order is hair::HairStyle's).
using HairStyle = hair::HairStyle;

/// How a patch's vertex ids run, a defect artists' meshes have (DESIGN.md).
enum class VertexOrder : int8_t { natural = 0, reversed = 1, shuffled = 2 };

/// One part of a hairstyle: a kind of hair grown from a region of the scalp.
struct ComponentSpec {
  /// normal: strips hanging from the scalp; short_cards: cards standing off the scalp;
  /// short_cap: cap grids lying on the scalp from the crown to the hairline (short02);
  /// ponytail: cap grids to a band, tails from it; braid: caps to a braid top, a braid.
  enum class Kind { normal, short_cards, ponytail, braid, short_cap };
  Kind kind = Kind::normal;
  /// Streams (strips, cards; for a ponytail the cap patches, one tail strip each; for a
  /// short cap its grids, side by side around the whorl). Braids always have three
  /// streams.
  int stream_count = 40;
  /// Length of a stream from its root to its tip, drawn uniformly in [min, max] (a short
  /// cap's stream ends at the hairline if that comes first).
  double length_min_m = 0.30;
  double length_max_m = 0.40;
  /// Waves across the strip: amplitude and wavelength (0 amplitude: straight).
  double wave_amplitude_m = 0.0;
  double wavelength_m = 0.08;
  /// Width of a strip or card (caps: at the hairline; a short cap's grids: 90 degrees
  /// from the whorl, narrowing towards it as sin(angle); braid pieces: the piece).
  double strip_width_m = 0.03;
  /// Scalp region of the roots: azimuth around +Y from the face (+Z, 0) towards +X,
  /// in degrees, and polar angle from the crown, in degrees. The front hairline is
  /// always respected. A short cap's grids fan out from its crown whorl (the band
  /// position): they share the azimuth range evenly around the whorl, each root at an
  /// angle in [polar_min_deg, polar_max_deg] from the whorl.
  double azimuth_min_deg = -180.0;
  double azimuth_max_deg = 180.0;
  double polar_min_deg = 0.0;
  double polar_max_deg = 115.0;
  /// Ponytail band, braid top or short cap's crown whorl: a point on the head at this
  /// azimuth and polar angle.
  double band_azimuth_deg = 180.0;
  double band_polar_deg = 70.0;
  /// Braid: half width across (a) and depth (b) of the three streams around the axis,
  /// and the length of one full braid period.
  double braid_width_m = 0.014;
  double braid_depth_m = 0.007;
  double braid_period_m = 0.07;
  /// Hidden length left out where a cap meets its tail (ponytail) or braid.
  double band_gap_m = 0.01;
  /// Short cap: the whorl turns every grid the same way, by an angle drawn in
  /// [swirl_min_deg, swirl_max_deg] with either sign, reached 90 degrees from it (the swirl
  /// of a crown; with swirl_min_deg 0, drawn in [-swirl_max_deg, swirl_max_deg]). Far
  /// beyond the default, the hair round the whorl runs level round the head.
  double swirl_min_deg = 0.0;
  double swirl_max_deg = 12.0;
  /// Short cap: meshed as one piece whose quads run in rings around the whorl (a wig cap),
  /// the rings' chains longer than the hair's, instead of one grid per stream. Its roots
  /// all lie polar_min_deg from the whorl.
  bool one_piece_rings = false;
  /// Short cap: meshed as one piece in a grid of latitudes and longitudes round the head's
  /// vertical axis, whatever way its hair runs (a wig cap modelled without regard to its
  /// hair, as short01's and short03's): neither family of edges follows the hair, and only
  /// the paint says where it goes. Its roots, as for one_piece_rings, lie polar_min_deg
  /// from the whorl. Not with one_piece_rings.
  bool one_piece_grid = false;
  /// one_piece_grid: above 0, the grid leaves out the rows of faces that start within this
  /// polar angle of the crown, so that the shell is open there and its latitudes close
  /// round the head: quads closed on themselves, a tube (shells modelled so, as Elvaerwyn's
  /// short men's cut).
  double grid_crown_hole_deg = 0.0;
  /// Ponytail: above 0, the tail is coiled round the band into a bun of this radius,
  /// lying against the head, each stream from its own side of the band (an up-do);
  /// the coil is fixed hair, as the cap is.
  double bun_radius_m = 0.0;
  /// Normal hair: above 0, each stream winds round its hanging axis in a helix of this
  /// radius and `ringlet_pitch_m` per turn (a corkscrew ringlet), fading in over its
  /// first 3 cm.
  double ringlet_radius_m = 0.0;
  double ringlet_pitch_m = 0.035;
  /// Ponytail (no bun) and braid: loose hair drawn back with volume, as artists make low
  /// braids and tails whose hair covers the ears (braid01's cap stands 2-4 cm off the head).
  /// cap_volume_m: the cap's grids stand up to this far off the head between their roots and
  /// the band. cap_drape: they fall from their roots down the side of the head to ear level,
  /// swept off the face, before they turn back to the band.
  double cap_volume_m = 0.0;
  bool cap_drape = false;
  /// Braid: its top stands this much farther off the head than a band's (0.012 m), where
  /// loose hair drawn back with volume gathers, and the braid leaves it backwards before it
  /// falls (braid01's braid starts 0.16 H off the skin, going back, not down).
  double braid_lift_m = 0.0;
  /// Braid: its width at the tip as a share of its width at the top (1: as wide all along);
  /// below 1 the three streams and their strips narrow evenly down the braid to the tie, as
  /// real braids do (braid01's ends at 0.59 of its widest).
  double braid_tip_width_share = 1.0;
  /// Braid: each of its three lobes woven from this many cards side by side (each its own
  /// stream from its own root, overlapping the next by half), as braid01's lobes are woven
  /// from the cap's cards; 1: one card a lobe.
  int braid_cards_per_lobe = 1;
  /// Normal hair: above 0, each stream stands off the head by up to this much below its
  /// root, rising smoothly over the first 40% of its length and turning back in over the
  /// last 25%, as a bob's cards do (bob01 and bob02's rails lie 1-1.5 cm farther off the body from
  /// the middle of their length on than hair-synth's hugging cards).
  double hang_volume_m = 0.0;
  /// Normal hair: the truth's hair is rooted all over the scalp its cards cover, not only at
  /// each card's root: under every point of a card that lies over the scalp (above the
  /// hairline), true strands rise from the scalp, over twice the card's height there, and
  /// run on along the card to its tip, as the hair under a voluminous cut's outer cards is
  /// rooted (bob01's and bob02's shells stand 2-4 cm off the head, and the scalp under
  /// them carries hair). Only the truth gains them; the mesh is the same.
  bool rooted_under_volume = false;
  /// Above 0: each piece is meshed as a closed tube of this many sides round the stream's
  /// centre (its diameter the strip width), as artists model ringlets, not a flat strip.
  int tube_sides = 0;
  /// Normal hair and a ponytail's tail: above 0, each piece of hanging hair (not a cap's
  /// grid) is meshed as a closed pouch, as game artists model a tail as a shell (Mozilla
  /// Hubs' ponytails): one strip down the piece's front from its start to its end, round
  /// its end and back up its back, the two sheets this far apart. The rails along the
  /// hair run down and back up, folding at the tip; the texture's v runs from the start
  /// (0) to the end (1) on both sheets.
  double folded_shell_thickness_m = 0.0;
};

/// How patches are cut from streams and how much they are spoiled; every defect has a
/// knob (issue 3).
struct DefectSpec {
  int rails_min = 2;  ///< rails (points across) of a strip, drawn in [min, max]
  int rails_max = 4;
  int cap_rails = 5;                ///< rails of a cap grid
  double segment_length_m = 0.015;  ///< quad length along the hair
  /// Normal hair and short caps: pieces each stream is cut into, drawn in [1, max] (1:
  /// one strip or grid from root to tip; a short cap in 2: a layered cut).
  int normal_pieces_max = 1;
  /// Braid pieces: length of one piece (about a third of a period: one crossing).
  double braid_piece_length_m = 0.025;
  /// Hidden length left out between consecutive patches of a stream (negative:
  /// they overlap by that much).
  double gap_m = 0.004;
  /// Share of junctions where consecutive patches overlap instead, by overlap_m.
  double overlap_share = 0.2;
  double overlap_m = 0.006;
  double jitter_m = 0.0008;        ///< uniform noise on every vertex, each axis
  double triangulate_share = 0.1;  ///< patches whose quads are split into triangles
  /// Of those, the share split along each quad's shorter diagonal in 3D, as glTF exporters,
  /// game engines and "beauty" triangulations do (the others along the same diagonal in
  /// every quad): on a sheared or twisted card the added edge is then no triangle's longest.
  double shorter_diagonal_share = 0.0;
  double reversed_share = 0.1;     ///< patches numbered tip to root
  double shuffled_share = 0.05;    ///< patches numbered at random
  /// Roots this far above the head surface (a short cap lies this far off the scalp at
  /// the crown, rising to 1.5 times this at the hairline).
  double scalp_lift_m = 0.004;
  double body_clearance_m = 0.008;  ///< hair kept this far off the body
  /// Share of the patches of hair lying on the scalp (short caps) whose tip end is tucked
  /// into the head, as artists hide a card's end under the skin (bob01's front cards run
  /// into the forehead): over its last tuck_length_m the patch dives from its lift to
  /// tuck_depth_m under the scalp. The true strands still end on the scalp.
  double tucked_share = 0.0;
  double tuck_length_m = 0.012;
  double tuck_depth_m = 0.008;
  /// The mesh carries a painted texture as artists' meshes do (synth_paint.h): strokes
  /// along v, which runs root to tip on every patch, and an alpha fading towards the tips...
  bool painted_texture = false;
  /// ...or not fading (a tiled hair texture, as caps are often painted): then the paint
  /// tells the hair's axis but not its root from its tip.
  bool painted_fade = true;
};

/// A hairstyle: its components and defects (a preset, or a preset varied by a seed).
struct HairStyleSpec {
  std::string name;
  std::vector<ComponentSpec> components;
  DefectSpec defects;
};

/// Names of the presets, in gallery order (the training corpus cycles through these).
const std::vector<std::string>& preset_names();

/// Presets of real meshes' kinds with painted textures (the real-meshes issue), in the
/// training corpus with `corpus --painted`: "ring_cap" (a one-piece wig cap meshed in rings around
/// the whorl, painted down from it), "cap_over_layer" (such a cap over a longer back layer of
/// strips), "mohawk" (spike cards along the middle of the head), "low_tail" (hair pulled
/// back under a band low at the nape into a tail), "face_locks" (medium hair with two
/// longer locks framing the face), "bun" (hair pulled up from the whole hairline to a
/// band high on the back of the crown and coiled round it), "ringlets" (a one-piece cap
/// over the top of the head with corkscrew ringlet tubes hanging from under its edge), "bob"
/// (a few wide one-piece cards cut level at the jaw, as bob01 and bob02), "swirl_cap" (a
/// one-piece cap in rings whose hair swirls round its whorl, painted with a tiled texture
/// that does not fade: the paint gives the axis, the hair's own lie its sense, as short01's
/// cap), "volume_bob" (the bob with its cards standing up to 3 cm more off the head, as
/// bob01's shell does, its truth rooted under them), "shell_tail" (a ponytail whose tail
/// is meshed as closed pouches, its rails folding back at the tip).
const std::vector<std::string>& painted_preset_names();

/// Whether corpus_plan() puts the preset `name` in the training corpus: every preset but
/// "bob", whose clusters come out shorter than a real bob's (docs/synth.md), and
/// "swirl_cap", "volume_bob" and "shell_tail", presets for extract and grow kept out of the
/// drawn training corpus (a preset in the corpus renumbers every model after it).
bool in_training_corpus(const std::string& name);

/// The preset `name`; throws hair::Error (usage) naming the known presets otherwise.
HairStyleSpec preset(const std::string& name);

/// `spec` with its knobs varied within plausible bounds by `seed` (the corpus). With
/// `artists_families`, then drawn into families of artists' meshes that the presets alone
/// miss (issue 26): a third of the short caps swept back from the forehead (as short04),
/// half the braids hanging to the waist (as braid01's), half the tails and braids gathered
/// from the whole head drawn back low and loose over the ears with volume (as braid01's
/// cap: cap_volume_m, cap_drape), the braids among them lifted off the head by that volume
/// (braid_lift_m), half the braids narrowing to the tie (braid_tip_width_share) and half
/// woven from the cap's cards (braid_cards_per_lobe, longer braid pieces). The
/// training corpus (corpus_plan
/// with_painted) draws them; without, the presets' varied models, and the tests measured
/// on them, stay as they were.
HairStyleSpec varied_spec(HairStyleSpec spec, uint32_t seed, bool artists_families = false);

/// One model of a corpus: its file stem, preset, seed and varied specification.
struct CorpusEntry {
  std::string name;  ///< "<preset>_<index, 3 digits>"
  std::string preset;
  uint32_t seed = 0;
  HairStyleSpec spec;
};

/// The models of a corpus of `count`: model i is preset i mod #presets with seed
/// base_seed * 1000 + i, its knobs varied by that seed (varied_spec). The presets are
/// preset_names(), followed by painted_preset_names() when `with_painted` (the kinds of
/// community meshes, with their painted textures: what the style classifiers train on),
/// which also draws the artists' families (varied_spec).
std::vector<CorpusEntry> corpus_plan(int count, uint32_t base_seed, bool with_painted = false);

/// One patch of the mesh and its truth.
struct SynthPatch {
  int32_t stream = -1;
  int32_t index_in_stream = 0;  ///< 0 at the root
  GroupType type = GroupType::root_free;
  HairStyle style = HairStyle::normal;
  VertexOrder order = VertexOrder::natural;
  bool triangulated = false;
  bool shorter_diagonals = false;  ///< triangulated along each quad's shorter diagonal
  bool tucked = false;  ///< its tip end dives into the head (DefectSpec::tucked_share)
  int32_t rails = 2;
  int64_t first_vertex = 0, vertex_count = 0;  ///< vertex ids [first, first + count)
  int64_t first_face = 0, face_count = 0;      ///< face ids [first, first + count)
  double start_m = 0, end_m = 0;               ///< arc length along the stream's centre
};

/// A generated hairstyle, in metres, +Y up.
struct SynthModel {
  std::string name;
  uint32_t seed = 0;
  HairStyleSpec spec;
  PolyMesh mesh;  ///< metres; patches are contiguous in vertex and face ids
  std::vector<SynthPatch> patches;
  /// Per vertex: arc length of its row along its stream's centre, metres.
  std::vector<float> vertex_along_m;
  /// Centre curve of every stream, root first; strand attribute "style".
  StrandSet stream_centres;
  std::vector<HairStyle> stream_style;    ///< #streams: the style of the stream's tip part
  std::vector<int32_t> stream_component;  ///< #streams: index into spec.components
  /// Dense true strands, root first; strand attribute "stream".
  StrandSet strands;
  /// #points of strands: the style of the hair at each point (a ponytail's strands are
  /// fixed on the cap, normal in the tail).
  std::vector<HairStyle> strand_point_style;
};

/// Builds a hairstyle on `body_m` (a body mesh in metres, +Y up, face towards +Z),
/// deterministically from `seed`. Pure: no file access.
///
/// Streams start on the head (roots placed on the body's head surface) and grow
/// outward and down, kept off the body; patches are cut along them; the truth group
/// types follow Algorithm 1: a stream of one patch is root_free, otherwise its patches
/// are root_connected, middle..., tip.
SynthModel generate_model(const HairStyleSpec& spec, const PolyMesh& body_m, uint32_t seed,
                          int strands_per_stream = 24);

}  // namespace hair::synth
