#include "hair/synth/synth_io.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <type_traits>

#include "hair/core/error.h"
#include "hair/h5/attribute.h"
#include "hair/h5/dataset.h"
#include "hair/h5/enum_dataset.h"
#include "hair/h5/schema.h"
#include "hair/h5/schema_validation.h"
#include "hair/h5/strand_set_io.h"

namespace hair::synth {

namespace {

/// The members of an enum dataset, from the compiled-in schema (one place for names).
const h5::EnumMembers& members(const std::string& path) {
  return h5::Schema::find(kSynthTruthSchema).dataset(path).enum_members;
}

const char* kind_name(ComponentSpec::Kind kind) {
  switch (kind) {
    case ComponentSpec::Kind::normal:
      return "normal";
    case ComponentSpec::Kind::short_cards:
      return "short_cards";
    case ComponentSpec::Kind::ponytail:
      return "ponytail";
    case ComponentSpec::Kind::braid:
      return "braid";
    case ComponentSpec::Kind::short_cap:
      return "short_cap";
  }
  return "?";
}

}  // namespace

std::string obj_text(const SynthModel& model, double unit_scale, const std::string& mtl_file_name) {
  const PolyMesh& mesh = model.mesh;
  std::string text = fmt::format(
      "# hair-synth: preset {}, seed {}; {} patches, {} vertices, {} faces; units: {} m\n"
      "# Truth: the .truth.h5 file beside this one (schemas/synth_truth.json).\n",
      model.name, model.seed, model.patches.size(), mesh.vertex_count(), mesh.face_count(),
      unit_scale);
  text.reserve(static_cast<size_t>(mesh.vertex_count()) * 40 + mesh.face_vertices.size() * 40);
  const bool textured = mesh.has_materials() && !mtl_file_name.empty();
  if (textured) text += fmt::format("mtllib {}\n", mtl_file_name);
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v)
    text += fmt::format("v {:.6f} {:.6f} {:.6f}\n", mesh.vertices(v, 0) / unit_scale,
                        mesh.vertices(v, 1) / unit_scale, mesh.vertices(v, 2) / unit_scale);
  for (Eigen::Index c = 0; c < mesh.corner_uv.rows(); ++c)
    text += fmt::format("vt {:.6f} {:.6f}\n", mesh.corner_uv(c, 0), mesh.corner_uv(c, 1));
  for (size_t p = 0; p < model.patches.size(); ++p) {
    const SynthPatch& patch = model.patches[p];
    text += fmt::format("g patch{}\n", p);
    if (textured) text += fmt::format("usemtl {}\n", mesh.materials.front().name);
    for (int64_t f = patch.first_face; f < patch.first_face + patch.face_count; ++f) {
      text += "f";
      for (int64_t corner = mesh.face_offsets[static_cast<size_t>(f)];
           corner < mesh.face_offsets[static_cast<size_t>(f) + 1]; ++corner)
        text +=
            fmt::format(" {}/{}", mesh.face_vertices[static_cast<size_t>(corner)] + 1, corner + 1);
      text += "\n";
    }
  }
  return text;
}

std::string mtl_text(const SynthModel& model, const std::string& image_file_name) {
  std::string text =
      fmt::format("# hair-synth: preset {}, seed {}: the painted hair\n", model.name, model.seed);
  for (const MeshMaterial& material : model.mesh.materials)
    text += fmt::format("newmtl {}\nKd 1 1 1\nmap_Kd {}\nmap_d {}\n", material.name,
                        image_file_name, image_file_name);
  return text;
}

