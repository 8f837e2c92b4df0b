#include "hair/cluster/typeify_io.h"

#include "hair/extract/extract_io.h"
#include "hair/h5/attribute.h"
#include "hair/h5/dataset.h"
#include "hair/h5/schema.h"
#include "hair/h5/schema_validation.h"
#include "hair/h5/strand_set_io.h"

namespace hair {
namespace {

/// CSR offsets and values of a list of lists.
void write_lists(h5::File& file, const std::string& offsets_path, const std::string& values_path,
                 const std::vector<std::vector<int32_t>>& lists) {
  std::vector<int64_t> offsets{0};
  std::vector<int32_t> values;
  for (const auto& list : lists) {
    values.insert(values.end(), list.begin(), list.end());
    offsets.push_back(static_cast<int64_t>(values.size()));
  }
  h5::write_vector(file, offsets_path, offsets);
  h5::write_vector(file, values_path, values);
}

}  // namespace

ExtractedStrands read_extracted_strands(const h5::File& file) {
  h5::require_schema(file, kExtractSchema);
  ExtractedStrands extracted;
  extracted.strands = h5::read_strand_set(file, "/strands");
  extracted.group_first_strand = h5::read_vector<int32_t>(file, "/groups/first_strand");
  extracted.head_height_m = h5::read_double_attribute(file, "/", "head_height_m");
  return extracted;
}

const h5::EnumMembers& group_type_members() {
  static const h5::EnumMembers members = {
      {"root_free", 0}, {"root_connected", 1}, {"middle", 2}, {"tip", 3}};
  return members;
}

void write_types_file(h5::File& file, const GroupTypes& types, double head_height_m,
                      double neighbour_distance_m) {
  h5::write_schema_attributes(file, h5::Schema::find(kTypesSchema));
  h5::write_string_attribute(file, "/", "unit", "m");
  h5::write_double_attribute(file, "/", "head_height_m", head_height_m);
  h5::write_double_attribute(file, "/", "neighbour_distance_m", neighbour_distance_m);
  h5::write_double_attribute(file, "/", "connect_angle_threshold_rad",
                             types.connect_angle_threshold_rad);
  h5::write_string_attribute(file, "/", "connect_threshold_source",
                             types.threshold_from_distribution ? "distribution" : "parameter");
  h5::write_enum_dataset(file, "/groups/type", h5::enum_values(types.type), group_type_members());
  if (types.start_scalp_distance_m.size() != types.type.size())
    throw Error::bad_input(file.name(), "every group needs its distance to the scalp");
  h5::write_vector(file, "/groups/start_scalp_distance_m", types.start_scalp_distance_m);
  StrandSet centres = types.centre_strands;
  centres.strand_attributes.clear();
  centres.point_attributes.clear();
  h5::write_matrix(file, "/centre_strands/points", centres.points);
  h5::write_vector(file, "/centre_strands/offsets", centres.offsets);
  write_lists(file, "/neighbours/before_offsets", "/neighbours/before", types.before);
  write_lists(file, "/neighbours/after_offsets", "/neighbours/after", types.after);
  std::vector<float> angles;
  for (const auto& list : types.after_angle_rad)
    angles.insert(angles.end(), list.begin(), list.end());
  h5::write_vector(file, "/neighbours/after_angle_rad", angles);
}

}  // namespace hair
