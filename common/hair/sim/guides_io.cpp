#include "hair/sim/guides_io.h"

#include "hair/extract/extract_io.h"
#include "hair/grow/grow_io.h"
#include "hair/h5/attribute.h"
#include "hair/h5/dataset.h"
#include "hair/h5/schema.h"
#include "hair/h5/schema_validation.h"
#include "hair/style/style_io.h"

namespace hair {

SimulationScene read_simulation_scene(const h5::File& extract, const h5::File& strands,
                                      const h5::File& styles) {
  SimulationScene scene;
  ExtractedBody body = read_extracted_body(extract);
  scene.body_vertices = std::move(body.vertices);
  scene.body_triangles = std::move(body.triangles);
  GrownStrands grown = read_grown_strands(strands);
  scene.cluster_style = read_cluster_styles(styles);
  auto grown_clusters = h5::read_vector<int64_t>(strands, "/clusters/strand_count").size();
  if (grown_clusters != scene.cluster_style.size())
    throw Error::other_model(styles.name(), "/clusters/style", scene.cluster_style.size(),
                             "clusters", strands.name(), grown_clusters);
  const auto& point_cluster =
      std::get<std::vector<int32_t>>(grown.strands.point_attributes.at("cluster"));
  for (int32_t cluster : point_cluster) {
    if (cluster < 0 || static_cast<size_t>(cluster) >= grown_clusters)
      throw Error::bad_dataset(
          strands.name(), "/strands/point_attributes/cluster",
          "names cluster " + std::to_string(cluster) + " of " + std::to_string(grown_clusters));
  }
  scene.strands = std::move(grown.strands);
  scene.head_height_m = grown.head_height_m;
  scene.source = strands.name();
  return scene;
}

const h5::EnumMembers& guide_kind_members() {
  static const h5::EnumMembers members = {{"strand", 0}, {"wisp_centre", 1}};
  return members;
}

void write_guides_file(h5::File& file, const SimulationResult& result, const GuidesFileInfo& info) {
  h5::write_schema_attributes(file, h5::Schema::find(kGuidesSchema));
  h5::write_string_attribute(file, "/", "unit", "m");
  h5::write_double_attribute(file, "/", "head_height_m", info.head_height_m);
  h5::write_double_attribute(file, "/", "fps", result.fps);
  h5::write_int64_attribute(file, "/", "substeps", info.substeps);
  h5::write_string_attribute(file, "/", "motion", info.motion);
  h5::write_int64_attribute(file, "/", "settled_at_frame", result.settled_at_frame);
  h5::write_int64_attribute(file, "/", "fixed_strand_count", result.fixed_strands);
  h5::write_int64_attribute(file, "/", "braided_strand_count", result.braided_strands);
  if (info.guide_ms_per_frame >= 0)
    h5::write_double_attribute(file, "/", "guide_ms_per_frame", info.guide_ms_per_frame);
  if (info.setup_s >= 0) h5::write_double_attribute(file, "/", "setup_s", info.setup_s);

  // Guides.
  std::vector<int64_t> offsets{0}, strand, anchor_point;
  std::vector<int32_t> cluster, ghost_count, anchor_count;
  std::vector<int8_t> kind, style;
  std::vector<double> mass_scale;
  std::vector<float> rest;
  for (const SimulatedGuide& guide : result.guides) {
    offsets.push_back(offsets.back() + static_cast<int64_t>(guide.rest_m.size()));
    for (const Eigen::Vector3d& p : guide.rest_m)
      for (int axis = 0; axis < 3; ++axis) rest.push_back(static_cast<float>(p[axis]));
    kind.push_back(static_cast<int8_t>(guide.kind));
    strand.push_back(guide.strand);
    anchor_point.push_back(guide.anchor_point);
    cluster.push_back(guide.cluster);
    style.push_back(static_cast<int8_t>(guide.style));
    mass_scale.push_back(guide.mass_scale);
    ghost_count.push_back(guide.ghost_count);
    anchor_count.push_back(guide.anchor_count);
  }
  const int64_t points = offsets.back();
  h5::write_vector(file, "/guides/offsets", offsets);
  h5::write_dataset(file, "/guides/rest_points", rest, {points, 3});
  h5::write_enum_dataset(file, "/guides/kind", kind, guide_kind_members());
  h5::write_vector(file, "/guides/strand", strand);
  h5::write_vector(file, "/guides/anchor_point", anchor_point);
  h5::write_vector(file, "/guides/cluster", cluster);
  h5::write_enum_dataset(file, "/guides/style", style, style_members());
  h5::write_vector(file, "/guides/mass_scale", mass_scale);
  h5::write_vector(file, "/guides/ghost_count", ghost_count);
  h5::write_vector(file, "/guides/anchor_count", anchor_count);

  // Clusters.
  h5::write_enum_dataset(file, "/clusters/style", info.cluster_style, style_members());
  h5::write_enum_dataset(file, "/clusters/simulated_style", result.simulated_style,
                         style_members());
  h5::write_vector(file, "/clusters/candidate_count", result.plan.cluster_candidates);
  h5::write_vector(file, "/clusters/guide_count", result.plan.cluster_guides);

  // Frames, one chunk per frame.
  const int64_t frames = result.frame_count;
  std::vector<double> time_s, kinetic, elastic, gravity, stretch, penetration, inside, speed;
  std::vector<uint8_t> integrated;
  std::vector<double> rotation, translation;
  for (int64_t f = 0; f < frames; ++f) {
    const FrameStatistics& stats = result.statistics[static_cast<size_t>(f)];
    time_s.push_back(stats.time_s);
    kinetic.push_back(stats.kinetic_energy_j);
    elastic.push_back(stats.elastic_energy_j);
    gravity.push_back(stats.gravity_energy_j);
    stretch.push_back(stats.max_stretch);
    penetration.push_back(stats.max_penetration_m);
    inside.push_back(stats.inside_fraction);
    speed.push_back(stats.max_speed_m_s);
    integrated.push_back(f > 0 && stats.integrated ? 1 : 0);
    const RigidTransform& head = result.head[static_cast<size_t>(f)];
    for (double v : {head.rotation.w(), head.rotation.x(), head.rotation.y(), head.rotation.z()})
      rotation.push_back(v);
    for (int axis = 0; axis < 3; ++axis) translation.push_back(head.translation_m[axis]);
  }
  h5::DatasetOptions per_frame;
  if (points > 0) per_frame.chunk_shape = {1, points, 3};
  h5::write_dataset(file, "/frames/guide_points", result.guide_points_m, {frames, points, 3},
                    per_frame);
  h5::write_vector(file, "/frames/time_s", time_s);
  h5::write_dataset(file, "/frames/head_rotation", rotation, {frames, 4});
  h5::write_dataset(file, "/frames/head_translation_m", translation, {frames, 3});
  h5::write_vector(file, "/frames/integrated", integrated);
  h5::write_vector(file, "/frames/kinetic_energy_j", kinetic);
  h5::write_vector(file, "/frames/elastic_energy_j", elastic);
  h5::write_vector(file, "/frames/gravity_energy_j", gravity);
  h5::write_vector(file, "/frames/max_stretch", stretch);
  h5::write_vector(file, "/frames/max_penetration_m", penetration);
  h5::write_vector(file, "/frames/inside_fraction", inside);
  h5::write_vector(file, "/frames/max_speed_m_s", speed);

  // Wisps.
  h5::write_vector(file, "/wisps/guide", result.wisp_guide);
  h5::write_vector(file, "/wisps/tetrahedron_offsets", result.wisp_tetrahedron_offset);
  const int64_t tetrahedra = result.wisp_tetrahedron_offset.back();
  h5::DatasetOptions wisp_frame;
  if (tetrahedra > 0) wisp_frame.chunk_shape = {1, tetrahedra, 7};
  h5::write_dataset(file, "/wisps/frames", result.wisp_frames, {frames, tetrahedra, 7}, wisp_frame);
  std::vector<int64_t> binding_point;
  std::vector<int32_t> binding_wisp, binding_tetrahedron;
  std::vector<float> binding_local;
  for (const WispBinding& binding : result.wisp_bindings) {
    binding_point.push_back(binding.point);
    binding_wisp.push_back(binding.wisp);
    binding_tetrahedron.push_back(binding.tetrahedron);
    for (int axis = 0; axis < 3; ++axis) binding_local.push_back(binding.local_m[axis]);
  }
  h5::write_vector(file, "/wisps/binding_point", binding_point);
  h5::write_vector(file, "/wisps/binding_wisp", binding_wisp);
  h5::write_vector(file, "/wisps/binding_tetrahedron", binding_tetrahedron);
  h5::write_dataset(file, "/wisps/binding_local_m", binding_local,
                    {static_cast<int64_t>(result.wisp_bindings.size()), 3});
}

SimulatedGuides read_simulated_guides(const h5::File& file) {
  h5::require_schema(file, kGuidesSchema);
  SimulatedGuides guides;
  guides.head_height_m = h5::read_double_attribute(file, "/", "head_height_m");
  guides.fps = h5::read_double_attribute(file, "/", "fps");
  guides.rest.offsets = h5::read_vector<int64_t>(file, "/guides/offsets");
  guides.rest.points = h5::read_matrix<float, 3>(file, "/guides/rest_points");
  auto to_int32 = [](const std::vector<int8_t>& values) {
    return std::vector<int32_t>(values.begin(), values.end());
  };
  guides.rest.strand_attributes["kind"] =
      to_int32(h5::read_enum_dataset(file, "/guides/kind", guide_kind_members()));
  guides.rest.strand_attributes["style"] =
      to_int32(h5::read_enum_dataset(file, "/guides/style", style_members()));
  guides.rest.strand_attributes["cluster"] = h5::read_vector<int32_t>(file, "/guides/cluster");
  h5::Array<float> frames = h5::read_array<float>(file, "/frames/guide_points");
  guides.frame_count = static_cast<int32_t>(frames.shape[0]);
  guides.guide_points_m = std::move(frames.values);
  h5::Array<double> rotation = h5::read_array<double>(file, "/frames/head_rotation");
  h5::Array<double> translation = h5::read_array<double>(file, "/frames/head_translation_m");
  for (int32_t f = 0; f < guides.frame_count; ++f) {
    auto r = static_cast<size_t>(4 * f), t = static_cast<size_t>(3 * f);
    RigidTransform head;
    head.rotation = Eigen::Quaterniond(rotation.values[r], rotation.values[r + 1],
                                       rotation.values[r + 2], rotation.values[r + 3]);
    head.translation_m = Eigen::Vector3d(translation.values[t], translation.values[t + 1],
                                         translation.values[t + 2]);
    guides.head.push_back(head);
  }
  return guides;
}

}  // namespace hair