nlohmann::ordered_json spec_json(const HairStyleSpec& spec) {
  nlohmann::ordered_json json;
  json["name"] = spec.name;
  json["components"] = nlohmann::ordered_json::array();
  for (const ComponentSpec& c : spec.components) {
    nlohmann::ordered_json item;
    item["kind"] = kind_name(c.kind);
    item["stream_count"] = c.stream_count;
    item["length_min_m"] = c.length_min_m;
    item["length_max_m"] = c.length_max_m;
    item["wave_amplitude_m"] = c.wave_amplitude_m;
    item["wavelength_m"] = c.wavelength_m;
    item["strip_width_m"] = c.strip_width_m;
    item["azimuth_min_deg"] = c.azimuth_min_deg;
    item["azimuth_max_deg"] = c.azimuth_max_deg;
    item["polar_min_deg"] = c.polar_min_deg;
    item["polar_max_deg"] = c.polar_max_deg;
    item["band_azimuth_deg"] = c.band_azimuth_deg;
    item["band_polar_deg"] = c.band_polar_deg;
    item["braid_width_m"] = c.braid_width_m;
    item["braid_depth_m"] = c.braid_depth_m;
    item["braid_period_m"] = c.braid_period_m;
    item["band_gap_m"] = c.band_gap_m;
    item["swirl_min_deg"] = c.swirl_min_deg;
    item["swirl_max_deg"] = c.swirl_max_deg;
    item["one_piece_rings"] = c.one_piece_rings;
    item["one_piece_grid"] = c.one_piece_grid;
    item["grid_crown_hole_deg"] = c.grid_crown_hole_deg;
    item["bun_radius_m"] = c.bun_radius_m;
    item["ringlet_radius_m"] = c.ringlet_radius_m;
    item["ringlet_pitch_m"] = c.ringlet_pitch_m;
    item["hang_volume_m"] = c.hang_volume_m;
    item["rooted_under_volume"] = c.rooted_under_volume;
    item["tube_sides"] = c.tube_sides;
    item["folded_shell_thickness_m"] = c.folded_shell_thickness_m;
    item["cap_volume_m"] = c.cap_volume_m;
    item["cap_drape"] = c.cap_drape;
    item["braid_lift_m"] = c.braid_lift_m;
    item["braid_tip_width_share"] = c.braid_tip_width_share;
    item["braid_cards_per_lobe"] = c.braid_cards_per_lobe;
    json["components"].push_back(item);
  }
  const DefectSpec& d = spec.defects;
  json["defects"] = {{"rails_min", d.rails_min},
                     {"rails_max", d.rails_max},
                     {"cap_rails", d.cap_rails},
                     {"segment_length_m", d.segment_length_m},
                     {"normal_pieces_max", d.normal_pieces_max},
                     {"braid_piece_length_m", d.braid_piece_length_m},
                     {"gap_m", d.gap_m},
                     {"overlap_share", d.overlap_share},
                     {"overlap_m", d.overlap_m},
                     {"jitter_m", d.jitter_m},
                     {"triangulate_share", d.triangulate_share},
                     {"shorter_diagonal_share", d.shorter_diagonal_share},
                     {"reversed_share", d.reversed_share},
                     {"shuffled_share", d.shuffled_share},
                     {"scalp_lift_m", d.scalp_lift_m},
                     {"body_clearance_m", d.body_clearance_m},
                     {"tucked_share", d.tucked_share},
                     {"tuck_length_m", d.tuck_length_m},
                     {"tuck_depth_m", d.tuck_depth_m},
                     {"painted_texture", d.painted_texture},
                     {"painted_fade", d.painted_fade}};
  return json;
}

