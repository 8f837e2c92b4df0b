// Points along a polyline by arc length.
#include <gtest/gtest.h>

#include "hair/geom/polyline.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;

TEST(Polyline, PointAtArcFractionWalksTheArcLength) {
  // An L: 3 m along x, then 1 m along y; 4 m in all.
  const std::vector<Vec3> l{Vec3(0, 0, 0), Vec3(3, 0, 0), Vec3(3, 1, 0)};
  EXPECT_TRUE(point_at_arc_fraction(l, 0).isApprox(Vec3(0, 0, 0)));
  EXPECT_TRUE(point_at_arc_fraction(l, 0.5).isApprox(Vec3(2, 0, 0)));
  EXPECT_TRUE(point_at_arc_fraction(l, 0.875).isApprox(Vec3(3, 0.5, 0)));
  EXPECT_TRUE(point_at_arc_fraction(l, 1).isApprox(Vec3(3, 1, 0)));
  EXPECT_TRUE(point_at_arc_fraction(l, 7).isApprox(Vec3(3, 1, 0)));     // clamped
  EXPECT_TRUE(point_at_arc_fraction(l, -1).isApprox(Vec3(0, 0, 0)));    // clamped
  // Repeated points are skipped; a polyline with no length is its first point.
  const std::vector<Vec3> repeated{Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(0, 2, 0)};
  EXPECT_TRUE(point_at_arc_fraction(repeated, 0.25).isApprox(Vec3(0, 0.5, 0)));
  const std::vector<Vec3> point{Vec3(1, 2, 3), Vec3(1, 2, 3)};
  EXPECT_TRUE(point_at_arc_fraction(point, 0.5).isApprox(Vec3(1, 2, 3)));
  EXPECT_TRUE(point_at_arc_fraction({Vec3(4, 5, 6)}, 0.5).isApprox(Vec3(4, 5, 6)));
}

}  // namespace
}  // namespace hair
