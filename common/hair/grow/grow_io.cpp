#include "hair/grow/grow_io.h"

#include "hair/cluster/clustering_io.h"
#include "hair/cluster/typeify_io.h"
#include "hair/core/error.h"
#include "hair/extract/extract_io.h"
#include "hair/grow/card_surfaces.h"
#include "hair/h5/attribute.h"
#include "hair/h5/dataset.h"
#include "hair/h5/enum_dataset.h"
#include "hair/h5/schema.h"
#include "hair/h5/schema_validation.h"
#include "hair/h5/strand_set_io.h"

namespace hair {

GrowInput read_grow_input(const h5::File& extract, const h5::File& types,
                          const h5::File& clusters) {
  GrowInput input;
  ExtractedStrands extracted = read_extracted_strands(extract);
  input.source = extract.name();
  input.input_strands = std::move(extracted.strands);
  input.head_height_m = extracted.head_height_m;
  ExtractedBody body = read_extracted_body(extract);
  input.body_vertices = std::move(body.vertices);
  input.body_triangles = std::move(body.triangles);
  input.scalp_triangle = std::move(body.scalp_triangle);
  // The hair mesh, fanned into triangles, each with its face's group.
  input.hair_vertices = h5::read_matrix<float, 3>(extract, "/mesh/vertices");
  const auto face_offsets = h5::read_vector<int64_t>(extract, "/mesh/face_offsets");
  const auto face_group = h5::read_vector<int32_t>(extract, "/mesh/face_group");
  if (face_offsets.empty() || face_group.size() != face_offsets.size() - 1)
    throw Error::bad_dataset(extract.name(), "/mesh/face_group", "is not one group per face");
  fan_triangulation_with_groups(face_offsets,
                                h5::read_vector<int32_t>(extract, "/mesh/face_vertices"),
                                face_group, input.hair_triangles, input.hair_triangle_group);
  // Each triangle's painted axis: its face's, where the face's strokes are clear.
  const Points3f face_flow = h5::read_matrix<float, 3>(extract, "/mesh/face_flow");
  const auto coherence = h5::read_vector<float>(extract, "/mesh/face_flow_coherence");
  if (static_cast<size_t>(face_flow.rows()) != face_group.size() ||
      coherence.size() != face_group.size())
    throw Error::bad_dataset(extract.name(), "/mesh/face_flow", "is not one axis per face");
  input.hair_triangle_flow =
      fan_painted_flow(face_offsets, face_flow, coherence, kClearFlowCoherence);
  auto group_count = extracted.group_first_strand.size() - 1;

  TypedGroups typed = read_typed_groups(types);
  if (typed.type.size() != group_count)
    throw Error::other_model(types.name(), "/groups/type", typed.type.size(), "groups",
                             extract.name(), group_count);
  input.group_type = std::move(typed.type);

  GroupClusters grouped = read_group_clusters(clusters);
  if (grouped.cluster.size() != group_count)
    throw Error::other_model(clusters.name(), "/groups/cluster", grouped.cluster.size(), "groups",
                             extract.name(), group_count);
  for (int32_t cluster : grouped.cluster)
    if (cluster < 0)
      throw Error::bad_dataset(clusters.name(), "/groups/cluster", "a group has no cluster");
  for (int32_t cluster : grouped.cluster)
    if (static_cast<size_t>(cluster) >= grouped.starts_at_root.size())
      throw Error::bad_dataset(clusters.name(), "/clusters/starts_at_root",
                               "has fewer entries than there are clusters");
  input.group_cluster = std::move(grouped.cluster);
  input.cluster_starts_at_root = std::move(grouped.starts_at_root);
  return input;
}

const h5::EnumMembers& grow_rule_members() {
  static const h5::EnumMembers members = {
      {"root", 0}, {"field", 1}, {"input_strand", 2}, {"bridge", 3}};
  return members;
}

void write_strands_file(h5::File& file, const GrowResult& result, const GrowParams& params,
                        double head_height_m) {
  h5::write_schema_attributes(file, h5::Schema::find(kStrandsSchema));
  h5::write_string_attribute(file, "/", "unit", "m");
  h5::write_double_attribute(file, "/", "head_height_m", head_height_m);
  h5::write_int64_attribute(file, "/", "strand_count_requested", params.strand_count);
  h5::write_double_attribute(file, "/", "scalp_area_m2", result.scalp_area_m2);
  h5::write_double_attribute(file, "/", "root_spacing_m", result.root_spacing_m);
  h5::write_int64_attribute(file, "/", "scalp_triangles_used", result.scalp_triangles_used);
  h5::write_int64_attribute(file, "/", "points_pushed_out", result.points_pushed_out);
  h5::write_string_attribute(file, "/", "root_clusters_from",
                             result.roots_from_any_type ? "any_strand" : "root_type_strands");
  h5::write_strand_set(file, "/strands", result.strands);
  h5::write_enum_dataset(file, "/strands/point_rule", h5::enum_values(result.point_rule),
                         grow_rule_members());
  std::vector<int64_t> strand_count, field_voxels, seeded_voxels;
  for (const GrownCluster& cluster : result.clusters) {
    strand_count.push_back(cluster.strand_count);
    field_voxels.push_back(cluster.field_voxel_count);
    seeded_voxels.push_back(cluster.field_seeded_voxels);
  }
  h5::write_vector(file, "/clusters/strand_count", strand_count);
  h5::write_vector(file, "/clusters/field_voxel_count", field_voxels);
  h5::write_vector(file, "/clusters/field_seeded_voxel_count", seeded_voxels);
}

GrownStrands read_grown_strands(const h5::File& file) {
  h5::require_schema(file, kStrandsSchema);
  GrownStrands grown;
  grown.strands = h5::read_strand_set(file, "/strands");
  grown.head_height_m = h5::read_double_attribute(file, "/", "head_height_m");
  return grown;
}

}  // namespace hair