namespace {

/// Reads `json[key]` into `value` if present, as the type of `value`.
template <class T>
void read_key(const nlohmann::json& json, const std::string& where, const char* key, T& value) {
  auto found = json.find(key);
  if (found == json.end()) return;
  bool ok = std::is_same_v<T, std::string> ? found->is_string()
            : std::is_same_v<T, bool>      ? found->is_boolean()
            : std::is_integral_v<T>        ? found->is_number_integer()
                                           : found->is_number();
  if (!ok)
    throw Error::usage(where + key + ": expected a " +
                       (std::is_same_v<T, std::string> ? "string"
                        : std::is_same_v<T, bool>      ? "true or false"
                        : std::is_integral_v<T>        ? "whole number"
                                                       : "number") +
                       ", found " + found->dump());
  value = found->get<T>();
}

/// Refuses keys of `json` outside `known`.
void require_known_keys(const nlohmann::json& json, const std::string& where,
                        const std::vector<std::string>& known) {
  if (!json.is_object()) throw Error::usage(where + ": expected an object");
  for (const auto& item : json.items())
    if (std::find(known.begin(), known.end(), item.key()) == known.end())
      throw Error::usage("unknown key '" + where + item.key() + "' in the specification");
}

void require_range(const std::string& name, double value, double lo, double hi) {
  if (!(value >= lo && value <= hi))
    throw Error::usage(fmt::format("{} = {}: expected {} to {}", name, value, lo, hi));
}

/// The component at `where` ("components[i].") of a specification: its keys checked, its
/// kind read, then its knobs, each left at its default when absent.
ComponentSpec component_from_json(const nlohmann::json& item, const std::string& where) {
  require_known_keys(item, where,
                     {"kind",
                      "stream_count",
                      "length_min_m",
                      "length_max_m",
                      "wave_amplitude_m",
                      "wavelength_m",
                      "strip_width_m",
                      "azimuth_min_deg",
                      "azimuth_max_deg",
                      "polar_min_deg",
                      "polar_max_deg",
                      "band_azimuth_deg",
                      "band_polar_deg",
                      "braid_width_m",
                      "braid_depth_m",
                      "braid_period_m",
                      "band_gap_m",
                      "swirl_min_deg",
                      "swirl_max_deg",
                      "one_piece_rings",
                      "one_piece_grid",
                      "grid_crown_hole_deg",
                      "bun_radius_m",
                      "ringlet_radius_m",
                      "ringlet_pitch_m",
                      "tube_sides",
                      "folded_shell_thickness_m",
                      "cap_volume_m",
                      "cap_drape",
                      "hang_volume_m",
                      "rooted_under_volume",
                      "braid_lift_m",
                      "braid_tip_width_share",
                      "braid_cards_per_lobe"});
  ComponentSpec c;
  std::string kind = "normal";
  read_key(item, where, "kind", kind);
  if (kind == "normal")
    c.kind = ComponentSpec::Kind::normal;
  else if (kind == "short_cards")
    c.kind = ComponentSpec::Kind::short_cards;
  else if (kind == "ponytail")
    c.kind = ComponentSpec::Kind::ponytail;
  else if (kind == "braid")
    c.kind = ComponentSpec::Kind::braid;
  else if (kind == "short_cap")
    c.kind = ComponentSpec::Kind::short_cap;
  else
    throw Error::usage(where + "kind = \"" + kind +
                       "\": expected normal, short_cards, short_cap, ponytail or braid");
  read_key(item, where, "stream_count", c.stream_count);
  read_key(item, where, "length_min_m", c.length_min_m);
  read_key(item, where, "length_max_m", c.length_max_m);
  read_key(item, where, "wave_amplitude_m", c.wave_amplitude_m);
  read_key(item, where, "wavelength_m", c.wavelength_m);
  read_key(item, where, "strip_width_m", c.strip_width_m);
  read_key(item, where, "azimuth_min_deg", c.azimuth_min_deg);
  read_key(item, where, "azimuth_max_deg", c.azimuth_max_deg);
  read_key(item, where, "polar_min_deg", c.polar_min_deg);
  read_key(item, where, "polar_max_deg", c.polar_max_deg);
  read_key(item, where, "band_azimuth_deg", c.band_azimuth_deg);
  read_key(item, where, "band_polar_deg", c.band_polar_deg);
  read_key(item, where, "braid_width_m", c.braid_width_m);
  read_key(item, where, "braid_depth_m", c.braid_depth_m);
  read_key(item, where, "braid_period_m", c.braid_period_m);
  read_key(item, where, "band_gap_m", c.band_gap_m);
  read_key(item, where, "swirl_min_deg", c.swirl_min_deg);
  read_key(item, where, "swirl_max_deg", c.swirl_max_deg);
  read_key(item, where, "one_piece_rings", c.one_piece_rings);
  read_key(item, where, "one_piece_grid", c.one_piece_grid);
  read_key(item, where, "grid_crown_hole_deg", c.grid_crown_hole_deg);
  read_key(item, where, "bun_radius_m", c.bun_radius_m);
  read_key(item, where, "ringlet_radius_m", c.ringlet_radius_m);
  read_key(item, where, "ringlet_pitch_m", c.ringlet_pitch_m);
  read_key(item, where, "tube_sides", c.tube_sides);
  read_key(item, where, "folded_shell_thickness_m", c.folded_shell_thickness_m);
  read_key(item, where, "cap_volume_m", c.cap_volume_m);
  read_key(item, where, "hang_volume_m", c.hang_volume_m);
  read_key(item, where, "rooted_under_volume", c.rooted_under_volume);
  read_key(item, where, "cap_drape", c.cap_drape);
  read_key(item, where, "braid_lift_m", c.braid_lift_m);
  read_key(item, where, "braid_tip_width_share", c.braid_tip_width_share);
  read_key(item, where, "braid_cards_per_lobe", c.braid_cards_per_lobe);
  return c;
}

/// Reads the specification's defects, `item`, into `d`: its keys checked, then each knob
/// present.
void read_defects(const nlohmann::json& item, DefectSpec& d) {
  const std::string where = "defects.";
  require_known_keys(item, where,
                     {"rails_min",
                      "rails_max",
                      "cap_rails",
                      "segment_length_m",
                      "normal_pieces_max",
                      "braid_piece_length_m",
                      "gap_m",
                      "overlap_share",
                      "overlap_m",
                      "jitter_m",
                      "triangulate_share",
                      "shorter_diagonal_share",
                      "reversed_share",
                      "shuffled_share",
                      "scalp_lift_m",
                      "body_clearance_m",
                      "tucked_share",
                      "tuck_length_m",
                      "tuck_depth_m",
                      "painted_texture",
                      "painted_fade"});
  read_key(item, where, "rails_min", d.rails_min);
  read_key(item, where, "rails_max", d.rails_max);
  read_key(item, where, "cap_rails", d.cap_rails);
  read_key(item, where, "segment_length_m", d.segment_length_m);
  read_key(item, where, "normal_pieces_max", d.normal_pieces_max);
  read_key(item, where, "braid_piece_length_m", d.braid_piece_length_m);
  read_key(item, where, "gap_m", d.gap_m);
  read_key(item, where, "overlap_share", d.overlap_share);
  read_key(item, where, "overlap_m", d.overlap_m);
  read_key(item, where, "jitter_m", d.jitter_m);
  read_key(item, where, "triangulate_share", d.triangulate_share);
  read_key(item, where, "shorter_diagonal_share", d.shorter_diagonal_share);
  read_key(item, where, "reversed_share", d.reversed_share);
  read_key(item, where, "shuffled_share", d.shuffled_share);
  read_key(item, where, "scalp_lift_m", d.scalp_lift_m);
  read_key(item, where, "body_clearance_m", d.body_clearance_m);
  read_key(item, where, "tucked_share", d.tucked_share);
  read_key(item, where, "tuck_length_m", d.tuck_length_m);
  read_key(item, where, "tuck_depth_m", d.tuck_depth_m);
  read_key(item, where, "painted_texture", d.painted_texture);
  read_key(item, where, "painted_fade", d.painted_fade);
}

}  // namespace

