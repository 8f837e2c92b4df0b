#include <gtest/gtest.h>

#include <array>
#include <limits>
#include <string>

#include "hair/core/error.h"
#include "hair/core/strand_set.h"
#include "unit/point_rows.h"

namespace {

using hair::test::rows;

/// Two strands (3 and 2 points) with one attribute of each kind.
hair::StrandSet two_strands() {
  hair::StrandSet strands;
  strands.append_strand(rows({{0, 0, 0}, {0, -1, 0}, {0, -2, 0}}));
  strands.append_strand(rows({{1, 0, 0}, {1, -1, 0}}));
  strands.strand_attributes["group"] = std::vector<int32_t>{7, -1};
  strands.point_attributes["thickness_m"] = std::vector<float>{1, 2, 3, 4, 5};
  strands.point_attributes["rest"] = strands.points;
  return strands;
}

std::string check_message(const hair::StrandSet& strands, int min_points_per_strand = 2) {
  try {
    hair::check_strand_set(strands, min_points_per_strand);
  } catch (const hair::Error& error) {
    EXPECT_EQ(error.kind(), hair::ErrorKind::runtime);
    return error.what();
  }
  return "";
}

TEST(StrandSet, AppendBuildsCsrLayout) {
  const hair::StrandSet strands = two_strands();
  EXPECT_EQ(strands.strand_count(), 2);
  EXPECT_EQ(strands.point_count(), 5);
  EXPECT_EQ(strands.offsets, (std::vector<int64_t>{0, 3, 5}));
  EXPECT_EQ(strands.strand_size(0), 3);
  EXPECT_EQ(strands.strand(1), rows({{1, 0, 0}, {1, -1, 0}}));
  EXPECT_EQ(strands.points.row(2), rows({{0, -2, 0}}));
}

TEST(StrandSet, AppendEmptyStrandRepeatsTheOffset) {
  hair::StrandSet strands;
  strands.append_strand(hair::Points3f(0, 3));
  strands.append_strand(rows({{0, 0, 0}, {1, 0, 0}}));
  EXPECT_EQ(strands.offsets, (std::vector<int64_t>{0, 0, 2}));
  EXPECT_EQ(strands.strand_size(0), 0);
}

TEST(StrandSet, CheckAcceptsAValidSet) {
  EXPECT_EQ(check_message(two_strands()), "");
  EXPECT_EQ(check_message(hair::StrandSet{}), "");
}

TEST(StrandSet, CheckNamesBrokenOffsets) {
  hair::StrandSet strands = two_strands();
  strands.offsets = {};
  EXPECT_EQ(check_message(strands),
            "offsets is empty, expected #strands + 1 entries starting at 0");
  strands.offsets = {1, 3, 5};
  EXPECT_EQ(check_message(strands), "offsets[0] = 1, expected 0");
  strands.offsets = {0, 3, 2, 5};
  EXPECT_EQ(check_message(strands), "offsets decrease at strand 1 (3 then 2)");
  strands.offsets = {0, 3, 4};
  EXPECT_EQ(check_message(strands), "offsets end at 4, expected #points = 5");
}

TEST(StrandSet, CheckNamesShortStrands) {
  const hair::StrandSet strands = two_strands();
  EXPECT_EQ(check_message(strands, 3), "strand 1 has 2 points, expected at least 3");
  hair::StrandSet single;
  single.append_strand(rows({{0, 0, 0}}));
  EXPECT_EQ(check_message(single), "strand 0 has 1 point, expected at least 2");
  EXPECT_EQ(check_message(single, 1), "");
}

TEST(StrandSet, CheckNamesTheStrandOfANonFiniteCoordinate) {
  hair::StrandSet strands = two_strands();
  strands.points(4, 1) = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(check_message(strands), "strand 1 point 1 is not finite (1, nan, 0)");
  strands.points(4, 1) = std::numeric_limits<float>::infinity();
  EXPECT_EQ(check_message(strands), "strand 1 point 1 is not finite (1, inf, 0)");
}

TEST(StrandSet, CheckNamesAttributesOfTheWrongLength) {
  hair::StrandSet strands = two_strands();
  strands.strand_attributes["group"] = std::vector<int32_t>{7};
  EXPECT_EQ(check_message(strands),
            "strand attribute 'group' has 1 entries, expected #strands = 2");
  strands = two_strands();
  strands.point_attributes["rest"] = hair::Points3f::Zero(4, 3);
  EXPECT_EQ(check_message(strands), "point attribute 'rest' has 4 entries, expected #points = 5");
}

}  // namespace

namespace hair {
namespace {

TEST(StrandSetFromPolylines, MatchesAppendingOneByOne) {
  std::vector<Points3f> polylines;
  StrandSet appended;
  for (int s = 0; s < 5; ++s) {
    Points3f polyline(2 + s, 3);
    for (int i = 0; i < polyline.rows(); ++i)
      polyline.row(i) << static_cast<float>(s), static_cast<float>(i), 0.5f;
    polylines.push_back(polyline);
    appended.append_strand(polyline);
  }
  StrandSet built = strand_set_from_polylines(polylines);
  EXPECT_EQ(built.offsets, appended.offsets);
  EXPECT_TRUE(built.points == appended.points);
  EXPECT_EQ(strand_set_from_polylines({}).strand_count(), 0);
}

}  // namespace
}  // namespace hair
