// The presets of synthetic hairstyles by name: the gallery's, and the painted ones of the
// kinds community meshes come in.
#include "hair/synth/synth_model.h"

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "hair/core/error.h"

namespace hair::synth {

const std::vector<std::string>& painted_preset_names() {
  static const std::vector<std::string> names = {
      "ring_cap", "cap_over_layer", "mohawk", "low_tail",  "face_locks",
      "bun",      "ringlets",       "bob",    "swirl_cap", "volume_bob", "shell_tail",
      "swirl_shell"};
  return names;
}

bool in_training_corpus(const std::string& name) {
  // The bob's clusters come out shorter than a real bob's (0.54 H against bob02's
  // 0.86 H), and trained on, they pulled short03's cap to normal (docs/synth.md).
  return name != "bob" && name != "swirl_cap" && name != "volume_bob" && name != "shell_tail" &&
         name != "swirl_shell";
}

const std::vector<std::string>& preset_names() {
  static const std::vector<std::string> names = {
      "long_straight", "long_wavy", "medium_straight", "medium_wavy", "short",  "short_cap",
      "ponytail",      "braid",     "normal_braid",    "two_braids",  "half_up"};
  return names;
}

namespace {

/// Hair hanging from the scalp in strips (ComponentSpec::Kind::normal), its knobs the defaults.
ComponentSpec normal_hair() {
  ComponentSpec normal;
  normal.kind = ComponentSpec::Kind::normal;
  return normal;
}

/// A one-piece wig cap, as short03: quads in rings around the crown whorl, its texture
/// unwrapped so that the painted strokes run from the whorl to the hairline.
void fill_ring_cap(HairStyleSpec& spec) {
  using Kind = ComponentSpec::Kind;
  ComponentSpec cap;
  cap.kind = Kind::short_cap;
  cap.one_piece_rings = true;
  cap.stream_count = 28;
  cap.length_min_m = 0.16;
  cap.length_max_m = 0.24;
  cap.strip_width_m = 0.02;
  cap.band_azimuth_deg = 180;
  cap.band_polar_deg = 20;
  cap.polar_min_deg = 8;
  cap.polar_max_deg = 8;
  spec.defects.scalp_lift_m = 0.003;
  spec.defects.painted_texture = true;
  spec.components = {cap};
}

/// A one-piece cap in rings over the top of the head, and under its back edge a longer
/// layer of strips hanging to the shoulders (a layered cut whose back layer a cap hides).
void fill_cap_over_layer(HairStyleSpec& spec) {
  ComponentSpec normal = normal_hair();
  ComponentSpec cap = preset("ring_cap").components.front();
  cap.length_min_m = 0.12;
  cap.length_max_m = 0.16;
  ComponentSpec left = normal, right = normal;
  left.azimuth_min_deg = 110;
  left.azimuth_max_deg = 180;
  right.azimuth_min_deg = -180;
  right.azimuth_max_deg = -110;
  for (ComponentSpec* layer : {&left, &right}) {
    layer->polar_min_deg = 75;
    layer->stream_count = 12;
    layer->length_min_m = 0.20;
    layer->length_max_m = 0.28;
  }
  spec.defects.scalp_lift_m = 0.003;
  spec.defects.painted_texture = true;
  spec.components = {cap, left, right};
}

/// Spike cards standing up along the middle of the head, front to back, the sides bare.
void fill_mohawk(HairStyleSpec& spec) {
  using Kind = ComponentSpec::Kind;
  ComponentSpec front;
  front.kind = Kind::short_cards;
  front.stream_count = 10;
  front.length_min_m = 0.05;
  front.length_max_m = 0.09;
  front.strip_width_m = 0.02;
  front.azimuth_min_deg = -12;
  front.azimuth_max_deg = 12;
  ComponentSpec back_left = front, back_right = front;
  back_left.azimuth_min_deg = 168;
  back_left.azimuth_max_deg = 180;
  back_right.azimuth_min_deg = -180;
  back_right.azimuth_max_deg = -168;
  back_left.stream_count = back_right.stream_count = 6;
  spec.defects.rails_max = 3;
  spec.defects.painted_texture = true;
  spec.components = {front, back_left, back_right};
}

/// Hair pulled back under a band low at the nape into a tail (the cap's grids run from
/// the hairline back and down to the band).
void fill_low_tail(HairStyleSpec& spec) {
  using Kind = ComponentSpec::Kind;
  ComponentSpec tail;
  tail.kind = Kind::ponytail;
  tail.stream_count = 12;
  tail.band_polar_deg = 105;
  tail.length_min_m = 0.22;
  tail.length_max_m = 0.30;
  tail.strip_width_m = 0.05;
  spec.defects.painted_texture = true;
  spec.components = {tail};
}

/// Medium hair with two longer locks framing the face, from the temples down past the
/// chin in front of the ears.
void fill_face_locks(HairStyleSpec& spec) {
  ComponentSpec normal = normal_hair();
  normal.length_min_m = 0.14;
  normal.length_max_m = 0.20;
  normal.stream_count = 35;
  normal.azimuth_min_deg = -150;
  normal.azimuth_max_deg = 150;
  ComponentSpec left = normal, right = normal;
  left.azimuth_min_deg = 40;
  left.azimuth_max_deg = 70;
  right.azimuth_min_deg = -70;
  right.azimuth_max_deg = -40;
  for (ComponentSpec* lock : {&left, &right}) {
    lock->stream_count = 4;
    lock->length_min_m = 0.26;
    lock->length_max_m = 0.32;
    lock->polar_min_deg = 60;
  }
  spec.defects.normal_pieces_max = 2;
  spec.defects.painted_texture = true;
  spec.components = {normal, left, right};
}

/// An up-do: hair pulled up and back from the whole hairline to a band high on the back
/// of the crown, its ends coiled round the band into a bun lying against the head.
void fill_bun(HairStyleSpec& spec) {
  using Kind = ComponentSpec::Kind;
  ComponentSpec up_do;
  up_do.kind = Kind::ponytail;
  up_do.stream_count = 24;
  up_do.polar_min_deg =
      35;  // roots towards the hairline: the strips cover the scalp as they converge
  up_do.band_polar_deg = 60;
  up_do.length_min_m = 0.26;
  up_do.length_max_m = 0.32;
  up_do.strip_width_m = 0.05;
  up_do.bun_radius_m = 0.03;
  spec.defects.painted_texture = true;
  spec.components = {up_do};
}

/// A one-piece cap in rings over the top of the head and, from under its edge at the
/// sides and back, corkscrew ringlets meshed as tubes hanging to the shoulders.
void fill_ringlets(HairStyleSpec& spec) {
  ComponentSpec normal = normal_hair();
  ComponentSpec cap = preset("ring_cap").components.front();
  cap.length_min_m = 0.12;
  cap.length_max_m = 0.16;
  ComponentSpec curls = normal;
  curls.stream_count = 20;
  curls.polar_min_deg = 70;
  curls.azimuth_min_deg = -160;
  curls.azimuth_max_deg = 160;
  curls.length_min_m = 0.18;
  curls.length_max_m = 0.26;
  curls.strip_width_m = 0.01;
  curls.ringlet_radius_m = 0.008;
  curls.ringlet_pitch_m = 0.035;
  curls.tube_sides = 6;
  spec.defects.scalp_lift_m = 0.003;
  // Rings 6 mm apart along the hair, twelve a turn of the curl (a 1.5 cm quad would cut
  // across a 3.5 cm turn by 37 degrees).
  spec.defects.segment_length_m = 0.006;
  spec.defects.painted_texture = true;
  spec.components = {cap, curls};
}

/// Hair cut level at the jaw, as bob01 and bob02: a few wide cards, each one piece from
/// its root to the cut, lying on the head and hanging close to it (no layers, no
/// pieces to chain).
void fill_bob(HairStyleSpec& spec) {
  ComponentSpec normal = normal_hair();
  normal.length_min_m = 0.18;
  normal.length_max_m = 0.24;
  normal.stream_count = 12;
  normal.strip_width_m = 0.06;
  normal.polar_max_deg = 45;  // roots round the crown: the cards cover the head
  normal.hang_volume_m = 0.012;  // standing off the head below the crown, as bob01's and bob02's
  normal.rooted_under_volume = true;  // and the scalp under the cards carries hair
  // Parted in the middle: no card roots over the face (it would hang over it).
  ComponentSpec left = normal, right = normal;
  left.azimuth_min_deg = 45;
  left.azimuth_max_deg = 180;
  right.azimuth_min_deg = -180;
  right.azimuth_max_deg = -45;
  spec.defects.normal_pieces_max = 1;
  spec.defects.painted_texture = true;
  spec.components = {left, right};
}

/// The bob with its cards standing off the head as far as bob01's shell does (2-4 cm off
/// the back of the head): up to 3 cm more below the crown, its truth rooted all over the
/// scalp under them. Extract's scalp has to reach that far under hair for the roots.
void fill_volume_bob(HairStyleSpec& spec) {
  fill_bob(spec);
  for (ComponentSpec& component : spec.components) component.hang_volume_m = 0.03;
}

/// A ponytail whose tail is a closed shell, as game artists model one (Mozilla Hubs'
/// ponytails): each tail strip a pouch 1.5 cm thick, its rails running down the front,
/// round the tip and back up the back to the band.
void fill_shell_tail(HairStyleSpec& spec) {
  using Kind = ComponentSpec::Kind;
  ComponentSpec tail;
  tail.kind = Kind::ponytail;
  tail.stream_count = 12;
  tail.band_polar_deg = 80;
  tail.length_min_m = 0.30;
  tail.length_max_m = 0.38;
  tail.strip_width_m = 0.05;
  tail.folded_shell_thickness_m = 0.015;
  spec.defects.normal_pieces_max = 1;
  spec.defects.painted_texture = true;
  spec.components = {tail};
}

/// A one-piece wig cap as ring_cap, but meshed in a grid of latitudes and longitudes
/// that pays no heed to its hair (short01's and short03's caps), its hair swirling round
/// the whorl (turned by 50-80 degrees 90 degrees from it, so that it runs level round
/// the sides of the head), and its texture tiled, not fading to the tips: extract traces
/// streamlines along the paint, which gives each face's axis but not which way the hair
/// runs, so each streamline is oriented by its own ends (the higher is the root), which
/// a level or rising stretch of the swirl can read either way; the streamlines around it
/// say which (extract's group sense).
void fill_swirl_cap(HairStyleSpec& spec) {
  ComponentSpec cap = preset("ring_cap").components.front();
  cap.one_piece_rings = false;
  cap.one_piece_grid = true;
  cap.swirl_min_deg = 50;
  cap.swirl_max_deg = 80;
  cap.band_polar_deg = 30;
  spec.defects.scalp_lift_m = 0.003;
  spec.defects.painted_texture = true;
  spec.defects.painted_fade = false;
  spec.components = {cap};
}

/// A one-piece shell as swirl_cap, open at the crown: its latitudes close round the head,
/// so that extract reads it as a tube (quads closed on themselves), as some shells are
/// modelled (the corpus's short men's cut), and neither family of its edges runs with the
/// hair that swirls over it.
void fill_swirl_shell(HairStyleSpec& spec) {
  fill_swirl_cap(spec);
  ComponentSpec& shell = spec.components.front();
  shell.band_polar_deg = 0;  // the whorl at the crown, where the shell is open
  shell.grid_crown_hole_deg = 12;
}

/// A painted preset: its name and what fills its specification (named, its defects the
/// defaults) with its components and defects.
struct PaintedPreset {
  const char* name;
  void (*fill)(HairStyleSpec& spec);
};

/// The painted presets, in the order they are looked up by name.
constexpr std::array<PaintedPreset, 12> kPaintedPresets = {{
    {"ring_cap", fill_ring_cap},
    {"cap_over_layer", fill_cap_over_layer},
    {"mohawk", fill_mohawk},
    {"low_tail", fill_low_tail},
    {"face_locks", fill_face_locks},
    {"bun", fill_bun},
    {"ringlets", fill_ringlets},
    {"bob", fill_bob},
    {"volume_bob", fill_volume_bob},
    {"shell_tail", fill_shell_tail},
    {"swirl_cap", fill_swirl_cap},
    {"swirl_shell", fill_swirl_shell},
}};

/// The painted presets (painted_preset_names()), of the kinds community meshes come in.
HairStyleSpec painted_preset(const std::string& name) {
  HairStyleSpec spec;
  spec.name = name;
  for (const PaintedPreset& painted : kPaintedPresets)
    if (name == painted.name) {
      painted.fill(spec);
      break;
    }
  return spec;
}

}  // namespace

HairStyleSpec preset(const std::string& name) {
  using Kind = ComponentSpec::Kind;
  HairStyleSpec spec;
  spec.name = name;
  ComponentSpec normal;
  normal.kind = Kind::normal;
  if (name == "long_straight" || name == "long_wavy") {
    normal.length_min_m = 0.30;
    normal.length_max_m = 0.42;
    normal.stream_count = 45;
    if (name == "long_wavy") normal.wave_amplitude_m = 0.01;
    spec.defects.normal_pieces_max = 3;
    spec.components = {normal};
  } else if (name == "medium_straight" || name == "medium_wavy") {
    normal.length_min_m = 0.14;
    normal.length_max_m = 0.22;
    normal.stream_count = 45;
    if (name == "medium_wavy") normal.wave_amplitude_m = 0.008;
    normal.wavelength_m = 0.06;
    spec.defects.normal_pieces_max = 2;
    spec.components = {normal};
  } else if (name == "short") {
    ComponentSpec cards;
    cards.kind = Kind::short_cards;
    cards.stream_count = 60;
    cards.length_min_m = 0.03;
    cards.length_max_m = 0.07;
    cards.strip_width_m = 0.025;
    spec.defects.rails_max = 3;
    spec.components = {cards};
  } else if (name == "short_cap") {
    // Like short02: the scalp covered by grids from the crown to the hairline, 3-4.5 mm
    // off it; the hairline ends most grids before their drawn length does (0.4-0.7 H).
    ComponentSpec cap;
    cap.kind = Kind::short_cap;
    cap.stream_count = 9;
    cap.length_min_m = 0.12;
    cap.length_max_m = 0.24;
    cap.strip_width_m = 0.07;
    cap.band_azimuth_deg = 180;  // the crown whorl, at the back of the top of the head
    cap.band_polar_deg = 20;
    cap.polar_min_deg = 3;  // roots 3-12 degrees from the whorl
    cap.polar_max_deg = 12;
    spec.defects.cap_rails = 6;
    spec.defects.scalp_lift_m = 0.003;
    spec.components = {cap};
  } else if (name == "ponytail") {
    ComponentSpec tail;
    tail.kind = Kind::ponytail;
    tail.stream_count = 10;
    tail.length_min_m = 0.35;
    tail.length_max_m = 0.45;
    tail.strip_width_m = 0.05;
    spec.components = {tail};
  } else if (name == "braid") {
    ComponentSpec braid;
    braid.kind = Kind::braid;
    braid.length_min_m = 0.25;
    braid.length_max_m = 0.32;
    braid.strip_width_m = 0.014;
    braid.azimuth_min_deg = -170;
    braid.azimuth_max_deg = 170;
    spec.components = {braid};
  } else if (name == "normal_braid") {
    ComponentSpec braid;
    braid.kind = Kind::braid;
    braid.length_min_m = 0.22;
    braid.length_max_m = 0.28;
    braid.strip_width_m = 0.014;
    braid.azimuth_min_deg = 120;
    braid.azimuth_max_deg = 180;
    braid.band_polar_deg = 80;
    normal.length_min_m = 0.18;
    normal.length_max_m = 0.26;
    normal.stream_count = 30;
    normal.azimuth_min_deg = -120;
    normal.azimuth_max_deg = 120;
    spec.defects.normal_pieces_max = 2;
    spec.components = {normal, braid};
  } else if (name == "two_braids") {
    ComponentSpec left;
    left.kind = Kind::braid;
    left.length_min_m = 0.22;
    left.length_max_m = 0.30;
    left.strip_width_m = 0.013;
    left.azimuth_min_deg = 0;
    left.azimuth_max_deg = 180;
    left.band_azimuth_deg = 120;
    left.band_polar_deg = 85;
    ComponentSpec right = left;
    right.azimuth_min_deg = -180;
    right.azimuth_max_deg = 0;
    right.band_azimuth_deg = -120;
    spec.components = {left, right};
  } else if (name == "half_up") {
    ComponentSpec tail;
    tail.kind = Kind::ponytail;
    tail.stream_count = 8;
    tail.polar_max_deg = 60;
    tail.band_polar_deg = 55;
    tail.length_min_m = 0.25;
    tail.length_max_m = 0.32;
    tail.strip_width_m = 0.05;
    tail.band_gap_m = 0.045;  // a large hidden gap at the band
    normal.polar_min_deg = 62;
    normal.stream_count = 25;
    normal.length_min_m = 0.18;
    normal.length_max_m = 0.26;
    spec.components = {tail, normal};
  } else if (std::find(painted_preset_names().begin(), painted_preset_names().end(), name) !=
             painted_preset_names().end()) {
    return painted_preset(name);
  } else {
    std::string known;
    for (const std::string& n : preset_names()) known += (known.empty() ? "" : ", ") + n;
    for (const std::string& n : painted_preset_names()) known += ", " + n;
    throw Error::usage("unknown preset '" + name + "'; presets: " + known);
  }
  return spec;
}

}  // namespace hair::synth
