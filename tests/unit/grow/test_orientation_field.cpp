// The orientation field on hand-made strands with known directions: parallel strands,
// two sheets of opposite slant, an arc; the band's extent, determinism and bad input.
#include <gtest/gtest.h>
#include <omp.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

#include "hair/core/error.h"
#include "hair/grow/orientation_field.h"
#include "unit/point_rows.h"

namespace hair {
namespace {

using test::rows;

/// Uniform draws from a fixed generator, the same on every platform.
class Random {
 public:
  explicit Random(uint64_t seed) : random_(seed) {}
  double uniform() { return static_cast<double>(random_() >> 11) * 0x1.0p-53; }
  double uniform(double low, double high) { return low + (high - low) * uniform(); }

 private:
  std::mt19937_64 random_;
};

/// A straight strand of `count` points from `root` along `step` per point.
Points3f straight(const Eigen::Vector3d& root, const Eigen::Vector3d& step, int count) {
  Points3f points(count, 3);
  for (int i = 0; i < count; ++i) points.row(i) = (root + i * step).transpose().cast<float>();
  return points;
}

std::vector<int64_t> all_ids(const StrandSet& strands) {
  std::vector<int64_t> ids;
  for (int64_t s = 0; s < strands.strand_count(); ++s) ids.push_back(s);
  return ids;
}

OrientationField build_all(const StrandSet& strands, const OrientationFieldParams& params = {}) {
  return OrientationField::build(strands, all_ids(strands), params);
}

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b)) * 180 / std::numbers::pi;
}

/// A 5 x 5 bundle of parallel straight strands along an oblique direction.
StrandSet parallel_bundle(const Eigen::Vector3d& direction) {
  std::vector<Points3f> polylines;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      polylines.push_back(
          straight(Eigen::Vector3d(0.004 * i, 0.1, 0.004 * j), 0.006 * direction, 20));
  return strand_set_from_polylines(polylines);
}

TEST(OrientationField, ParallelStrandsGiveTheirDirectionEverywhere) {
  const Eigen::Vector3d direction = Eigen::Vector3d(0.3, -1.0, 0.2).normalized();
  StrandSet strands = parallel_bundle(direction);
  OrientationField field = build_all(strands);
  ASSERT_GT(field.seeded_voxel_count(), 0);
  ASSERT_GT(field.band_voxel_count(), 2 * field.seeded_voxel_count());
  for (int64_t voxel = 0; voxel < field.band_voxel_count(); ++voxel) {
    ASSERT_LT((field.voxel_direction(voxel) - direction).norm(), 1e-6) << "voxel " << voxel;
    EXPECT_TRUE(field.contains(field.voxel_centre_m(voxel)));
  }
  // Anywhere in the box: inside the band the direction, outside nothing.
  Random random(3);
  int inside = 0;
  for (int i = 0; i < 20000; ++i) {
    Eigen::Vector3d point;
    for (int axis = 0; axis < 3; ++axis)
      point[axis] = random.uniform(field.box_low_m()[axis], field.box_high_m()[axis]);
    std::optional<Eigen::Vector3d> found = field.direction(point);
    ASSERT_EQ(found.has_value(), field.contains(point));
    if (!found) continue;
    ++inside;
    ASSERT_LT((*found - direction).norm(), 1e-6);
  }
  EXPECT_GT(inside, 1000);
}

