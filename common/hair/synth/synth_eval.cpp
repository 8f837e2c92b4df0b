#include "hair/synth/synth_eval.h"

#include <algorithm>

namespace hair::synth {

namespace {

/// The patch of every mesh vertex.
std::vector<int32_t> vertex_patches(const SynthModel& model) {
  std::vector<int32_t> patch_of(static_cast<size_t>(model.mesh.vertex_count()), -1);
  for (size_t p = 0; p < model.patches.size(); ++p)
    for (int64_t v = 0; v < model.patches[p].vertex_count; ++v)
      patch_of[static_cast<size_t>(model.patches[p].first_vertex + v)] = static_cast<int32_t>(p);
  return patch_of;
}

const std::vector<int32_t>& source_vertices(const ExtractResult& extract) {
  return std::get<std::vector<int32_t>>(extract.strands.point_attributes.at("source_vertex"));
}

}  // namespace

std::vector<int32_t> group_patches(const SynthModel& model, const ExtractResult& extract) {
  // By the faces of each group (extract keeps vertex ids), so that groups of unpaired
  // triangles, whose strands have no source vertices, are found too.
  std::vector<int32_t> patch_of_vertex = vertex_patches(model);
  const PolyMesh& mesh = extract.hair_mesh;
  std::vector<int32_t> result(static_cast<size_t>(extract.group_count()), -1);
  std::vector<bool> mixed(result.size(), false);
  for (int64_t f = 0; f < mesh.face_count(); ++f) {
    auto group = static_cast<size_t>(extract.face_group[static_cast<size_t>(f)]);
    for (int32_t vertex : mesh.face(f)) {
      if (vertex < 0 || vertex >= static_cast<int32_t>(patch_of_vertex.size())) continue;
      int32_t patch = patch_of_vertex[static_cast<size_t>(vertex)];
      if (result[group] < 0) result[group] = patch;
      if (patch != result[group]) mixed[group] = true;
    }
  }
  for (size_t g = 0; g < result.size(); ++g)
    if (mixed[g]) result[g] = -1;
  return result;
}

std::vector<GroupOrientation> group_orientations(const SynthModel& model,
                                                 const ExtractResult& extract,
                                                 const std::vector<int32_t>& patch_of_group) {
  const std::vector<int32_t>& source = source_vertices(extract);
  std::vector<GroupOrientation> result(static_cast<size_t>(extract.group_count()),
                                       GroupOrientation::across);
  for (int32_t g = 0; g < extract.group_count(); ++g) {
    if (patch_of_group[static_cast<size_t>(g)] < 0) continue;
    std::array<int, 3> votes{};
    for (int32_t s = extract.group_first_strand[static_cast<size_t>(g)];
         s < extract.group_first_strand[static_cast<size_t>(g) + 1]; ++s) {
      int32_t first = source[static_cast<size_t>(extract.strands.offsets[static_cast<size_t>(s)])];
      int32_t last =
          source[static_cast<size_t>(extract.strands.offsets[static_cast<size_t>(s) + 1] - 1)];
      if (first < 0 || last < 0) continue;
      float along_first = model.vertex_along_m[static_cast<size_t>(first)];
      float along_last = model.vertex_along_m[static_cast<size_t>(last)];
      ++votes[along_last > along_first ? 0 : along_last < along_first ? 1 : 2];
    }
    result[static_cast<size_t>(g)] =
        static_cast<GroupOrientation>(std::max_element(votes.begin(), votes.end()) - votes.begin());
  }
  return result;
}

}  // namespace hair::synth
