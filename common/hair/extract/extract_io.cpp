#include "hair/extract/extract_io.h"

#include "hair/h5/attribute.h"
#include "hair/h5/dataset.h"
#include "hair/h5/enum_dataset.h"
#include "hair/h5/schema.h"
#include "hair/h5/schema_validation.h"
#include "hair/h5/strand_set_io.h"

namespace hair {

const h5::EnumMembers& patch_kind_members() {
  static const h5::EnumMembers members = {
      {"strip", 0}, {"grid", 1}, {"tube", 2}, {"cap", 3}, {"triangle_soup", 4}};
  return members;
}

const h5::EnumMembers& orientation_rule_members() {
  static const h5::EnumMembers members = {{"vertex_order", 0}, {"scalp_distance", 1},
                                          {"continuation", 2}, {"uv", 3},
                                          {"height", 4},       {"parting", 5},
                                          {"alpha_fade", 6}};
  return members;
}

void write_extract_file(h5::File& file, const ExtractResult& result, const ExtractParams& params) {
  h5::write_schema_attributes(file, h5::Schema::find(kExtractSchema));
  h5::write_string_attribute(file, "/", "unit", "m");
  h5::write_string_attribute(file, "/", "up_axis", "+Y");
  h5::write_double_attribute(file, "/", "unit_scale", params.unit_scale);
  h5::write_double_attribute(file, "/", "head_height_m", result.head.head_height);
  h5::write_double_attribute(file, "/", "head_top_y_m", result.head.head_top_y);
  h5::write_double_attribute(file, "/", "neck_y_m", result.head.neck_y);

  h5::write_strand_set(file, "/strands", result.strands);

  h5::write_enum_dataset(file, "/groups/patch_kind", h5::enum_values(result.group_kind),
                         patch_kind_members());
  h5::write_enum_dataset(file, "/groups/orientation_rule", h5::enum_values(result.group_rule),
                         orientation_rule_members());
  h5::write_vector(file, "/groups/orientation_confidence", result.group_confidence);
  h5::write_vector(file, "/groups/first_strand", result.group_first_strand);
  h5::write_vector(file, "/groups/face_count", result.group_face_count);

  const PolyMesh& mesh = result.hair_mesh;
  h5::write_matrix(file, "/mesh/vertices", mesh.vertices);
  h5::write_vector(file, "/mesh/face_offsets", mesh.face_offsets);
  h5::write_vector(file, "/mesh/face_vertices", mesh.face_vertices);
  h5::write_vector(file, "/mesh/face_group", result.face_group);
  if (mesh.has_uv()) h5::write_matrix(file, "/mesh/corner_uv", mesh.corner_uv);
  const PaintedFlow& flow = result.painted_flow;
  const auto faces = static_cast<size_t>(mesh.face_count());
  Points3f face_flow = Points3f::Zero(mesh.face_count(), 3);
  std::vector<float> coherence(faces, 0.0f), alpha_fall(faces, 0.0f);
  if (flow.direction.size() == faces) {
    for (size_t f = 0; f < faces; ++f) face_flow.row(static_cast<Eigen::Index>(f)) = flow.direction[f].transpose();
    coherence = flow.coherence;
    alpha_fall = flow.alpha_fall;
  }
  h5::write_matrix(file, "/mesh/face_flow", face_flow);
  h5::write_vector(file, "/mesh/face_flow_coherence", coherence);
  h5::write_vector(file, "/mesh/face_flow_alpha_fall", alpha_fall);

  h5::write_matrix(file, "/body/vertices", result.body_vertices);
  h5::write_matrix(file, "/body/triangles", result.body_triangles);
  h5::write_vector(file, "/body/scalp_triangle", result.scalp_triangle);
}

ExtractedBody read_extracted_body(const h5::File& extract) {
  h5::require_schema(extract, kExtractSchema);
  ExtractedBody body;
  body.vertices = h5::read_matrix<float, 3>(extract, "/body/vertices");
  body.triangles = h5::read_matrix<int32_t, 3>(extract, "/body/triangles");
  body.scalp_triangle = h5::read_vector<uint8_t>(extract, "/body/scalp_triangle");
  return body;
}

ExtractedPaint read_extracted_paint(const h5::File& extract) {
  h5::require_schema(extract, kExtractSchema);
  ExtractedPaint paint;
  paint.mesh.vertices = h5::read_matrix<float, 3>(extract, "/mesh/vertices");
  paint.mesh.face_offsets = h5::read_vector<int64_t>(extract, "/mesh/face_offsets");
  paint.mesh.face_vertices = h5::read_vector<int32_t>(extract, "/mesh/face_vertices");
  Points3f direction = h5::read_matrix<float, 3>(extract, "/mesh/face_flow");
  for (Eigen::Index f = 0; f < direction.rows(); ++f)
    paint.flow.direction.emplace_back(direction.row(f).transpose());
  paint.flow.coherence = h5::read_vector<float>(extract, "/mesh/face_flow_coherence");
  paint.flow.alpha_fall = h5::read_vector<float>(extract, "/mesh/face_flow_alpha_fall");
  return paint;
}

}  // namespace hair
