// How the edge families of a quad region lie against the painted flow, and what the
// alpha fade along rails says: on a flat grid with a flow set by hand, the family along
// the flow is found whichever is longer, and the fade's sign follows the rails' order.
#include <gtest/gtest.h>

#include "hair/extract/rail_paint.h"
#include "hair/mesh/patch_rails.h"
#include "unit/painted_grid.h"

namespace hair {
namespace {

using test::all_faces;
using test::flat_grid;
using test::uniform_flow;

/// The family whose chains run along y (the grid's columns).
int family_along_y(const PolyMesh& mesh, const QuadRegion& region) {
  const auto& chain = region.families[0].chains.front();
  const Eigen::Vector3f step = mesh.vertices.row(chain[1]) - mesh.vertices.row(chain[0]);
  return std::abs(step.y()) > std::abs(step.x()) ? 0 : 1;
}

TEST(RailPaint, TheFamilyAlongThePaintIsFoundWhereTheOtherIsLonger) {
  // A wide grid: the rows (along x) are the longer chains, the paint runs down y, as on
  // a cap whose rings are longer than its strands.
  PolyMesh mesh = flat_grid(12, 4, 0.12f, 0.04f);
  std::vector<int64_t> faces = all_faces(mesh);
  std::vector<PatchTopology> topologies{patch_topology(mesh, faces)};
  ASSERT_EQ(topologies[0].regions.size(), 1u);
  const int along_y = family_along_y(mesh, topologies[0].regions[0]);
  ASSERT_GT(topologies[0].regions[0].families[1 - along_y].mean_chain_length,
            topologies[0].regions[0].families[along_y].mean_chain_length);

  PaintedFlow flow = uniform_flow(mesh, Eigen::Vector3f(0, -1, 0), 0.0f);
  const auto paint = family_paint(mesh, flow, EdgeFaces(mesh), topologies);
  const auto& families = paint[0][0];
  EXPECT_NEAR(families[static_cast<size_t>(along_y)].judged_share, 1.0, 1e-9);
  EXPECT_NEAR(families[static_cast<size_t>(along_y)].along_share, 1.0, 1e-9);
  EXPECT_NEAR(families[static_cast<size_t>(1 - along_y)].along_share, 0.0, 1e-9);
  EXPECT_EQ(family_along_paint(families, 0.5, 0.25), along_y);

  // Paint at 45 degrees lies along neither: the paint does not decide.
  PaintedFlow diagonal = uniform_flow(mesh, Eigen::Vector3f(1, 1, 0), 0.0f);
  EXPECT_EQ(family_along_paint(family_paint(mesh, diagonal, EdgeFaces(mesh), topologies)[0][0], 0.5,
                               0.25),
            -1);
  // Nor does paint that is not clear.
  flow.coherence.assign(flow.coherence.size(), 0.1f);
  const auto unclear = family_paint(mesh, flow, EdgeFaces(mesh), topologies)[0][0];
  EXPECT_EQ(unclear[0].judged_share, 0.0);
  EXPECT_EQ(family_along_paint(unclear, 0.5, 0.25), -1);
}

TEST(RailPaint, TheAlphaFadeVotesForTheRailsRunningTowardsTheTips) {
  PolyMesh mesh = flat_grid(2, 6, 0.02f, 0.06f);
  EdgeFaces edge_faces(mesh);
  // A rail down the middle column, from the top (y = 0.06) to the bottom.
  std::vector<int32_t> down;
  for (int j = 6; j >= 0; --j) down.push_back(j * 3 + 1);
  std::vector<int32_t> up(down.rbegin(), down.rend());
  PaintedFlow fading_down = uniform_flow(mesh, Eigen::Vector3f(0, -1, 0), 0.2f);
  AlphaFade fade = rails_alpha_fade(mesh, fading_down, edge_faces, {down});
  EXPECT_NEAR(fade.vote, 1.0, 1e-9);
  EXPECT_NEAR(fade.mean_fall, 0.2, 1e-6);
  EXPECT_EQ(fade.judged_edges, 6);
  EXPECT_NEAR(rails_alpha_fade(mesh, fading_down, edge_faces, {up}).vote, -1.0, 1e-9);
  // Without a fade the vote stays 0.
  PaintedFlow flat = uniform_flow(mesh, Eigen::Vector3f(0, -1, 0), 0.0f);
  EXPECT_EQ(rails_alpha_fade(mesh, flat, edge_faces, {down}).vote, 0.0);
}

TEST(RailPaint, TheFallAlongAWholeRailIsTheSameHoweverFinelyTheCardIsCut) {
  // The same 6 cm card fading by 1.2 from one end to the other, cut into 6 faces along
  // its length and into 24: the fall per face drops fourfold, the fall along the rail
  // does not (a tube or a finely cut card fades by little per face).
  for (int faces_along : {6, 24}) {
    SCOPED_TRACE(faces_along);
    PolyMesh mesh = flat_grid(2, faces_along, 0.02f, 0.06f);
    EdgeFaces edge_faces(mesh);
    std::vector<std::vector<int32_t>> rails(2);
    for (int j = faces_along; j >= 0; --j) {
      rails[0].push_back(j * 3 + 1);  // the middle column, top down
      rails[1].push_back(j * 3 + 2);  // the right edge
    }
    PaintedFlow flow = uniform_flow(mesh, Eigen::Vector3f(0, -1, 0), 1.2f / faces_along);
    AlphaFade fade = rails_alpha_fade(mesh, flow, edge_faces, rails);
    EXPECT_NEAR(fade.mean_fall, 1.2 / faces_along, 1e-6);
    EXPECT_EQ(fade.judged_rails, 2);
    EXPECT_NEAR(fade.mean_rail_fall, 1.2, 1e-5);
  }
}

}  // namespace
}  // namespace hair