HairStyleSpec spec_from_json(const nlohmann::json& json) {
  require_known_keys(json, "", {"name", "components", "defects"});
  HairStyleSpec spec;
  read_key(json, "", "name", spec.name);
  if (json.contains("components")) {
    if (!json["components"].is_array()) throw Error::usage("components: expected an array");
    for (size_t i = 0; i < json["components"].size(); ++i)
      spec.components.push_back(
          component_from_json(json["components"][i], fmt::format("components[{}].", i)));
  }
  if (json.contains("defects")) read_defects(json["defects"], spec.defects);
  check_spec(spec);
  return spec;
}

void check_spec(const HairStyleSpec& spec) {
  if (spec.components.empty()) throw Error::usage("components: expected at least one");
  for (size_t i = 0; i < spec.components.size(); ++i) {
    const ComponentSpec& c = spec.components[i];
    std::string where = fmt::format("components[{}].", i);
    require_range(where + "stream_count", c.stream_count, 1, 2000);
    require_range(where + "length_min_m", c.length_min_m, 0.01, 2.0);
    require_range(where + "length_max_m", c.length_max_m, c.length_min_m, 2.0);
    require_range(where + "wave_amplitude_m", c.wave_amplitude_m, 0, 0.1);
    require_range(where + "wavelength_m", c.wavelength_m, 0.005, 1.0);
    require_range(where + "strip_width_m", c.strip_width_m, 0.002, 0.2);
    require_range(where + "azimuth_min_deg", c.azimuth_min_deg, -180, 180);
    require_range(where + "azimuth_max_deg", c.azimuth_max_deg, c.azimuth_min_deg, 180);
    require_range(where + "polar_min_deg", c.polar_min_deg, 0, 180);
    require_range(where + "polar_max_deg", c.polar_max_deg, c.polar_min_deg, 180);
    require_range(where + "band_azimuth_deg", c.band_azimuth_deg, -180, 180);
    require_range(where + "band_polar_deg", c.band_polar_deg, 0, 180);
    require_range(where + "braid_width_m", c.braid_width_m, 0, 0.1);
    require_range(where + "braid_depth_m", c.braid_depth_m, 0, 0.1);
    require_range(where + "braid_period_m", c.braid_period_m, 0.01, 1.0);
    require_range(where + "band_gap_m", c.band_gap_m, 0, 0.2);
    require_range(where + "swirl_max_deg", c.swirl_max_deg, 0, 120);
    require_range(where + "swirl_min_deg", c.swirl_min_deg, 0, c.swirl_max_deg);
    if (c.one_piece_rings && c.one_piece_grid)
      throw Error::usage(where + "one_piece_rings and one_piece_grid: a cap is meshed one way");
    require_range(where + "grid_crown_hole_deg", c.grid_crown_hole_deg, 0, 90);
    require_range(where + "bun_radius_m", c.bun_radius_m, 0, 0.1);
    require_range(where + "ringlet_radius_m", c.ringlet_radius_m, 0, 0.05);
    require_range(where + "ringlet_pitch_m", c.ringlet_pitch_m, 0.005, 0.5);
    require_range(where + "cap_volume_m", c.cap_volume_m, 0, 0.1);
    require_range(where + "hang_volume_m", c.hang_volume_m, 0, 0.1);
    require_range(where + "braid_lift_m", c.braid_lift_m, 0, 0.1);
    require_range(where + "braid_tip_width_share", c.braid_tip_width_share, 0.1, 1.0);
    require_range(where + "braid_cards_per_lobe", c.braid_cards_per_lobe, 1, 12);
    if (c.tube_sides != 0) require_range(where + "tube_sides", c.tube_sides, 3, 32);
    require_range(where + "folded_shell_thickness_m", c.folded_shell_thickness_m, 0, 0.1);
    if (c.folded_shell_thickness_m > 0 && c.tube_sides > 0)
      throw Error::usage(where + "folded_shell_thickness_m and tube_sides: a piece is meshed one way");
    if (c.rooted_under_volume && c.kind != ComponentSpec::Kind::normal)
      throw Error::usage(where + "rooted_under_volume: for normal hair only (kind \"normal\")");
  }
  const DefectSpec& d = spec.defects;
  require_range("defects.rails_min", d.rails_min, 2, 8);
  require_range("defects.rails_max", d.rails_max, d.rails_min, 8);
  require_range("defects.cap_rails", d.cap_rails, 2, 16);
  require_range("defects.segment_length_m", d.segment_length_m, 0.001, 0.1);
  require_range("defects.normal_pieces_max", d.normal_pieces_max, 1, 20);
  require_range("defects.braid_piece_length_m", d.braid_piece_length_m, 0.005, 0.2);
  require_range("defects.gap_m", d.gap_m, -0.05, 0.1);
  require_range("defects.overlap_share", d.overlap_share, 0, 1);
  require_range("defects.overlap_m", d.overlap_m, 0, 0.05);
  require_range("defects.jitter_m", d.jitter_m, 0, 0.01);
  require_range("defects.triangulate_share", d.triangulate_share, 0, 1);
  require_range("defects.shorter_diagonal_share", d.shorter_diagonal_share, 0, 1);
  require_range("defects.reversed_share", d.reversed_share, 0, 1);
  require_range("defects.shuffled_share", d.shuffled_share, 0, 1 - d.reversed_share);
  require_range("defects.scalp_lift_m", d.scalp_lift_m, 0, 0.05);
  require_range("defects.body_clearance_m", d.body_clearance_m, 0.001, 0.05);
  require_range("defects.tucked_share", d.tucked_share, 0, 1);
  require_range("defects.tuck_length_m", d.tuck_length_m, 0.002, 0.1);
  require_range("defects.tuck_depth_m", d.tuck_depth_m, 0, 0.05);
}

