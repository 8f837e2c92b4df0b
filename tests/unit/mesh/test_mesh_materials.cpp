// Materials of hair meshes: an OBJ's mtllib/usemtl and its MTL file's map_Kd/map_d, with
// image paths resolved as artists' tools write them; missing libraries are a warning.
#include <gtest/gtest.h>

#include <filesystem>

#include "hair/core/error.h"
#include "hair/mesh/mesh_checks.h"
#include "hair/mesh/mesh_io.h"
#include "hair/mesh/mesh_material.h"
#include "hair/mesh/quad_recovery.h"
#include "unit/file_test.h"

namespace hair {
namespace {

class MeshMaterials : public hair::test::FileTest {};

TEST_F(MeshMaterials, MtlMapsResolveAgainstTheLibraryFolderPastTheirOptions) {
  std::filesystem::create_directories(directory_ / "lib");
  std::filesystem::path library = write_file(
      "lib/hair.mtl",
      "# a library\n"
      "newmtl cards\nKd 1 1 1\nmap_Kd -bm 1 -s 1 1 1 textures/hair cards.png\n"
      "map_d -imfchan m textures\\alpha.png\n"
      "newmtl bare\nKd 0.5 0.5 0.5\n"
      "newmtl absolute\nmap_Kd /srv/art/hair.png\n");
  std::vector<MeshMaterial> materials = read_mtl(library);
  ASSERT_EQ(materials.size(), 3u);
  EXPECT_EQ(materials[0].name, "cards");
  EXPECT_EQ(materials[0].diffuse.path, directory_ / "lib" / "textures/hair cards.png");
  EXPECT_EQ(materials[0].alpha.path, directory_ / "lib" / "textures/alpha.png");
  EXPECT_EQ(materials[1].name, "bare");
  EXPECT_FALSE(materials[1].diffuse.present());
  EXPECT_FALSE(materials[1].alpha.present());
  EXPECT_EQ(materials[2].diffuse.path, std::filesystem::path("/srv/art/hair.png"));
}

TEST_F(MeshMaterials, AMissingLibraryIsAnErrorNamingIt) {
  try {
    read_mtl(directory_ / "nowhere.mtl");
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("nowhere.mtl"), std::string::npos);
    EXPECT_EQ(error.exit_code(), 2);
  }
}

constexpr const char* kQuadsOfTwoMaterials =
    "mtllib hair.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "f 1/1 2/2 3/3 4/4\n"
    "usemtl cards\n"
    "f 2/1 5/2 6/3 3/4\n"
    "usemtl unknown\n"
    "f 1/1 2/2 3/3\n";

TEST_F(MeshMaterials, ObjFacesCarryTheirMaterialThroughCleaningAndQuadRecovery) {
  write_file("hair.mtl", "newmtl cards\nmap_Kd textures/cards.png\n");
  std::filesystem::path obj = write_file("hair.obj", kQuadsOfTwoMaterials);
  PolyMesh mesh = read_mesh(obj);
  ASSERT_EQ(mesh.face_material.size(), 3u);
  EXPECT_EQ(mesh.face_material[0], -1);  // before any usemtl
  ASSERT_GE(mesh.face_material[1], 0);
  const MeshMaterial* cards = mesh.material_of(1);
  ASSERT_NE(cards, nullptr);
  EXPECT_EQ(cards->name, "cards");
  EXPECT_EQ(cards->diffuse.path, directory_ / "textures/cards.png");
  const MeshMaterial* unknown = mesh.material_of(2);  // named in no library: no images
  ASSERT_NE(unknown, nullptr);
  EXPECT_EQ(unknown->name, "unknown");
  EXPECT_FALSE(unknown->diffuse.present());

  clean_mesh(mesh, obj.string());
  QuadRecovery recovered = quads_from_triangles(mesh, 60);
  ASSERT_EQ(recovered.mesh.face_material.size(),
            static_cast<size_t>(recovered.mesh.face_count()));
  for (int64_t f = 0; f < recovered.mesh.face_count(); ++f)
    EXPECT_EQ(recovered.mesh.face_material[static_cast<size_t>(f)],
              mesh.face_material[static_cast<size_t>(recovered.source_face[static_cast<size_t>(f)])]);
  EXPECT_EQ(recovered.mesh.materials.size(), mesh.materials.size());
}

TEST_F(MeshMaterials, TrianglesOfTwoMaterialsAreNotPairedIntoAQuad) {
  write_file("two.mtl", "newmtl a\nnewmtl b\n");
  std::filesystem::path obj = write_file(
      "two.obj",
      "mtllib two.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
      "usemtl a\nf 1 2 3\nusemtl b\nf 1 3 4\n");
  PolyMesh mesh = read_mesh(obj);
  EXPECT_EQ(quads_from_triangles(mesh, 60).triangles_paired, 0);
  write_file("one.mtl", "newmtl a\n");
  PolyMesh same = read_mesh(write_file(
      "one.obj", "mtllib one.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nusemtl a\nf 1 2 3\nf 1 3 4\n"));
  EXPECT_EQ(quads_from_triangles(same, 60).triangles_paired, 2);
}

TEST_F(MeshMaterials, AMissingLibraryLeavesTheMeshReadableWithoutImages) {
  std::filesystem::path obj = write_file("hair.obj", kQuadsOfTwoMaterials);  // no hair.mtl
  PolyMesh mesh = read_mesh(obj);
  EXPECT_EQ(mesh.face_count(), 3);
  for (const MeshMaterial& material : mesh.materials) EXPECT_FALSE(material.diffuse.present());
}

TEST_F(MeshMaterials, AMeshWithoutMaterialsHasNone) {
  PolyMesh mesh = read_mesh(write_file("plain.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n"));
  EXPECT_FALSE(mesh.has_materials());
  EXPECT_EQ(mesh.material_of(0), nullptr);
}

TEST_F(MeshMaterials, MakeHumanMeshesNameTheirPaintedTexture) {
  const std::filesystem::path hair = std::filesystem::path(HAIR_SHARED_DATA_DIR) / "makehuman/hair";
  for (const char* model : {"braid01", "long01", "short03"}) {
    PolyMesh mesh = read_mesh(hair / (std::string(model) + ".obj"));
    ASSERT_TRUE(mesh.has_materials()) << model;
    ASSERT_EQ(mesh.materials.size(), 1u) << model;
    for (int32_t material : mesh.face_material) EXPECT_EQ(material, 0) << model;
    EXPECT_EQ(mesh.materials[0].diffuse.path, hair / "textures" / (std::string(model) + ".png"));
    EXPECT_TRUE(std::filesystem::is_regular_file(mesh.materials[0].diffuse.path));
  }
}

}  // namespace
}  // namespace hair