TEST(OrientationField, BandIsEveryVoxelWithinBandOfASeed) {
  // One strand along x through voxel centres: the seeds are the voxels x = 0 .. 19 on the
  // row y = z = 0, and the band the voxels whose centres lie within 3 voxels of them.
  StrandSet strands = strand_set_from_polylines(
      {straight(Eigen::Vector3d(0.0025, 0.0025, 0.0025), Eigen::Vector3d(0.005, 0, 0), 20)});
  OrientationField field = build_all(strands);
  EXPECT_EQ(field.seeded_voxel_count(), 20);
  int64_t expected = 0;
  for (int z = -5; z <= 5; ++z)
    for (int y = -5; y <= 5; ++y)
      for (int x = -5; x <= 25; ++x) {
        int dx = x < 0 ? -x : (x > 19 ? x - 19 : 0);
        bool in_band = dx * dx + y * y + z * z <= 9;
        expected += in_band;
        Eigen::Vector3d centre =
            (Eigen::Vector3d(x, y, z) + Eigen::Vector3d::Constant(0.5)) * 0.005;
        ASSERT_EQ(field.contains(centre), in_band) << x << " " << y << " " << z;
      }
  EXPECT_EQ(field.band_voxel_count(), expected);
  EXPECT_TRUE(field.box_low_m().isApprox(Eigen::Vector3d(-0.015, -0.015, -0.015)));
  EXPECT_TRUE(field.box_high_m().isApprox(Eigen::Vector3d(0.115, 0.02, 0.02)));
  for (int64_t voxel = 0; voxel < field.band_voxel_count(); ++voxel)
    EXPECT_EQ(field.voxel_seeded(voxel),
              std::abs(field.voxel_centre_m(voxel).y() - 0.0025) < 1e-9 &&
                  std::abs(field.voxel_centre_m(voxel).z() - 0.0025) < 1e-9 &&
                  field.voxel_centre_m(voxel).x() > 0 && field.voxel_centre_m(voxel).x() < 0.1);
}

TEST(OrientationField, DirectionTurnsMonotonicallyAcrossTheGapBetweenTwoSheets) {
  // Two sheets of strands in the planes z = 2.5 mm and z = 22.5 mm (voxel centres, 4 voxels
  // apart: 3 empty voxels between), slanting to +x and to -x while falling along -y.
  const Eigen::Vector3d lower = Eigen::Vector3d(0.5, -1, 0).normalized();
  const Eigen::Vector3d upper = Eigen::Vector3d(-0.5, -1, 0).normalized();
  std::vector<Points3f> polylines;
  for (int i = 0; i < 40; ++i) {
    double x = -0.05 + 0.0025 * i;
    polylines.push_back(straight(Eigen::Vector3d(x, 0, 0.0025), 0.005 * lower, 30));
    polylines.push_back(straight(Eigen::Vector3d(x, 0, 0.0225), 0.005 * upper, 30));
  }
  OrientationField field = build_all(strand_set_from_polylines(polylines));

  std::optional<double> previous;
  for (int step = 0; step <= 20; ++step) {
    Eigen::Vector3d point(0.0, -0.07, 0.0025 + 0.001 * step);
    std::optional<Eigen::Vector3d> found = field.direction(point);
    ASSERT_TRUE(found) << "z = " << point.z();
    EXPECT_LT(found->y(), -0.85);
    EXPECT_LT(std::abs(found->z()), 1e-9);
    if (previous) {
      EXPECT_LT(found->x(), *previous - 1e-3) << "z = " << point.z();
    }
    previous = found->x();
  }
  EXPECT_NEAR(field.direction(Eigen::Vector3d(0.0, -0.07, 0.0025))->x(), lower.x(), 1e-3);
  EXPECT_NEAR(field.direction(Eigen::Vector3d(0.0, -0.07, 0.0225))->x(), upper.x(), 1e-3);
  // Halfway the slants about cancel: straight down (the sheets' ends, 5 cm and 8 cm away,
  // are not quite symmetric about the query point).
  EXPECT_NEAR(field.direction(Eigen::Vector3d(0.0, -0.07, 0.0125))->x(), 0, 0.01);
}

TEST(OrientationField, FollowsTheTangentOfAnArc) {
  // A quarter circle of radius 10 cm in the plane z = 0, 60 points, counter-clockwise.
  const double radius_m = 0.1;
  const int count = 60;
  Points3f arc(count, 3);
  auto angle_at = [&](double t) { return 0.5 * std::numbers::pi * t; };
  for (int i = 0; i < count; ++i) {
    double angle = angle_at(static_cast<double>(i) / (count - 1));
    arc.row(i) << static_cast<float>(radius_m * std::cos(angle)),
        static_cast<float>(radius_m * std::sin(angle)), 0.001f;
  }
  OrientationField field = build_all(strand_set_from_polylines({arc}));
  double worst_deg = 0;
  for (int i = 0; i <= 200; ++i) {
    double angle = angle_at(0.05 + 0.9 * i / 200.0);  // away from the ends
    Eigen::Vector3d point(radius_m * std::cos(angle), radius_m * std::sin(angle), 0.001);
    Eigen::Vector3d tangent(-std::sin(angle), std::cos(angle), 0);
    std::optional<Eigen::Vector3d> found = field.direction(point);
    ASSERT_TRUE(found) << "angle " << angle;
    worst_deg = std::max(worst_deg, angle_deg(*found, tangent));
  }
  std::printf(
      "[ field    ] arc of radius %.2f m, voxel 5 mm: worst angle to the tangent %.2f deg\n",
      radius_m, worst_deg);
  EXPECT_LT(worst_deg, 4.0);
}

