#include "hair/mesh/mesh_patches.h"

#include <numeric>

namespace hair {
namespace {

int32_t find_root(std::vector<int32_t>& parent, int32_t v) {
  while (parent[v] != v) {
    parent[v] = parent[parent[v]];
    v = parent[v];
  }
  return v;
}

}  // namespace

MeshPatches mesh_patches(const PolyMesh& mesh) {
  std::vector<int32_t> parent(static_cast<size_t>(mesh.vertex_count()));
  std::iota(parent.begin(), parent.end(), 0);
  for (int64_t f = 0; f < mesh.face_count(); ++f) {
    auto face = mesh.face(f);
    int32_t first = find_root(parent, face[0]);
    for (size_t c = 1; c < face.size(); ++c) {
      int32_t other = find_root(parent, face[c]);
      if (other != first) parent[other] = first;
    }
  }
  MeshPatches patches;
  patches.face_patch.assign(static_cast<size_t>(mesh.face_count()), -1);
  std::vector<int32_t> patch_of_root(parent.size(), -1);
  for (int64_t f = 0; f < mesh.face_count(); ++f) {
    int32_t root = find_root(parent, mesh.face(f)[0]);
    if (patch_of_root[root] < 0) {
      patch_of_root[root] = patches.patch_count();
      patches.patch_faces.emplace_back();
    }
    patches.face_patch[f] = patch_of_root[root];
    patches.patch_faces[patch_of_root[root]].push_back(f);
  }
  return patches;
}

}  // namespace hair
