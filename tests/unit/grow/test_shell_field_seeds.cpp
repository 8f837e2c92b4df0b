// Seeds under hair that lies off the head (shell_field_seeds.h), on a sphere 10 cm in radius:
// a strand 3.5 cm off it, one lying on it, one standing on it, one beyond max_height_m, and
// an inner layer under the first.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <vector>

#include "hair/grow/shell_field_seeds.h"
#include "unit/icosphere.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;

constexpr double kRadius = 0.1;
const Vec3 kCentre(0, 1.5, 0);

double radians(double degrees) { return degrees * std::numbers::pi / 180; }

/// A strand down the back of the sphere (azimuth 180 degrees: -Z) from polar angle
/// `first_deg` to `last_deg`, `height_m` off it, 2.5 degrees a segment.
Points3f arc(double height_m, double first_deg, double last_deg) {
  const int count = static_cast<int>(std::round((last_deg - first_deg) / 2.5)) + 1;
  Points3f points(count, 3);
  for (int i = 0; i < count; ++i) {
    const double polar = radians(first_deg + (last_deg - first_deg) * i / (count - 1));
    const Vec3 p = kCentre + (kRadius + height_m) * Vec3(0, std::cos(polar), -std::sin(polar));
    points.row(i) = p.cast<float>().transpose();
  }
  return points;
}

/// A strand standing on the sphere's top, 5 cm straight up from 5 mm over it.
Points3f spike() {
  Points3f points(11, 3);
  for (int i = 0; i < 11; ++i)
    points.row(i) = (kCentre + Vec3(0, kRadius + 0.005 + 0.005 * i, 0)).cast<float>().transpose();
  return points;
}

Points3f all_points(const std::vector<Points3f>& strands) {
  Eigen::Index count = 0;
  for (const Points3f& s : strands) count += s.rows();
  Points3f points(count, 3);
  Eigen::Index row = 0;
  for (const Points3f& s : strands) {
    points.middleRows(row, s.rows()) = s;
    row += s.rows();
  }
  return points;
}

struct Fixture {
  testing::SphereMesh sphere = testing::icosphere(4, kRadius, kCentre);
  TriangleMeshDistance body{sphere.vertices, sphere.triangles};
  ShellSeedParams params;
  Fixture() {
    params.spacing_m = 0.014;
    params.max_height_m = 0.07;
  }
};

// 3.5 cm off: two levels (0.7 and 2.1 cm over the sphere: the band of 1.4 cm round each
// reaches the body and the strand), each a copy of the strand running its way.
TEST(ShellFieldSeeds, HairOffTheHeadIsSeededLevelByLevelDownToIt) {
  Fixture f;
  const std::vector<Points3f> strands = {arc(0.035, 20, 90)};
  const PointIndex hair(all_points(strands));
  const StrandSet seeds = seeds_under_strands(strands, f.body, hair, f.params);
  const auto& level = std::get<std::vector<int32_t>>(seeds.strand_attributes.at("level"));
  ASSERT_EQ(seeds.strand_count(), 2);
  EXPECT_EQ(std::get<std::vector<int32_t>>(seeds.strand_attributes.at("strand")),
            (std::vector<int32_t>{0, 0}));
  for (int64_t s = 0; s < 2; ++s) {
    EXPECT_EQ(level[static_cast<size_t>(s)], s);
    const double height_m = 0.014 * (0.5 + static_cast<double>(s));
    EXPECT_EQ(seeds.offsets[s + 1] - seeds.offsets[s], strands[0].rows());
    for (int64_t row = seeds.offsets[s]; row < seeds.offsets[s + 1]; ++row) {
      const Vec3 p = seeds.points.row(row).cast<double>().transpose();
      EXPECT_NEAR(f.body.distance(p), height_m, 0.0005);
      if (row + 1 < seeds.offsets[s + 1]) {
        const Vec3 seed_step =
            (seeds.points.row(row + 1) - seeds.points.row(row)).cast<double>().transpose();
        const int64_t i = row - seeds.offsets[s];
        const Vec3 strand_step =
            (strands[0].row(i + 1) - strands[0].row(i)).cast<double>().transpose();
        EXPECT_GT(seed_step.normalized().dot(strand_step.normalized()), 0.99);
      }
    }
  }
}

// Hair lying on the head (5 mm off), standing on it (a spike), or beyond max_height_m
// (8 cm off: hanging away from the head) seeds nothing under it.
TEST(ShellFieldSeeds, HairOnTheHeadStandingOnItOrHangingAwaySeedsNothing) {
  Fixture f;
  for (const Points3f& strand : {arc(0.005, 20, 90), spike(), arc(0.08, 20, 90)}) {
    const std::vector<Points3f> strands = {strand};
    const PointIndex hair(all_points(strands));
    EXPECT_EQ(seeds_under_strands(strands, f.body, hair, f.params).strand_count(), 0);
  }
  // Below min_foot_y_m (the scalp's lowest point): the part of the shell over the sphere's
  // lower half seeds nothing; the upper half as before, in two runs (levels) of 17 points
  // each (polar 20-60 degrees).
  f.params.min_foot_y_m = kCentre.y() + kRadius * std::cos(radians(61));
  const std::vector<Points3f> strands = {arc(0.035, 20, 90)};
  const PointIndex hair(all_points(strands));
  const StrandSet seeds = seeds_under_strands(strands, f.body, hair, f.params);
  ASSERT_EQ(seeds.strand_count(), 2);
  EXPECT_EQ(seeds.offsets[1], 17);
  for (int64_t row = 0; row < seeds.points.rows(); ++row)
    EXPECT_GE(seeds.points(row, 1), f.params.min_foot_y_m);
}

// An inner layer of hair 7 mm over the head, under the upper half of the shell: the lowest
// level is left out where it lies within half a spacing of that layer (its own strands seed
// it there), kept under the lower half.
TEST(ShellFieldSeeds, AnInnerLayerUnderTheShellKeepsItsOwnDirection) {
  Fixture f;
  const std::vector<Points3f> shell = {arc(0.035, 20, 90)};
  const Points3f inner = arc(0.007, 20, 55);
  const PointIndex hair(all_points({shell[0], inner}));
  const StrandSet seeds = seeds_under_strands(shell, f.body, hair, f.params);
  const auto& level = std::get<std::vector<int32_t>>(seeds.strand_attributes.at("level"));
  int64_t lowest_points = 0, upper_points = 0;
  for (int64_t s = 0; s < seeds.strand_count(); ++s)
    for (int64_t row = seeds.offsets[s]; row < seeds.offsets[s + 1]; ++row) {
      const Vec3 p = seeds.points.row(row).cast<double>().transpose();
      const double polar_deg = std::acos((p - kCentre).normalized().y()) * 180 / std::numbers::pi;
      if (level[static_cast<size_t>(s)] == 0) {
        ++lowest_points;
        EXPECT_GT(polar_deg, 55) << "a lowest seed over the inner layer";
      } else {
        ++upper_points;
      }
    }
  EXPECT_GT(lowest_points, 5);
  EXPECT_EQ(upper_points, shell[0].rows());  // the level above the inner layer is whole
}

}  // namespace
}  // namespace hair
