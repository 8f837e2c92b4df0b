// Patches, quad recovery and the edge families of strips, grids, tubes and caps.
#include <gtest/gtest.h>

#include "hair/mesh/mesh_patches.h"
#include "hair/mesh/patch_rails.h"
#include "hair/mesh/quad_recovery.h"
#include "unit/synthetic_hair.h"

namespace hair {
namespace {

using testing::hair_strip;
using testing::StripOptions;

std::vector<Eigen::Vector3d> straight(int segments, double length = 1.0) {
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i <= segments; ++i) points.push_back({0, -length * i / segments, 0});
  return points;
}

std::vector<int64_t> all_faces(const PolyMesh& mesh) {
  std::vector<int64_t> faces(static_cast<size_t>(mesh.face_count()));
  std::iota(faces.begin(), faces.end(), 0);
  return faces;
}

/// The family whose chains are longer.
int longer_family(const QuadRegion& region) {
  return region.families[0].mean_chain_length > region.families[1].mean_chain_length ? 0 : 1;
}

TEST(MeshPatches, DisjointStripsArePatchesNumberedByTheirFirstFace) {
  PolyMesh mesh = hair_strip(straight(4), Eigen::Vector3d::UnitX(), 0.1, {});
  PolyMesh second = hair_strip(straight(3), Eigen::Vector3d::UnitX(), 0.1, {});
  second.vertices.col(0).array() += 1.0f;
  testing::append_mesh(mesh, second);
  MeshPatches patches = mesh_patches(mesh);
  ASSERT_EQ(patches.patch_count(), 2);
  EXPECT_EQ(patches.patch_faces[0].size(), 4u);
  EXPECT_EQ(patches.patch_faces[1].size(), 3u);
  EXPECT_EQ(patches.face_patch.front(), 0);
  EXPECT_EQ(patches.face_patch.back(), 1);
}

TEST(PatchTopology, StripHasTwoRailsAlongAndRungsAcross) {
  PolyMesh strip = hair_strip(straight(10), Eigen::Vector3d::UnitX(), 0.1, {});
  PatchTopology topology = patch_topology(strip, all_faces(strip));
  ASSERT_EQ(topology.regions.size(), 1u);
  const QuadRegion& region = topology.regions[0];
  int along = longer_family(region);
  EXPECT_EQ(region.families[along].chains.size(), 2u);
  for (const auto& rail : region.families[along].chains) EXPECT_EQ(rail.size(), 11u);
  EXPECT_EQ(region.families[1 - along].chains.size(), 11u);
  EXPECT_EQ(topology.family_conflicts, 0);
  EXPECT_NEAR(region.families[along].v_alignment, 1.0, 1e-6);  // v runs along
  std::vector<int> along_family{along};
  EXPECT_EQ(patch_kind(topology, along_family), PatchKind::strip);
}

TEST(PatchTopology, RailsOfAGridRunTheSameWayWhateverTheVertexOrder) {
  for (bool shuffle : {false, true}) {
    PolyMesh grid = hair_strip(straight(8), Eigen::Vector3d::UnitX(), 0.3,
                               {.rails = 5, .shuffle_order = shuffle, .seed = 11});
    PatchTopology topology = patch_topology(grid, all_faces(grid));
    const EdgeFamily& rails = topology.regions[0].families[longer_family(topology.regions[0])];
    ASSERT_EQ(rails.chains.size(), 5u);
    float first_y = grid.vertices(rails.chains[0].front(), 1);
    for (const auto& rail : rails.chains) {
      EXPECT_EQ(rail.size(), 9u);
      EXPECT_FLOAT_EQ(grid.vertices(rail.front(), 1), first_y);  // all start at the same end
    }
    std::vector<int> along{longer_family(topology.regions[0])};
    EXPECT_EQ(patch_kind(topology, along), PatchKind::grid);
  }
}

TEST(PatchTopology, TubeHasClosedRingsAcross) {
  // A cylinder of 8 quads around and 6 along, like a braid piece.
  PolyMesh tube;
  int around = 8, rows = 7;
  tube.vertices.resize(around * rows, 3);
  for (int r = 0; r < rows; ++r)
    for (int a = 0; a < around; ++a)
      tube.vertices.row(r * around + a) << 0.02f * std::cos(a * 0.785f), -0.05f * r,
          0.02f * std::sin(a * 0.785f);
  for (int32_t r = 0; r + 1 < rows; ++r)
    for (int32_t a = 0; a < around; ++a) {
      int32_t p = r * around + a, q = r * around + (a + 1) % around;
      tube.append_face(std::vector<int32_t>{p, q, q + around, p + around});
    }
  PatchTopology topology = patch_topology(tube, all_faces(tube));
  const QuadRegion& region = topology.regions[0];
  int rings = region.families[0].closed_chain_count > 0 ? 0 : 1;
  EXPECT_EQ(region.families[rings].closed_chain_count, rows);
  EXPECT_EQ(region.families[1 - rings].closed_chain_count, 0);
  EXPECT_EQ(region.families[1 - rings].chains.size(), static_cast<size_t>(around));
  std::vector<int> along{1 - rings};
  EXPECT_EQ(patch_kind(topology, along), PatchKind::tube);
}

TEST(PatchTopology, PoleIsCountedAndChainsStopThere) {
  // Five quads around a centre vertex (a pole of valence 5), closed into a disc.
  PolyMesh cap;
  cap.vertices.resize(11, 3);
  cap.vertices.row(0) << 0, 0, 0;
  for (int i = 0; i < 10; ++i) {
    double angle = 2 * std::numbers::pi * i / 10, radius = i % 2 ? 0.8 : 1.0;
    cap.vertices.row(1 + i) << static_cast<float>(radius * std::cos(angle)), 0,
        static_cast<float>(radius * std::sin(angle));
  }
  for (int32_t k = 0; k < 5; ++k)
    cap.append_face(std::vector<int32_t>{0, 1 + 2 * k, 2 + 2 * k, 1 + (2 * k + 2) % 10});
  PatchTopology topology = patch_topology(cap, all_faces(cap));
  EXPECT_EQ(topology.interior_poles, 1);
  std::vector<int> along{0};
  EXPECT_EQ(patch_kind(topology, along), PatchKind::cap);
}

TEST(QuadRecovery, TriangulatedGridPairsBackIntoItsQuads) {
  PolyMesh triangles =
      hair_strip(straight(12), Eigen::Vector3d::UnitX(), 0.2, {.rails = 3, .triangulate = true});
  ASSERT_EQ(triangles.face_count(), 48);
  QuadRecovery recovered = quads_from_triangles(triangles);
  EXPECT_EQ(recovered.mesh.face_count(), 24);
  EXPECT_EQ(recovered.triangles_paired, 48);
  EXPECT_EQ(recovered.triangles_left, 0);
  ASSERT_TRUE(recovered.mesh.has_uv());
  EXPECT_EQ(recovered.mesh.corner_uv.rows(), 96);
  PatchTopology topology = patch_topology(recovered.mesh, all_faces(recovered.mesh));
  EXPECT_EQ(topology.regions[0].families[longer_family(topology.regions[0])].chains.size(), 3u);
}

/// A card one quad wide whose right rail runs a quad's height above its left (a card
/// twisted or sheared in 3D, as a ringlet's tube is), each quad split along the diagonal
/// that is the shorter in 3D, with the texture laid flat: a grid of rectangles in UV.
PolyMesh sheared_triangulated_strip(int quads, bool with_uv) {
  const float width = 0.01f, height = 0.006f;
  PolyMesh mesh;
  mesh.vertices.resize(2 * (quads + 1), 3);
  for (int j = 0; j <= quads; ++j) {
    mesh.vertices.row(2 * j) << 0, j * height, 0;                // left
    mesh.vertices.row(2 * j + 1) << width, (j + 1) * height, 0;  // right, one quad up
  }
  std::vector<float> uv;
  auto add = [&](std::array<int32_t, 3> corners) {
    mesh.append_face(std::vector<int32_t>(corners.begin(), corners.end()));
    for (int32_t v : corners) {
      uv.push_back(static_cast<float>(v % 2));
      uv.push_back(static_cast<float>(v / 2) / static_cast<float>(quads));
    }
  };
  for (int j = 0; j < quads; ++j) {
    const int32_t left = 2 * j, right = 2 * j + 1, next_left = 2 * j + 2, next_right = 2 * j + 3;
    add({left, right, next_left});        // split along right-next_left, the shorter
    add({right, next_right, next_left});  // diagonal (0.01 m against 0.016 m)
  }
  if (with_uv)
    mesh.corner_uv = Eigen::Map<Uv2f>(uv.data(), static_cast<Eigen::Index>(uv.size() / 2), 2);
  return mesh;
}

TEST(QuadRecovery, ACardShearedIn3DPairsBackByItsTexturesRectangles) {
  // In 3D the diagonal the triangulation added is no triangle's longest edge, and the
  // triangles across each rung make quads as near to square. In UV the card's quads are
  // rectangles: every pair is found.
  QuadRecovery recovered = quads_from_triangles(sheared_triangulated_strip(8, true));
  EXPECT_EQ(recovered.triangles_paired, 16);
  EXPECT_EQ(recovered.triangles_left, 0);
  for (int64_t f = 0; f < recovered.mesh.face_count(); ++f) {
    // Each quad is one of the card's: its corners two consecutive rungs.
    std::vector<int32_t> corners(recovered.mesh.face(f).begin(), recovered.mesh.face(f).end());
    std::sort(corners.begin(), corners.end());
    ASSERT_EQ(corners.size(), 4u);
    EXPECT_EQ(corners[0] % 2, 0);
    EXPECT_EQ(corners[3], corners[0] + 3) << "face " << f;
  }
  // Without the texture the most square pairs straddle the rungs, which leaves the
  // strip's end triangles alone; the matching re-pairs the strip so that every triangle has
  // a partner, and those are the card's quads.
  QuadRecovery untextured = quads_from_triangles(sheared_triangulated_strip(8, false));
  int card_quads = 0;
  for (int64_t f = 0; f < untextured.mesh.face_count(); ++f) {
    std::vector<int32_t> corners(untextured.mesh.face(f).begin(), untextured.mesh.face(f).end());
    std::sort(corners.begin(), corners.end());
    if (corners.size() == 4 && corners[0] % 2 == 0 && corners[3] == corners[0] + 3) ++card_quads;
  }
  EXPECT_EQ(untextured.triangles_left, 0);
  EXPECT_EQ(card_quads, 8);
}

TEST(QuadRecovery, NeedleTrianglesStayTriangles) {
  PolyMesh fan;
  fan.vertices.resize(4, 3);
  fan.vertices << 0, 0, 0, 1, 0, 0, 0.5f, 0.05f, 0, 1, 0.1f, 0;
  fan.append_face(std::vector<int32_t>{0, 1, 2});
  fan.append_face(std::vector<int32_t>{2, 1, 3});
  QuadRecovery recovered = quads_from_triangles(fan, 30.0);
  EXPECT_EQ(recovered.triangles_paired, 0);
  EXPECT_EQ(recovered.mesh.face_count(), 2);
}

}  // namespace
}  // namespace hair
