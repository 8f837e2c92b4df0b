#pragma once
// What each fuzz target does with one input: the readers a user's files reach, run as
// the stages run them. Each returns a finding (empty if the input was read or refused
// cleanly); the fuzz targets abort on one, the regression test (tests/unit/fuzz/
// test_fuzz_inputs.cpp) expects none on every stored input.

#include <Eigen/Core>
#include <array>

#include "fuzz/fuzz_input_file.h"
#include "hair/cluster/clustering_io.h"
#include "hair/cluster/typeify_io.h"
#include "hair/extract/extract_io.h"
#include "hair/extract/painted_flow.h"
#include "hair/grow/grow_io.h"
#include "hair/h5/attribute.h"
#include "hair/h5/file.h"
#include "hair/h5/inspect_report.h"
#include "hair/interp/frames_io.h"
#include "hair/mesh/mesh_io.h"
#include "hair/mesh/mesh_material.h"
#include "hair/mesh/poly_mesh.h"
#include "hair/sim/guides_io.h"
#include "hair/style/style_io.h"

namespace hair::fuzz {

/// A hair mesh read as extract reads it, then the painted flow of its faces (its
/// materials' images read as well, wherever they are).
inline void read_mesh_and_paint(const std::filesystem::path& path) {
  const PolyMesh mesh = read_mesh(path, MeshReader::automatic);
  painted_flow(mesh, PaintedFlowParams{}, path.string());
}

/// fuzz_obj: the input is an OBJ file (the native reader).
inline std::string obj_finding(const uint8_t* data, size_t size) {
  const std::filesystem::path path = write_input("hair.obj", data, size);
  return finding_of([&] { read_mesh_and_paint(path); });
}

/// fuzz_assimp_mesh: the input's first byte picks the format (GLB, glTF, FBX or PLY: the
/// file's extension), the rest is the file, read through assimp.
inline std::string assimp_mesh_finding(const uint8_t* data, size_t size) {
  static constexpr std::array<const char*, 4> kNames = {"hair.glb", "hair.gltf", "hair.fbx",
                                                         "hair.ply"};
  if (size == 0) return {};
  const std::filesystem::path path =
      write_input(kNames[data[0] % kNames.size()], data + 1, size - 1);
  return finding_of([&] { read_mesh_and_paint(path); });
}

/// fuzz_mtl: the input is an MTL file; the images its materials name are loaded too
/// (missing ones give warnings).
inline std::string mtl_finding(const uint8_t* data, size_t size) {
  const std::filesystem::path path = write_input("hair.mtl", data, size);
  return finding_of([&] {
    load_painted_textures(read_mtl(path), PaintedFlowParams{}, path.string());
  });
}

/// Two quads side by side, mapped onto the whole texture, with one material.
inline PolyMesh textured_quads() {
  PolyMesh mesh;
  mesh.vertices.resize(6, 3);
  for (int row = 0; row < 2; ++row)
    for (int column = 0; column < 3; ++column)
      mesh.vertices.row(3 * row + column) << 0.01f * static_cast<float>(column),
          -0.01f * static_cast<float>(row), 0.0f;
  const std::array<std::array<int32_t, 4>, 2> faces = {{{0, 1, 4, 3}, {1, 2, 5, 4}}};
  for (const auto& face : faces) mesh.append_face(face);
  mesh.corner_uv.resize(static_cast<Eigen::Index>(mesh.face_vertices.size()), 2);
  for (size_t corner = 0; corner < mesh.face_vertices.size(); ++corner) {
    const int32_t vertex = mesh.face_vertices[corner];
    mesh.corner_uv.row(static_cast<Eigen::Index>(corner))
        << 0.5f * static_cast<float>(vertex % 3), 1.0f - static_cast<float>(vertex / 3);
  }
  mesh.materials.resize(1);
  mesh.materials[0].name = "hair";
  mesh.face_material = {0, 0};
  return mesh;
}

/// fuzz_texture: the input is an encoded image (PNG or JPEG) embedded in a mesh's
/// material, decoded, prepared and carried onto two quads through their UVs.
inline std::string texture_finding(const uint8_t* data, size_t size) {
  static const PolyMesh mesh = textured_quads();
  std::vector<MeshMaterial> materials = mesh.materials;
  materials[0].diffuse.path = "embedded.png";
  materials[0].diffuse.encoded.assign(data, data + size);
  return finding_of([&] {
    const PaintedFlowParams params;
    painted_flow(mesh, load_painted_textures(materials, params, "fuzz"), params);
  });
}

/// The readers of the stages that take a file of schema `schema`.
inline void read_as_stages_do(const h5::File& file, const std::string& schema) {
  if (schema == kExtractSchema) {
    read_extracted_strands(file);
    read_extracted_body(file);
    read_extracted_paint(file);
  } else if (schema == kTypesSchema) {
    read_typed_groups(file);
  } else if (schema == kMiddleSchema) {
    read_middle_clusters(file, 0);
  } else if (schema == kClustersSchema) {
    read_group_clusters(file);
  } else if (schema == kStrandsSchema) {
    read_grown_strands(file);
  } else if (schema == kStylesSchema) {
    read_cluster_styles(file);
  } else if (schema == kGuidesSchema) {
    read_simulated_guides(file);
  } else if (schema == kFramesSchema) {
    const FramesFile frames = read_frames_file(file);
    if (frames.frame_count() > 0) read_frame_points(file, 0);
  }
}

/// fuzz_h5_inputs: the input is an HDF5 file. It is listed and checked against the
/// schema it names (hair-inspect --validate), then, if valid, read by the readers of
/// the stages that take it.
inline std::string h5_input_finding(const uint8_t* data, size_t size) {
  const std::filesystem::path path = write_input("input.h5", data, size);
  return finding_of([&] {
    const h5::File file = h5::File::open_read_only(path);
    if (h5::inspect_report(file, true).violation) return;
    read_as_stages_do(file, h5::read_string_attribute(file, "/", "schema"));
  });
}

}  // namespace hair::fuzz
