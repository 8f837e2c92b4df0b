#include "hair/interp/frames_io.h"

#include <cmath>

#include "hair/grow/grow_io.h"
#include "hair/h5/attribute.h"
#include "hair/h5/dataset.h"
#include "hair/h5/frame_dataset.h"
#include "hair/h5/schema.h"
#include "hair/h5/schema_validation.h"
#include "hair/sim/guides_io.h"
#include "hair/style/style_io.h"

namespace hair {
namespace {

std::vector<RigidTransform> read_head(const h5::File& file) {
  h5::Array<double> rotation = h5::read_array<double>(file, "/frames/head_rotation");
  h5::Array<double> translation = h5::read_array<double>(file, "/frames/head_translation_m");
  std::vector<RigidTransform> head;
  for (int64_t f = 0; f < rotation.shape[0]; ++f) {
    auto r = static_cast<size_t>(4 * f), t = static_cast<size_t>(3 * f);
    RigidTransform pose;
    pose.rotation = Eigen::Quaterniond(rotation.values[r], rotation.values[r + 1],
                                       rotation.values[r + 2], rotation.values[r + 3]);
    pose.translation_m = Eigen::Vector3d(translation.values[t], translation.values[t + 1],
                                         translation.values[t + 2]);
    head.push_back(pose);
  }
  return head;
}

}  // namespace

const h5::EnumMembers& interpolation_method_members() {
  static const h5::EnumMembers members = {
      {"fixed", 0}, {"barycentric", 1}, {"clump", 2}, {"braided", 3}};
  return members;
}

InterpolationInput read_interpolation_input(const h5::File& guides, const h5::File& strands,
                                            const h5::File& styles) {
  h5::require_schema(guides, kGuidesSchema);
  InterpolationInput input;
  GrownStrands grown = read_grown_strands(strands);
  input.cluster_style = read_cluster_styles(styles);
  input.strands = std::move(grown.strands);
  input.head_height_m = grown.head_height_m;
  const size_t clusters = h5::read_vector<int64_t>(strands, "/clusters/strand_count").size();
  if (input.cluster_style.size() != clusters)
    throw Error::other_model(styles.name(), "/clusters/style", input.cluster_style.size(),
                             "clusters", strands.name(), clusters);
  InterpolationGuides& g = input.guides;
  g.cluster_simulated_style =
      h5::read_enum_dataset(guides, "/clusters/simulated_style", style_members());
  if (g.cluster_simulated_style.size() != clusters)
    throw Error::other_model(guides.name(), "/clusters/simulated_style",
                             g.cluster_simulated_style.size(), "clusters", strands.name(),
                             clusters);
  const auto& point_cluster =
      std::get<std::vector<int32_t>>(input.strands.point_attributes.at("cluster"));
  for (int32_t cluster : point_cluster)
    if (cluster < 0 || static_cast<size_t>(cluster) >= clusters)
      throw Error::bad_dataset(
          strands.name(), "/strands/point_attributes/cluster",
          "names cluster " + std::to_string(cluster) + " of " + std::to_string(clusters));

  g.offsets = h5::read_vector<int64_t>(guides, "/guides/offsets");
  g.rest_points = h5::read_matrix<float, 3>(guides, "/guides/rest_points");
  g.cluster = h5::read_vector<int32_t>(guides, "/guides/cluster");
  std::vector<int8_t> kind = h5::read_enum_dataset(guides, "/guides/kind", guide_kind_members());
  for (int8_t k : kind) g.is_wisp_centre.push_back(k == 1 ? 1 : 0);
  g.strand = h5::read_vector<int64_t>(guides, "/guides/strand");
  const std::vector<int64_t>& guide_strand = g.strand;
  std::vector<int64_t> anchor_point = h5::read_vector<int64_t>(guides, "/guides/anchor_point");
  // Every strand guide starts on its grown strand's anchor point: the same model.
  const double tolerance_m = 1e-4 * input.head_height_m;
  for (size_t i = 0; i < guide_strand.size(); ++i) {
    if (g.is_wisp_centre[i]) continue;
    int64_t s = guide_strand[i];
    bool fits = s >= 0 && s < input.strands.strand_count() && anchor_point[i] >= 0 &&
                anchor_point[i] < input.strands.strand_size(s);
    if (fits) {
      Eigen::Vector3d on_strand = point_of(
          input.strands.points, input.strands.offsets[static_cast<size_t>(s)] + anchor_point[i]);
      Eigen::Vector3d first = point_of(g.rest_points, g.offsets[i]);
      fits = (on_strand - first).norm() <= tolerance_m;
    }
    if (!fits)
      throw Error::bad_dataset(guides.name(), "/guides/strand",
                               "guide " + std::to_string(i) + " does not start on strand " +
                                   std::to_string(s) + " of " + strands.name() +
                                   ": made from another model");
  }
  g.wisp_tetrahedron_offsets = h5::read_vector<int32_t>(guides, "/wisps/tetrahedron_offsets");
  g.binding_point = h5::read_vector<int64_t>(guides, "/wisps/binding_point");
  g.binding_wisp = h5::read_vector<int32_t>(guides, "/wisps/binding_wisp");
  g.binding_tetrahedron = h5::read_vector<int32_t>(guides, "/wisps/binding_tetrahedron");
  Points3f local = h5::read_matrix<float, 3>(guides, "/wisps/binding_local_m");
  for (Eigen::Index b = 0; b < local.rows(); ++b)
    g.binding_local_m.push_back(local.row(b).transpose());
  for (int64_t point : g.binding_point)
    if (point >= input.strands.point_count())
      throw Error::bad_dataset(guides.name(), "/wisps/binding_point",
                               "names point " + std::to_string(point) + " of " +
                                   std::to_string(input.strands.point_count()) + " in " +
                                   strands.name() + ": made from another model");
  input.wisp_tetrahedron_count = g.wisp_tetrahedron_offsets.back();

  input.fps = h5::read_double_attribute(guides, "/", "fps");
  input.motion = h5::read_string_attribute(guides, "/", "motion");
  input.time_s = h5::read_vector<double>(guides, "/frames/time_s");
  input.frame_count = static_cast<int64_t>(input.time_s.size());
  input.head = read_head(guides);
  if (input.head.empty())
    throw Error::bad_dataset(guides.name(), "/frames/head_rotation", "has no frames");
  // The wisps' frames at rest: frame 0's, back through the head at time 0.
  const std::vector<float> first = h5::read_frame(guides, "/wisps/frames", 0);
  const RigidTransform& head = input.head.front();
  const Eigen::Quaterniond inverse = head.rotation.normalized().conjugate();
  for (size_t t = 0; t + 7 <= first.size(); t += 7) {
    Eigen::Vector3d origin =
        head.apply_inverse(Eigen::Vector3d(first[t], first[t + 1], first[t + 2]));
    Eigen::Quaterniond q =
        inverse * Eigen::Quaterniond(first[t + 3], first[t + 4], first[t + 5], first[t + 6]);
    for (double v : {origin.x(), origin.y(), origin.z(), q.w(), q.x(), q.y(), q.z()})
      g.wisp_rest_frames.push_back(static_cast<float>(v));
  }
  return input;
}

GuideFrameData read_guide_frame(const h5::File& guides, int64_t frame) {
  GuideFrameData data;
  data.guide_points_m = h5::read_frame(guides, "/frames/guide_points", frame);
  data.wisp_frames = h5::read_frame(guides, "/wisps/frames", frame);
  return data;
}

void write_frames_bindings(h5::File& file, const StrandSet& strands, const StrandBinding& binding,
                           const FramesFileInfo& info) {
  h5::write_schema_attributes(file, h5::Schema::find(kFramesSchema));
  h5::write_string_attribute(file, "/", "unit", "m");
  h5::write_double_attribute(file, "/", "head_height_m", info.head_height_m);
  h5::write_double_attribute(file, "/", "fps", info.fps);
  h5::write_string_attribute(file, "/", "motion", info.motion);
  h5::write_int64_attribute(file, "/", "first_frame", info.first_frame);
  h5::write_int64_attribute(file, "/", "source_frame_count", info.source_frame_count);
  h5::write_double_attribute(file, "/", "rest_max_deviation_m", info.rest_max_deviation_m);
  if (info.interpolation_ms_per_frame >= 0)
    h5::write_double_attribute(file, "/", "interpolation_ms_per_frame",
                               info.interpolation_ms_per_frame);

  const int64_t count = strands.strand_count();
  const auto& point_cluster =
      std::get<std::vector<int32_t>>(strands.point_attributes.at("cluster"));
  std::vector<int32_t> cluster, guides;
  std::vector<float> weights;
  std::vector<int8_t> method;
  for (int64_t s = 0; s < count; ++s) {
    const auto si = static_cast<size_t>(s);
    cluster.push_back(point_cluster[static_cast<size_t>(strands.offsets[si])]);
    method.push_back(static_cast<int8_t>(binding.method[si]));
    for (size_t k = 0; k < 3; ++k) {
      guides.push_back(binding.guides[si][k]);
      weights.push_back(binding.weights[si][k]);
    }
  }
  h5::write_vector(file, "/strands/offsets", strands.offsets);
  h5::write_matrix(file, "/strands/rest_points", strands.points);
  h5::write_vector(file, "/strands/point_cluster", point_cluster);
  h5::write_vector(file, "/strands/cluster", cluster);
  h5::write_enum_dataset(file, "/strands/method", method, interpolation_method_members());
  h5::write_dataset(file, "/strands/guides", guides, {count, 3});
  h5::write_dataset(file, "/strands/weights", weights, {count, 3});
  std::vector<uint8_t> is_guide(static_cast<size_t>(count), 0);
  for (int64_t s : info.guide_strand)
    if (s >= 0 && s < count) is_guide[static_cast<size_t>(s)] = 1;
  h5::write_vector(file, "/strands/is_guide", is_guide);
  h5::write_vector(file, "/strands/held_count", binding.held_count);
  h5::write_vector(file, "/strands/bound_from", binding.bound_from);
  h5::write_enum_dataset(file, "/clusters/simulated_style", info.simulated_style, style_members());
  h5::write_enum_dataset(file, "/clusters/style", info.cluster_style, style_members());
}

void write_frames_timeline(h5::File& file, const std::vector<int64_t>& index,
                           const std::vector<double>& time_s,
                           const std::vector<RigidTransform>& head) {
  std::vector<double> rotation, translation;
  for (const RigidTransform& pose : head) {
    for (double v : {pose.rotation.w(), pose.rotation.x(), pose.rotation.y(), pose.rotation.z()})
      rotation.push_back(v);
    for (int axis = 0; axis < 3; ++axis) translation.push_back(pose.translation_m[axis]);
  }
  const auto frames = static_cast<int64_t>(index.size());
  h5::write_vector(file, "/frames/index", index);
  h5::write_vector(file, "/frames/time_s", time_s);
  h5::write_dataset(file, "/frames/head_rotation", rotation, {frames, 4});
  h5::write_dataset(file, "/frames/head_translation_m", translation, {frames, 3});
}

FramesFile read_frames_file(const h5::File& file) {
  h5::require_schema(file, kFramesSchema);
  FramesFile frames;
  frames.head_height_m = h5::read_double_attribute(file, "/", "head_height_m");
  frames.fps = h5::read_double_attribute(file, "/", "fps");
  frames.motion = h5::read_string_attribute(file, "/", "motion");
  frames.first_frame = h5::read_int64_attribute(file, "/", "first_frame");
  frames.rest.offsets = h5::read_vector<int64_t>(file, "/strands/offsets");
  frames.rest.points = h5::read_matrix<float, 3>(file, "/strands/rest_points");
  frames.rest.point_attributes["cluster"] =
      h5::read_vector<int32_t>(file, "/strands/point_cluster");
  frames.rest.strand_attributes["cluster"] = h5::read_vector<int32_t>(file, "/strands/cluster");
  std::vector<int8_t> method =
      h5::read_enum_dataset(file, "/strands/method", interpolation_method_members());
  frames.rest.strand_attributes["method"] = std::vector<int32_t>(method.begin(), method.end());
  std::vector<uint8_t> is_guide = h5::read_vector<uint8_t>(file, "/strands/is_guide");
  frames.rest.strand_attributes["is_guide"] =
      std::vector<int32_t>(is_guide.begin(), is_guide.end());
  frames.cluster_style = h5::read_enum_dataset(file, "/clusters/style", style_members());
  frames.simulated_style =
      h5::read_enum_dataset(file, "/clusters/simulated_style", style_members());
  frames.index = h5::read_vector<int64_t>(file, "/frames/index");
  frames.time_s = h5::read_vector<double>(file, "/frames/time_s");
  frames.head = read_head(file);
  return frames;
}

Points3f read_frame_points(const h5::File& file, int64_t row) {
  std::vector<float> values = h5::read_frame(file, "/frames/points", row);
  return Eigen::Map<const Points3f>(values.data(), static_cast<Eigen::Index>(values.size() / 3), 3);
}

}  // namespace hair
