// Mesh reading and checks: the native OBJ reader keeps the file's vertex order; assimp
// reads other formats; bad meshes are rejected with one line naming the problem.
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include <assimp/Exporter.hpp>
#include <filesystem>

#include "unit/file_test.h"
#include "hair/core/error.h"
#include "hair/mesh/mesh_checks.h"
#include "hair/mesh/mesh_io.h"
#include "hair/mesh/quad_recovery.h"

namespace hair {
namespace {

/// The message of the hair::Error that reading and checking `path` throws (empty if none).
std::string read_error(const std::filesystem::path& path,
                       MeshReader reader = MeshReader::automatic) {
  try {
    PolyMesh mesh = read_mesh(path, reader);
    check_mesh(mesh, path.string());
  } catch (const Error& error) {
    EXPECT_EQ(error.exit_code(), 2);
    EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos);
    return error.what();
  }
  return {};
}

class MeshReading : public hair::test::FileTest {};

constexpr const char* kTwoQuads =
    "# two quads sharing an edge, ids out of face order\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "vn 0 0 1\n"
    "g hair\nusemtl none\ns off\n"
    "f 5/1/1 6/2/1 3/3/1 2/4/1\n"
    "f -6/1 -5/2 -4/3 -3/4\n";

TEST_F(MeshReading, ObjKeepsTheFilesVertexOrderAndCornerTextures) {
  PolyMesh mesh = read_mesh(write_file("quads.obj", kTwoQuads));
  ASSERT_EQ(mesh.vertex_count(), 6);
  EXPECT_EQ(mesh.vertices.row(4), Eigen::RowVector3f(2, 0, 0));
  ASSERT_EQ(mesh.face_count(), 2);
  EXPECT_EQ(std::vector<int32_t>(mesh.face(0).begin(), mesh.face(0).end()),
            (std::vector<int32_t>{4, 5, 2, 1}));
  EXPECT_EQ(std::vector<int32_t>(mesh.face(1).begin(), mesh.face(1).end()),
            (std::vector<int32_t>{0, 1, 2, 3}));
  ASSERT_TRUE(mesh.has_uv());
  EXPECT_EQ(mesh.corner_uv.row(2), Eigen::RowVector2f(1, 1));
}

TEST_F(MeshReading, AssimpReadsTheSameSurfaceRenumbered) {
  PolyMesh native = read_mesh(write_file("quads.obj", kTwoQuads));
  PolyMesh through_assimp = read_mesh(directory_ / "quads.obj", MeshReader::assimp);
  EXPECT_EQ(through_assimp.vertex_count(), native.vertex_count());  // seams welded
  EXPECT_EQ(through_assimp.face_count(), native.face_count());
  EXPECT_EQ(through_assimp.face_size(0), 4);  // quads kept
}

TEST_F(MeshReading, GltfWrittenByAssimpReadsBack) {
  aiScene scene;
  scene.mRootNode = new aiNode();
  scene.mMaterials = new aiMaterial* [1] { new aiMaterial() };
  scene.mNumMaterials = 1;
  scene.mMeshes = new aiMesh* [1] { new aiMesh() };
  scene.mNumMeshes = 1;
  scene.mRootNode->mMeshes = new unsigned[1]{0};
  scene.mRootNode->mNumMeshes = 1;
  aiMesh& mesh = *scene.mMeshes[0];
  mesh.mPrimitiveTypes = aiPrimitiveType_TRIANGLE;  // glTF holds triangles only
  mesh.mNumVertices = 4;
  mesh.mVertices = new aiVector3D[4]{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  mesh.mNumFaces = 2;
  mesh.mFaces = new aiFace[2];
  for (int f = 0; f < 2; ++f) {
    mesh.mFaces[f].mNumIndices = 3;
    mesh.mFaces[f].mIndices = f == 0 ? new unsigned[3]{0, 1, 2} : new unsigned[3]{0, 2, 3};
  }
  std::filesystem::path path = directory_ / "square.gltf";
  Assimp::Exporter exporter;
  ASSERT_EQ(exporter.Export(&scene, "gltf2", path.string()), aiReturn_SUCCESS)
      << exporter.GetErrorString();
  PolyMesh read = read_mesh(path);
  EXPECT_EQ(read.vertex_count(), 4);
  ASSERT_EQ(read.face_count(), 2);
  QuadRecovery quads = quads_from_triangles(read);
  EXPECT_EQ(quads.mesh.face_count(), 1);  // the square again
  EXPECT_EQ(quads.triangles_paired, 2);
}

TEST_F(MeshReading, BadFilesAreRejectedWithOneLine) {
  EXPECT_NE(read_error(directory_ / "missing.obj").find("no such file"), std::string::npos);
  EXPECT_NE(read_error(write_file("hair.xyz", "hello")).find("unsupported mesh format '.xyz'"),
            std::string::npos);
  EXPECT_NE(read_error(write_file("empty.obj", "# nothing\n")).find("empty mesh"),
            std::string::npos);
  EXPECT_NE(read_error(write_file("points.obj", "v 0 0 0\nv 1 0 0\n")).find("no faces"),
            std::string::npos);
  EXPECT_NE(read_error(write_file("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n"))
                .find("vertex 2 (counting from 1, as OBJ does) has a non-finite"),
            std::string::npos);
  EXPECT_NE(read_error(write_file("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"))
                .find("line 4: face refers to vertex 9 of 3"),
            std::string::npos);
  EXPECT_NE(read_error(write_file("word.obj", "v 0 zero 0\n"))
                .find("line 1: expected a number, found 'zero'"),
            std::string::npos);
  EXPECT_NE(read_error(write_file("short.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n")).find("fewer than 3"),
            std::string::npos);
}

TEST_F(MeshReading, AMeshOverItsTriangleLimitIsRefusedByTheSettingsName) {
  // Two quads are four triangles, in OBJ read natively and through assimp.
  const std::filesystem::path path = write_file("quads.obj", kTwoQuads);
  for (MeshReader reader : {MeshReader::automatic, MeshReader::assimp}) {
    EXPECT_EQ(read_mesh(path, reader, {4, "max_mesh_triangles"}).face_count(), 2);
    try {
      read_mesh(path, reader, {3, "max_mesh_triangles"});
      ADD_FAILURE() << "four triangles read under a limit of three";
    } catch (const Error& error) {
      EXPECT_EQ(error.exit_code(), 2);
      const std::string message = error.what();
      EXPECT_NE(message.find("quads.obj"), std::string::npos) << message;
      EXPECT_NE(message.find("more triangles than the limit of 3 (max_mesh_triangles)"),
                std::string::npos)
          << message;
      EXPECT_EQ(message.find('\n'), std::string::npos);
    }
  }
  // The native reader stops at the face that passes the limit: a file whose later lines
  // are broken is refused for its size, not for the broken line.
  const std::filesystem::path broken =
      write_file("broken.obj", std::string(kTwoQuads) + "f 1 2 3\nf 1 2 3\nnot obj at all\n");
  try {
    read_mesh(broken, MeshReader::automatic, {4, "max_mesh_triangles"});
    ADD_FAILURE() << "read past the limit";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("line 18: more triangles"), std::string::npos)
        << error.what();
  }
}

TEST_F(MeshReading, CleaningDropsRepeatedCornersAndDegenerateFaces) {
  PolyMesh mesh = read_mesh(write_file("degenerate.obj",
                                       "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                       "f 1 2 2 3 4\nf 1 2 1\n"));
  MeshCleanup cleanup = clean_mesh(mesh, "degenerate.obj");
  EXPECT_EQ(cleanup.repeated_corners_removed,
            2);  // 2-2 in the first face, 1...1 closing the second
  EXPECT_EQ(cleanup.degenerate_faces_removed, 1);
  ASSERT_EQ(mesh.face_count(), 1);
  EXPECT_EQ(mesh.face_size(0), 4);
  PolyMesh all_degenerate = read_mesh(write_file("flat.obj", "v 0 0 0\nv 1 0 0\nf 1 2 1\n"));
  EXPECT_THROW(clean_mesh(all_degenerate, "flat.obj"), Error);
}

}  // namespace
}  // namespace hair
