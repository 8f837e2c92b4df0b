// Quad recovery on real cards as other tools write them: the ten MakeHuman meshes, every
// quad split into two triangles along one diagonal or the other (the truth is the mesh
// itself: which two triangles came from one quad).
#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <set>

#include "hair/mesh/mesh_io.h"
#include "hair/mesh/quad_recovery.h"

namespace hair {
namespace {

enum class Diagonal { alternating, shorter, random };

/// `mesh` with every quad split into two triangles, written one after the other; the
/// diagonal is chosen as `diagonal` says (alternating from quad to quad; the shorter in
/// 3D, as "beauty" triangulations and many exporters do; at random).
PolyMesh triangulated(const PolyMesh& mesh, Diagonal diagonal) {
  PolyMesh out;
  out.vertices = mesh.vertices;
  out.materials = mesh.materials;
  std::vector<float> uv;
  std::mt19937 random(7);
  for (int64_t f = 0; f < mesh.face_count(); ++f) {
    const int64_t base = mesh.face_offsets[static_cast<size_t>(f)];
    const int n = static_cast<int>(mesh.face_size(f));
    int first = 0;
    if (n == 4) {
      auto corner = [&](int c) { return mesh.vertices.row(mesh.face_vertices[base + c]); };
      switch (diagonal) {
        case Diagonal::alternating: first = static_cast<int>(f % 2); break;
        case Diagonal::shorter:
          first = (corner(0) - corner(2)).squaredNorm() <= (corner(1) - corner(3)).squaredNorm()
                      ? 0
                      : 1;
          break;
        case Diagonal::random: first = static_cast<int>(random() % 2); break;
      }
    }
    for (int k = 1; k + 1 < n; ++k) {
      const std::array<int64_t, 3> corners = {base + first, base + (first + k) % n,
                                              base + (first + k + 1) % n};
      std::vector<int32_t> face;
      for (int64_t c : corners) {
        face.push_back(mesh.face_vertices[c]);
        uv.push_back(mesh.corner_uv(c, 0));
        uv.push_back(mesh.corner_uv(c, 1));
      }
      out.append_face(face);
      out.face_material.push_back(mesh.face_material[static_cast<size_t>(f)]);
    }
  }
  out.corner_uv = Eigen::Map<const Uv2f>(uv.data(), static_cast<Eigen::Index>(uv.size() / 2), 2);
  return out;
}

std::set<std::vector<int32_t>> sorted_quads(const PolyMesh& mesh) {
  std::set<std::vector<int32_t>> quads;
  for (int64_t f = 0; f < mesh.face_count(); ++f) {
    if (mesh.face_size(f) != 4) continue;
    std::vector<int32_t> corners(mesh.face(f).begin(), mesh.face(f).end());
    std::sort(corners.begin(), corners.end());
    quads.insert(corners);
  }
  return quads;
}

TEST(QuadRecoveryWritten, TheTenMakeHumanMeshesTriangulatedPairBackIntoTheirQuads) {
  const std::filesystem::path hair = std::filesystem::path(HAIR_SHARED_DATA_DIR) / "makehuman/hair";
  for (const char* model : {"afro01", "bob01", "bob02", "braid01", "long01", "ponytail01",
                            "short01", "short02", "short03", "short04"}) {
    const PolyMesh mesh = read_mesh(hair / (std::string(model) + ".obj"));
    ASSERT_TRUE(mesh.has_uv()) << model;
    const std::set<std::vector<int32_t>> truth = sorted_quads(mesh);
    ASSERT_GT(truth.size(), 100u) << model;
    for (Diagonal diagonal : {Diagonal::alternating, Diagonal::shorter, Diagonal::random}) {
      const QuadRecovery recovered = quads_from_triangles(triangulated(mesh, diagonal), 60.0);
      size_t found = 0, made = 0;
      for (const std::vector<int32_t>& quad : sorted_quads(recovered.mesh)) {
        ++made;
        found += truth.count(quad);
      }
      // Nearly every quad comes back (a triangle pair whose quad has a corner more than 60
      // degrees off a right angle is not taken: some of a braid's and a ponytail's twisted
      // quads), and few pairs join halves of two quads.
      EXPECT_GE(found, 0.88 * static_cast<double>(truth.size()))
          << model << " diagonal " << static_cast<int>(diagonal);
      EXPECT_LE(made - found, 0.11 * static_cast<double>(truth.size()))
          << model << " diagonal " << static_cast<int>(diagonal);
    }
  }
}

}  // namespace
}  // namespace hair