void write_truth_file(h5::File& file, const SynthModel& model, double unit_scale,
                      const std::string& mesh_file_name) {
  h5::write_schema_attributes(file, h5::Schema::find(kSynthTruthSchema));
  h5::write_string_attribute(file, "/", "unit", "m");
  h5::write_string_attribute(file, "/", "up_axis", "+Y");
  h5::write_double_attribute(file, "/", "unit_scale", unit_scale);
  h5::write_string_attribute(file, "/", "mesh_file", mesh_file_name);
  h5::write_string_attribute(file, "/", "preset", model.name);
  h5::write_int64_attribute(file, "/", "seed", model.seed);

  std::vector<int32_t> stream, index_in_stream, rails;
  std::vector<GroupType> type;
  std::vector<HairStyle> style;
  std::vector<VertexOrder> order;
  std::vector<uint8_t> triangulated;
  std::vector<int64_t> first_vertex{0}, first_face{0};
  Eigen::Matrix<float, Eigen::Dynamic, 2, Eigen::RowMajor> along(
      static_cast<Eigen::Index>(model.patches.size()), 2);
  for (size_t p = 0; p < model.patches.size(); ++p) {
    const SynthPatch& patch = model.patches[p];
    stream.push_back(patch.stream);
    index_in_stream.push_back(patch.index_in_stream);
    rails.push_back(patch.rails);
    type.push_back(patch.type);
    style.push_back(patch.style);
    order.push_back(patch.order);
    triangulated.push_back(patch.triangulated ? 1 : 0);
    first_vertex.push_back(patch.first_vertex + patch.vertex_count);
    first_face.push_back(patch.first_face + patch.face_count);
    along(static_cast<Eigen::Index>(p), 0) = static_cast<float>(patch.start_m);
    along(static_cast<Eigen::Index>(p), 1) = static_cast<float>(patch.end_m);
  }
  h5::write_vector(file, "/patches/stream", stream);
  h5::write_vector(file, "/patches/index_in_stream", index_in_stream);
  h5::write_enum_dataset(file, "/patches/group_type", h5::enum_values(type),
                         members("/patches/group_type"));
  h5::write_enum_dataset(file, "/patches/style", h5::enum_values(style), members("/patches/style"));
  h5::write_enum_dataset(file, "/patches/vertex_order", h5::enum_values(order),
                         members("/patches/vertex_order"));
  h5::write_vector(file, "/patches/triangulated", triangulated);
  h5::write_vector(file, "/patches/rails", rails);
  h5::write_vector(file, "/patches/first_vertex", first_vertex);
  h5::write_vector(file, "/patches/first_face", first_face);
  h5::write_matrix(file, "/patches/along_range", along);
  h5::write_vector(file, "/mesh/vertex_along", model.vertex_along_m);

  h5::write_strand_set(file, "/streams/centre", model.stream_centres);
  h5::write_enum_dataset(file, "/streams/style", h5::enum_values(model.stream_style),
                         members("/streams/style"));
  h5::write_vector(file, "/streams/component", model.stream_component);
  h5::write_strand_set(file, "/strands", model.strands);
  h5::write_enum_dataset(file, "/strands/point_style", h5::enum_values(model.strand_point_style),
                         members("/strands/point_style"));
}

std::array<int, 4> streams_by_style(const SynthModel& model) {
  std::array<int, 4> counts{};
  for (HairStyle style : model.stream_style) ++counts[static_cast<size_t>(style)];
  return counts;
}

}  // namespace hair::synth
