// Strands kept within a tolerance of themselves (Douglas-Peucker): straight strands keep
// their ends, curls their bends, every dropped point stays within the tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hair/core/error.h"
#include "hair/geom/strand_simplify.h"

namespace hair {
namespace {

/// A straight strand of 30 points, a helix (a curl: radius 5 mm, 1 cm a turn, 4 turns) of
/// 200 points, and a strand of two points.
StrandSet three_strands() {
  Points3f straight(30, 3), helix(200, 3), pair(2, 3);
  for (int i = 0; i < 30; ++i) straight.row(i) << 0.0f, -0.01f * i, 0.0f;
  for (int i = 0; i < 200; ++i) {
    const double turn = 4.0 * i / 199.0;
    helix.row(i) << static_cast<float>(0.005 * std::cos(2 * std::numbers::pi * turn)),
        static_cast<float>(-0.01 * turn),
        static_cast<float>(0.005 * std::sin(2 * std::numbers::pi * turn));
  }
  pair << 0.1f, 0.0f, 0.0f, 0.1f, -0.1f, 0.0f;
  StrandSet strands = strand_set_from_polylines({straight, helix, pair});
  std::vector<float> along(static_cast<size_t>(strands.point_count()));
  for (size_t i = 0; i < along.size(); ++i) along[i] = static_cast<float>(i);
  strands.point_attributes["along"] = along;
  strands.strand_attributes["id"] = std::vector<int32_t>{7, 8, 9};
  return strands;
}

TEST(StrandSimplify, StraightStrandsKeepTheirEndsCurlsTheirBends) {
  const StrandSet strands = three_strands();
  const double tolerance_m = 0.0005;
  const std::vector<int64_t> rows = rows_within_tolerance(strands, tolerance_m);
  const StrandSet kept = select_points(strands, rows);
  ASSERT_EQ(kept.strand_count(), 3);
  EXPECT_EQ(kept.strand_size(0), 2);  // the straight strand: root and tip
  EXPECT_EQ(kept.strand_size(2), 2);
  // The curl keeps points in every turn: a chord of a 5 mm circle within 0.5 mm spans
  // at most 2 acos(0.9) = 52 degrees, so at least 7 points a turn.
  EXPECT_GE(kept.strand_size(1), 4 * 7);
  EXPECT_LT(kept.strand_size(1), 200);
  // Roots and tips are kept exactly, and every dropped point is within the tolerance.
  for (int64_t s = 0; s < 3; ++s) {
    EXPECT_EQ(kept.strand(s).row(0), strands.strand(s).row(0));
    EXPECT_EQ(kept.strand(s).bottomRows(1), strands.strand(s).bottomRows(1));
  }
  EXPECT_LE(largest_deviation(strands.points, rows), tolerance_m);
  EXPECT_GT(largest_deviation(strands.points, rows), 0.0);
  // Attributes follow their points.
  const auto& along = std::get<std::vector<float>>(kept.point_attributes.at("along"));
  for (size_t k = 0; k < rows.size(); ++k) EXPECT_EQ(along[k], static_cast<float>(rows[k]));
  EXPECT_EQ(std::get<std::vector<int32_t>>(kept.strand_attributes.at("id")),
            (std::vector<int32_t>{7, 8, 9}));
  EXPECT_NO_THROW(check_strand_set(kept));
}

TEST(StrandSimplify, ATighterToleranceKeepsMoreAndZeroKeepsEveryBend) {
  const StrandSet strands = three_strands();
  const size_t loose = rows_within_tolerance(strands, 0.002).size();
  const size_t tight = rows_within_tolerance(strands, 0.0001).size();
  EXPECT_LT(loose, tight);
  // 0: only points exactly on the chord between their kept neighbours go (the straight
  // strand's may, within float rounding); every point of the helix stays.
  const std::vector<int64_t> exact = rows_within_tolerance(strands, 0.0);
  EXPECT_EQ(largest_deviation(strands.points, exact), 0.0);
  EXPECT_EQ(select_points(strands, exact).strand_size(1), 200);
  EXPECT_THROW(rows_within_tolerance(strands, -1e-3), Error);
  EXPECT_THROW(rows_within_tolerance(strands, NAN), Error);
}

}  // namespace
}  // namespace hair