TEST(OrientationField, NothingOutsideTheBand) {
  StrandSet strands = strand_set_from_polylines(
      {straight(Eigen::Vector3d(0.0025, 0.0025, 0.0025), Eigen::Vector3d(0.005, 0, 0), 20)});
  OrientationField field = build_all(strands);
  for (const Eigen::Vector3d& point :
       {Eigen::Vector3d(0.05, 0.025, 0.0025), Eigen::Vector3d(0.05, 0.0025, -0.02),
        Eigen::Vector3d(-0.03, 0.0025, 0.0025), Eigen::Vector3d(0.14, 0.0025, 0.0025),
        Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(-1e30, 0, 0), Eigen::Vector3d(std::nan(""), 0, 0),
        Eigen::Vector3d(std::numeric_limits<double>::infinity(), 0, 0)}) {
    EXPECT_FALSE(field.contains(point)) << point.transpose();
    EXPECT_FALSE(field.direction(point)) << point.transpose();
  }
  // Just inside the band's edge, 3 voxels off the strand: the strand's direction.
  Eigen::Vector3d edge(0.05, 0.0025 + 0.0151, 0.0025);
  ASSERT_TRUE(field.direction(edge));
  EXPECT_LT((*field.direction(edge) - Eigen::Vector3d::UnitX()).norm(), 1e-9);

  OrientationField empty;
  EXPECT_FALSE(empty.contains(Eigen::Vector3d::Zero()));
  EXPECT_FALSE(empty.direction(Eigen::Vector3d::Zero()));
  EXPECT_EQ(empty.band_voxel_count(), 0);
}

TEST(OrientationField, OnlyTheChosenStrandsCount) {
  // Two crossing strands; a field of one of them ignores the other.
  StrandSet strands = strand_set_from_polylines(
      {straight(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.005, 0, 0), 20),
       straight(Eigen::Vector3d(0.05, -0.05, 0), Eigen::Vector3d(0, 0.005, 0), 20)});
  OrientationField first = OrientationField::build(strands, {0}, {});
  EXPECT_LT(
      (*first.direction(Eigen::Vector3d(0.05, 0.001, 0.001)) - Eigen::Vector3d::UnitX()).norm(),
      1e-9);
  EXPECT_FALSE(first.contains(Eigen::Vector3d(0.05, -0.04, 0)));
  OrientationField second = OrientationField::build(strands, {1}, {});
  EXPECT_LT(
      (*second.direction(Eigen::Vector3d(0.05, 0.001, 0.001)) - Eigen::Vector3d::UnitY()).norm(),
      1e-9);
}

/// About 200 strands of 30 points falling from a head-sized sphere: roots on the upper
/// half of a sphere of radius 10 cm, each strand leaving along the normal and bending
/// down; about 0.3 x 0.4 x 0.3 m.
StrandSet hair_like(int strand_count, uint64_t seed) {
  Random random(seed);
  std::vector<Points3f> polylines;
  for (int s = 0; s < strand_count; ++s) {
    double azimuth = random.uniform(0, 2 * std::numbers::pi);
    double elevation = random.uniform(0.1, 0.5 * std::numbers::pi);
    Eigen::Vector3d normal(std::cos(elevation) * std::cos(azimuth), std::sin(elevation),
                           std::cos(elevation) * std::sin(azimuth));
    Eigen::Vector3d point = 0.1 * normal;
    Eigen::Vector3d heading = normal;
    Points3f strand(30, 3);
    for (int i = 0; i < 30; ++i) {
      strand.row(i) = point.transpose().cast<float>();
      heading = (heading + Eigen::Vector3d(0, -0.25, 0)).normalized();
      point += 0.01 * heading;
    }
    polylines.push_back(strand);
  }
  return strand_set_from_polylines(polylines);
}

