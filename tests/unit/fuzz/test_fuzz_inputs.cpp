// The fuzz targets' stored inputs (tests/fuzz/inputs/<target>/: the seeds bench/fuzz.sh
// starts from, and every input a fuzzing run found a fault with, kept as a regression)
// through the same readers in the ordinary build: each is read, or refused as bad input
// with one line; nothing else escapes and nothing crashes.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <vector>

#include "fuzz/fuzz_readers.h"
#include "support/run_command.h"

namespace {

namespace fs = std::filesystem;

const fs::path kInputs = fs::path(HAIR_SOURCE_DIR) / "tests" / "fuzz" / "inputs";

std::vector<fs::path> inputs_of(const std::string& target) {
  std::vector<fs::path> paths;
  for (const auto& entry : fs::directory_iterator(kInputs / target))
    if (entry.is_regular_file() && entry.path().extension() != ".md") paths.push_back(entry.path());
  std::sort(paths.begin(), paths.end());
  return paths;
}

using Finding = std::string (*)(const uint8_t*, size_t);

/// Every stored input of `target` through `finding`. A target's seeds are stored with it,
/// except fuzz_h5_inputs', which bench/fuzz.sh makes from the current build (stored ones
/// would go stale with each schema version): there, only regressions are stored.
void expect_no_finding(const std::string& target, Finding finding, bool seeds_stored = true) {
  const std::vector<fs::path> paths = inputs_of(target);
  if (seeds_stored) {
    ASSERT_FALSE(paths.empty()) << "no stored inputs for " << target;
  }
  for (const fs::path& path : paths) {
    const std::vector<uint8_t> bytes = hair::test::read_file_octets(path);
    EXPECT_EQ(finding(bytes.data(), bytes.size()), "") << path;
  }
}

TEST(FuzzInputs, ObjInputsAreReadOrRefused) {
  expect_no_finding("obj", hair::fuzz::obj_finding);
}

TEST(FuzzInputs, AssimpMeshInputsAreReadOrRefused) {
  expect_no_finding("assimp_mesh", hair::fuzz::assimp_mesh_finding);
}

TEST(FuzzInputs, MtlInputsAreReadOrRefused) {
  expect_no_finding("mtl", hair::fuzz::mtl_finding);
}

TEST(FuzzInputs, TextureInputsAreReadOrRefused) {
  expect_no_finding("texture", hair::fuzz::texture_finding);
}

TEST(FuzzInputs, H5InputsAreReadOrRefused) {
  expect_no_finding("h5_inputs", hair::fuzz::h5_input_finding, false);
}

// The seeds are worth starting from only if the readers take them: a fuzzer mutating a
// file that is refused at its first line explores little.
TEST(FuzzInputs, TheMeshSeedsAreReadWithTheirFaces) {
  for (const char* name : {"quad_strip.obj", "mixed_faces.obj"}) {
    const hair::PolyMesh mesh = hair::read_mesh(kInputs / "obj" / name);
    EXPECT_GE(mesh.face_count(), 2) << name;
  }
  // The assimp seeds carry their format in their first byte (fuzz_readers.h).
  for (const char* name : {"quad.glb", "quad.gltf", "quad.ply", "triangle.fbx"}) {
    const std::vector<uint8_t> bytes = hair::test::read_file_octets(kInputs / "assimp_mesh" / name);
    const fs::path path = hair::fuzz::write_input(name, bytes.data() + 1, bytes.size() - 1);
    const hair::PolyMesh mesh = hair::read_mesh(path);
    EXPECT_GE(mesh.face_count(), 1) << name;
    EXPECT_EQ(mesh.vertex_count(), 4) << name;
  }
}

TEST(FuzzInputs, TheTextureSeedIsPaintedAlongItsStrokes) {
  const std::vector<uint8_t> bytes = hair::test::read_file_octets(kInputs / "texture" / "strokes_16.png");
  const hair::PolyMesh mesh = hair::fuzz::textured_quads();
  std::vector<hair::MeshMaterial> materials = mesh.materials;
  materials[0].diffuse.path = "strokes_16.png";
  materials[0].diffuse.encoded = bytes;
  const hair::PaintedFlowParams params;
  const hair::PaintedTextures textures = hair::load_painted_textures(materials, params, "seed");
  ASSERT_TRUE(textures.unreadable_images.empty());
  const hair::PaintedFlow flow = hair::painted_flow(mesh, textures, params);
  EXPECT_EQ(flow.painted_face_count(), 2);
}

}  // namespace
