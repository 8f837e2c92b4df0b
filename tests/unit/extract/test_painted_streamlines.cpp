// Strands traced along the painted flow over a patch: on a flat grid with a uniform
// diagonal flow the streamlines are straight lines along it, kept apart by the spacing,
// covering the patch; they stop at the border and where the paint is not clear.
#include <gtest/gtest.h>

#include "hair/extract/painted_streamlines.h"
#include "unit/painted_grid.h"

namespace hair {
namespace {

using test::all_faces;
using test::flat_grid;
using test::uniform_flow;

TEST(PaintedStreamlines, ADiagonalFlowGivesStraightEvenlySpacedLinesAlongIt) {
  const float cell = 0.01f;
  PolyMesh mesh = flat_grid(10, 10, 10 * cell, 10 * cell);  // 10 cm square
  const Eigen::Vector3f diagonal = Eigen::Vector3f(1, 1, 0).normalized();
  PaintedFlow flow = uniform_flow(mesh, diagonal, 0.0f);
  StreamlineParams params;
  params.spacing_m = cell;
  params.min_length_m = 2 * cell;
  std::vector<int64_t> faces = all_faces(mesh);
  std::vector<PaintedStreamline> lines = painted_streamlines(mesh, flow, faces, params);
  // Diagonals of a 10-cell square spaced one cell apart across the flow: about
  // 2 x 10 / sqrt(2) = 14, fewer short ones at the corners.
  EXPECT_GE(lines.size(), 8u);
  EXPECT_LE(lines.size(), 20u);
  double total_length = 0;
  for (const PaintedStreamline& line : lines) {
    ASSERT_GE(line.points.rows(), 2);
    EXPECT_TRUE(line.points.allFinite());
    for (Eigen::Index i = 1; i < line.points.rows(); ++i) {
      Eigen::Vector3f step = line.points.row(i) - line.points.row(i - 1);
      ASSERT_GT(step.norm(), 0);
      EXPECT_GT(std::abs(step.normalized().dot(diagonal)), std::cos(1 * M_PI / 180));
      total_length += step.norm();
    }
    // Inside the square.
    EXPECT_GE(line.points.minCoeff(), -1e-6f);
    EXPECT_LE(line.points.col(0).maxCoeff(), 10 * cell + 1e-6f);
  }
  // Together they cover the square: its area over the spacing, within a factor.
  const double expected_length = 0.1 * 0.1 / cell;
  EXPECT_GT(total_length, 0.6 * expected_length);
  EXPECT_LT(total_length, 1.6 * expected_length);
  // Apart: no point of one line within half the spacing of another's point.
  for (size_t a = 0; a < lines.size(); ++a)
    for (size_t b = a + 1; b < lines.size(); ++b)
      for (Eigen::Index i = 0; i < lines[a].points.rows(); ++i)
        for (Eigen::Index j = 0; j < lines[b].points.rows(); ++j)
          EXPECT_GT((lines[a].points.row(i) - lines[b].points.row(j)).norm(), 0.45 * cell);
  // The same again: deterministic.
  std::vector<PaintedStreamline> again = painted_streamlines(mesh, flow, faces, params);
  ASSERT_EQ(again.size(), lines.size());
  for (size_t i = 0; i < lines.size(); ++i) EXPECT_EQ(again[i].points, lines[i].points);
}

TEST(PaintedStreamlines, TheyStopWhereThePaintIsNotClearAndCarryTheFade) {
  const float cell = 0.01f;
  PolyMesh mesh = flat_grid(4, 10, 4 * cell, 10 * cell);  // 4 cm wide, 10 cm tall
  PaintedFlow flow = uniform_flow(mesh, Eigen::Vector3f(0, -1, 0), 0.3f);  // tips down
  // The upper half has no clear paint.
  for (int64_t f = 0; f < mesh.face_count(); ++f)
    if (f >= 4 * 5) flow.coherence[static_cast<size_t>(f)] = 0.05f;
  StreamlineParams params;
  params.spacing_m = cell;
  params.min_length_m = 2 * cell;
  std::vector<int64_t> faces = all_faces(mesh);
  std::vector<PaintedStreamline> lines = painted_streamlines(mesh, flow, faces, params);
  ASSERT_GE(lines.size(), 2u);
  for (const PaintedStreamline& line : lines) {
    EXPECT_LE(line.points.col(1).maxCoeff(), 5 * cell + 1e-6f);  // not into the upper half
    // The alpha falls towards the line's lower end.
    const bool runs_down = line.points(0, 1) > line.points(line.points.rows() - 1, 1);
    EXPECT_NEAR(line.fade_vote, runs_down ? 1.0 : -1.0, 1e-6);
    EXPECT_NEAR(line.fade_mean_fall, 0.3, 1e-3);
  }
  // No clear paint anywhere: no streamlines.
  flow.coherence.assign(flow.coherence.size(), 0.0f);
  EXPECT_TRUE(painted_streamlines(mesh, flow, faces, params).empty());
}

}  // namespace
}  // namespace hair