bool identical(const OrientationField& a, const OrientationField& b) {
  if (a.band_voxel_count() != b.band_voxel_count() ||
      a.seeded_voxel_count() != b.seeded_voxel_count() || a.box_low_m() != b.box_low_m() ||
      a.box_high_m() != b.box_high_m())
    return false;
  for (int64_t voxel = 0; voxel < a.band_voxel_count(); ++voxel)
    if (std::memcmp(a.voxel_direction(voxel).data(), b.voxel_direction(voxel).data(),
                    3 * sizeof(double)) != 0 ||
        a.voxel_seeded(voxel) != b.voxel_seeded(voxel) ||
        a.voxel_centre_m(voxel) != b.voxel_centre_m(voxel))
      return false;
  return true;
}

TEST(OrientationField, DeterministicWhateverTheThreadCount) {
  // 8 strands: CHOLMOD solves; 60 strands: conjugate gradients.
  for (int strand_count : {8, 60}) {
    StrandSet strands = hair_like(strand_count, 7);
    const int threads_before = omp_get_max_threads();
    omp_set_num_threads(1);
    OrientationField one = build_all(strands);
    omp_set_num_threads(2);
    OrientationField two = build_all(strands);
    OrientationField again = build_all(strands);
    omp_set_num_threads(threads_before);
    int64_t unknowns = one.band_voxel_count() - one.seeded_voxel_count();
    EXPECT_EQ(unknowns > OrientationFieldParams{}.direct_max_unknowns, strand_count == 60);
    EXPECT_TRUE(identical(one, two)) << strand_count << " strands";
    EXPECT_TRUE(identical(two, again)) << strand_count << " strands";
  }
}

TEST(OrientationField, ConjugateGradientsAgreeWithCholmod) {
  StrandSet strands = hair_like(20, 13);
  OrientationFieldParams direct, iterative;
  direct.direct_max_unknowns = 1'000'000;
  iterative.direct_max_unknowns = 0;
  OrientationField exact = build_all(strands, direct);
  ASSERT_GT(exact.band_voxel_count(), 5000);
  for (double tolerance : {1e-6, 1e-8, 1e-10}) {
    iterative.cg_tolerance = tolerance;
    OrientationField approximate = build_all(strands, iterative);
    ASSERT_EQ(approximate.band_voxel_count(), exact.band_voxel_count());
    double worst = 0;
    for (int64_t voxel = 0; voxel < exact.band_voxel_count(); ++voxel)
      worst = std::max(worst,
                       (approximate.voxel_direction(voxel) - exact.voxel_direction(voxel)).norm());
    std::printf("[ field    ] %lld band voxels: CG to %.0e differs from CHOLMOD by %.1e at most\n",
                static_cast<long long>(exact.band_voxel_count()), tolerance, worst);
    EXPECT_LT(worst, 1e3 * tolerance);
  }
}

