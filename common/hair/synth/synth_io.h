#pragma once
// Writing a synthetic hairstyle (synth_model.h): the mesh as Wavefront OBJ in source
// units, its truth as HDF5 (schemas/synth_truth.json).

#include <nlohmann/json.hpp>
#include <string>

#include "hair/h5/file.h"
#include "hair/synth/synth_model.h"

namespace hair::synth {

/// Name of the truth file's schema.
inline constexpr const char* kSynthTruthSchema = "hairstyle.synth_truth";

/// The mesh as OBJ text: `v` in source units (metres / unit_scale) in the mesh's vertex
/// order, one `vt` per face corner, `f v/vt`; a `g` line before each patch. A painted
/// mesh (DefectSpec::painted_texture) names `mtl_file_name` (mtllib) and its material
/// (usemtl) when that is given; see mtl_text().
std::string obj_text(const SynthModel& model, double unit_scale,
                     const std::string& mtl_file_name = "");

/// The MTL of a painted mesh: its material with `map_Kd` (and `map_d`) `image_file_name`.
std::string mtl_text(const SynthModel& model, const std::string& image_file_name);

/// The specification as JSON (the truth file's `parameters` attribute and the manifest).
nlohmann::ordered_json spec_json(const HairStyleSpec& spec);

/// The specification read back from spec_json()'s form: keys left out keep their
/// defaults (ComponentSpec{}, DefectSpec{}); an unknown key, a value of the wrong type or
/// out of range is a usage error naming it ("defects.rails_max = 9: expected 2..8").
HairStyleSpec spec_from_json(const nlohmann::json& json);

/// Throws hair::Error (usage) naming the first knob out of range.
void check_spec(const HairStyleSpec& spec);

/// Writes every dataset and attribute of the truth file but the provenance ones.
void write_truth_file(h5::File& file, const SynthModel& model, double unit_scale,
                      const std::string& mesh_file_name);

/// Streams of the model per style: {normal, fixed, short, braided}.
std::array<int, 4> streams_by_style(const SynthModel& model);

}  // namespace hair::synth