TEST(OrientationField, HairSizedClusterTimings) {
  StrandSet strands = hair_like(200, 11);
  Eigen::Vector3f low = strands.points.colwise().minCoeff(),
                  high = strands.points.colwise().maxCoeff();
  auto start = std::chrono::steady_clock::now();
  OrientationField field = build_all(strands);
  double build_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // Queries near the strands' points, jittered by up to a voxel.
  Random random(5);
  std::vector<Eigen::Vector3d> queries;
  for (int i = 0; i < 1'000'000; ++i) {
    auto row =
        static_cast<Eigen::Index>(random.uniform() * static_cast<double>(strands.point_count()));
    Eigen::Vector3d jitter(random.uniform(-0.005, 0.005), random.uniform(-0.005, 0.005),
                           random.uniform(-0.005, 0.005));
    queries.push_back(strands.points.row(row).transpose().cast<double>() + jitter);
  }
  start = std::chrono::steady_clock::now();
  int64_t found = 0;
  double checksum = 0;
  for (const Eigen::Vector3d& query : queries)
    if (std::optional<Eigen::Vector3d> direction = field.direction(query)) {
      ++found;
      checksum += direction->y();
    }
  double query_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "[ field    ] %lld strands over %.2f x %.2f x %.2f m, voxel 5 mm, band 15 mm: build %.3f s, "
      "%lld band voxels (%lld seeded), 1e6 direction() %.3f s (%lld found, mean y %.3f)\n",
      static_cast<long long>(strands.strand_count()), high.x() - low.x(), high.y() - low.y(),
      high.z() - low.z(), build_s, static_cast<long long>(field.band_voxel_count()),
      static_cast<long long>(field.seeded_voxel_count()), query_s, static_cast<long long>(found),
      checksum / static_cast<double>(found));
  EXPECT_EQ(found, static_cast<int64_t>(queries.size()));  // within a voxel of a seed
  EXPECT_LT(checksum / static_cast<double>(found), -0.5);  // the hair falls
}

TEST(OrientationField, BadInputThrows) {
  StrandSet strands = strand_set_from_polylines(
      {straight(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.005, 0, 0), 20)});
  auto kind_of = [](const StrandSet& set, const std::vector<int64_t>& ids,
                    OrientationFieldParams params, int64_t max_voxels = 20'000'000) {
    try {
      OrientationField::build(set, ids, params, max_voxels);
    } catch (const Error& error) {
      return static_cast<int>(error.kind());
    }
    return -1;
  };
  const int usage = static_cast<int>(ErrorKind::usage);
  const int bad_input = static_cast<int>(ErrorKind::bad_input);
  EXPECT_EQ(kind_of(strands, {0}, {}), -1);
  EXPECT_EQ(kind_of(strands, {}, {}), usage);
  EXPECT_EQ(kind_of(strands, {1}, {}), usage);
  EXPECT_EQ(kind_of(strands, {-1}, {}), usage);
  for (double voxel_m : {0.0, -0.005, std::nan(""), std::numeric_limits<double>::infinity()})
    EXPECT_EQ(kind_of(strands, {0}, {voxel_m, 0.015}), usage) << voxel_m;
  for (double band_m : {-0.001, std::nan(""), 0.005 * 17})
    EXPECT_EQ(kind_of(strands, {0}, {0.005, band_m}), usage) << band_m;
  EXPECT_EQ(kind_of(strands, {0}, {0.005, 0.0}), -1);
  EXPECT_EQ(kind_of(strands, {0}, {0.005, 0.015, -1}), usage);
  for (double tolerance : {0.0, 1e-3, std::nan("")})
    EXPECT_EQ(kind_of(strands, {0}, {0.005, 0.015, 0, tolerance}), usage) << tolerance;
  EXPECT_EQ(kind_of(strands, {0}, {}, 0), usage);
  EXPECT_EQ(kind_of(strands, {0}, {}, 1000), usage);  // the box is 26 x 7 x 7 voxels
  EXPECT_EQ(kind_of(strands, {0}, {}, 26 * 7 * 7), -1);

  StrandSet not_finite = strands;
  not_finite.points(3, 1) = std::nanf("");
  EXPECT_EQ(kind_of(not_finite, {0}, {}), bad_input);
  StrandSet far = strands;
  far.points.row(5) << 1e30f, 0, 0;
  EXPECT_EQ(kind_of(far, {0}, {}), bad_input);

  // No direction: a strand of one repeated point, a single point, or a strand and its
  // reverse cancelling.
  EXPECT_EQ(kind_of(strand_set_from_polylines({rows({{0, 0, 0}, {0, 0, 0}})}), {0}, {}), bad_input);
  EXPECT_EQ(kind_of(strand_set_from_polylines({rows({{0, 0, 0}})}), {0}, {}), bad_input);
  Points3f reverse = strands.points.colwise().reverse();
  StrandSet both = strand_set_from_polylines({strands.points, reverse});
  EXPECT_EQ(kind_of(both, {0, 1}, {}), bad_input);
  EXPECT_EQ(kind_of(both, {0}, {}), -1);
}

}  // namespace
}  // namespace hair
