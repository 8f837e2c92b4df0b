// The body's signed distance field against an analytic sphere and against brute force
// on the MakeHuman body; its sign on a holed and a turned-round mesh; push_out;
// determinism; refused inputs; build and sample times.
#include <gtest/gtest.h>
#include <omp.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <numbers>
#include <optional>
#include <random>
#include <thread>

#include "hair/core/error.h"
#include "hair/geom/body_sdf.h"
#include "hair/geom/triangle_mesh_distance.h"
#include "hair/mesh/body_measures.h"
#include "hair/mesh/mesh_io.h"
#include "unit/icosphere.h"

namespace hair {
namespace {

using Mesh = testing::SphereMesh;

/// A sphere of `radius_m` about the origin (tests/unit/icosphere.h).
Mesh icosphere(double radius_m, int subdivisions) {
  return testing::icosphere(subdivisions, radius_m);
}

constexpr double kRadius = 0.1;
constexpr double kVoxel = 0.002;
constexpr double kBand = 0.01;

/// The sphere's field over a box 5 cm wider than the sphere on every side.
BodySdf sphere_sdf(const Mesh& mesh) {
  Eigen::Vector3d corner = Eigen::Vector3d::Constant(kRadius + 0.05);
  return BodySdf(mesh.vertices, mesh.triangles, -corner, corner, kVoxel, kBand, "sphere");
}

/// A point at `radius_m` from the origin in a random direction.
Eigen::Vector3d random_point_at(std::mt19937& random, double radius_m) {
  std::normal_distribution<double> normal;
  Eigen::Vector3d direction(normal(random), normal(random), normal(random));
  return radius_m * direction.normalized();
}

/// Generalized winding number by brute force over every triangle: the reference sign.
double winding_number(const Mesh& mesh, const Eigen::Vector3d& p) {
  double total = 0;
  for (Eigen::Index t = 0; t < mesh.triangles.rows(); ++t) {
    Eigen::Vector3d a = mesh.vertices.row(mesh.triangles(t, 0)).cast<double>().transpose() - p;
    Eigen::Vector3d b = mesh.vertices.row(mesh.triangles(t, 1)).cast<double>().transpose() - p;
    Eigen::Vector3d c = mesh.vertices.row(mesh.triangles(t, 2)).cast<double>().transpose() - p;
    double la = a.norm(), lb = b.norm(), lc = c.norm();
    total += 2 * std::atan2(a.dot(b.cross(c)),
                            la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb);
  }
  return total / (4 * std::numbers::pi);
}

TEST(BodySdf, SphereMatchesTheAnalyticDistanceInTheBand) {
  Mesh mesh = icosphere(kRadius, 4);  // 5120 triangles, edges about 7 mm
  BodySdf sdf = sphere_sdf(mesh);
  EXPECT_EQ(sdf.values().size(), static_cast<size_t>(sdf.dims().cast<int64_t>().prod()));
  EXPECT_TRUE(sdf.origin_m().isApprox(Eigen::Vector3d::Constant(-kRadius - 0.05 - kBand)));
  std::mt19937 random(1);
  // Away from the band's edge, where the cell's corners hold clamped values.
  std::uniform_real_distribution<double> depth(-kBand + 2 * kVoxel, kBand - 2 * kVoxel);
  double largest_error = 0;
  for (int i = 0; i < 2000; ++i) {
    double expected = depth(random);
    Eigen::Vector3d p = random_point_at(random, kRadius + expected);
    double error = std::abs(sdf.distance(p) - expected);
    largest_error = std::max(largest_error, error);
    EXPECT_LE(error, 0.5 * kVoxel) << p.transpose();
  }
  std::printf("[ sdf      ] sphere r %.2f m, voxel %.1f mm: largest error %.3f mm in the band\n",
              kRadius, 1e3 * kVoxel, 1e3 * largest_error);
}

TEST(BodySdf, SphereSignInsideAndOutside) {
  BodySdf sdf = sphere_sdf(icosphere(kRadius, 4));
  // Beyond the band the grid holds +-band_m (as float); outside the box, band_m.
  EXPECT_FLOAT_EQ(sdf.distance(Eigen::Vector3d::Zero()), -kBand);
  EXPECT_FLOAT_EQ(sdf.distance({0.14, 0.0, 0.0}), kBand);
  EXPECT_DOUBLE_EQ(sdf.distance({1.0, 0.0, 0.0}), kBand);
  EXPECT_TRUE(sdf.gradient({1.0, 0.0, 0.0}).isZero());
  EXPECT_FALSE(sdf.contains({1.0, 0.0, 0.0}));
  // Boxes that meet no surface: one region each, decided by the winding number.
  Mesh mesh = icosphere(kRadius, 4);
  Eigen::Vector3d corner = Eigen::Vector3d::Constant(0.02);
  for (const auto& [centre, expected] :
       {std::pair{Eigen::Vector3d::Zero().eval(), -kBand}, {Eigen::Vector3d(0.3, 0, 0), kBand}}) {
    BodySdf away(mesh.vertices, mesh.triangles, centre - corner, centre + corner, kVoxel, kBand,
                 "sphere");
    for (float value : away.values()) ASSERT_FLOAT_EQ(value, expected);
  }
  std::mt19937 random(2);
  std::uniform_real_distribution<double> radius(0, kRadius + 0.05);
  for (int i = 0; i < 2000; ++i) {
    double r = radius(random);
    if (std::abs(r - kRadius) < kVoxel) continue;
    Eigen::Vector3d p = random_point_at(random, r);
    EXPECT_EQ(sdf.distance(p) < 0, r < kRadius) << p.transpose();
  }
}

TEST(BodySdf, GradientIsTheOutwardNormalNearTheSurface) {
  BodySdf sdf = sphere_sdf(icosphere(kRadius, 4));
  std::mt19937 random(3);
  std::uniform_real_distribution<double> depth(-0.5 * kBand, 0.5 * kBand);
  for (int i = 0; i < 1000; ++i) {
    Eigen::Vector3d p = random_point_at(random, kRadius + depth(random));
    Eigen::Vector3d g = sdf.gradient(p);
    EXPECT_NEAR(g.norm(), 1.0, 0.1) << p.transpose();
    EXPECT_GT(g.normalized().dot(p.normalized()), 0.99) << p.transpose();
  }
}

TEST(BodySdf, PushOutReachesTheClearance) {
  BodySdf sdf = sphere_sdf(icosphere(kRadius, 4));
  constexpr double clearance = 0.002;
  std::mt19937 random(4);
  std::uniform_real_distribution<double> depth(0, 0.8 * kBand);
  for (int i = 0; i < 500; ++i) {
    Eigen::Vector3d p = random_point_at(random, kRadius - depth(random));
    Eigen::Vector3d direction = p.normalized();
    EXPECT_TRUE(sdf.push_out(p, clearance));
    EXPECT_GE(sdf.distance(p), clearance) << p.transpose();
    EXPECT_NEAR(p.norm(), kRadius + clearance, 0.5 * kVoxel) << p.transpose();
    EXPECT_GT(p.normalized().dot(direction), 0.999);  // straight out
  }
  Eigen::Vector3d clear(0, kRadius + 0.005, 0);
  Eigen::Vector3d before = clear;
  EXPECT_FALSE(sdf.push_out(clear, clearance));
  EXPECT_EQ(clear, before);
  // Deeper than the band the field is flat: nothing says which way is out.
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  EXPECT_FALSE(sdf.push_out(centre, clearance));
  EXPECT_TRUE(centre.isZero());
}

// Between two close surfaces (a plate 2 mm thick, like an ear) the field's gradient is
// weak: with the plate's middle near the middle of a voxel, both grid planes beside it
// hold nearly the same distance. push_out moves a point there no farther than twice what
// it is short of the clearance per step, never off into the distance (Newton's step,
// 1 / |g| long, threw such points centimetres away).
TEST(BodySdf, PushOutBetweenCloseSurfacesStaysNearby) {
  // The grid's planes lie at y = -0.08 + k kVoxel: at 0 and 0.002. The plate's middle,
  // 0.00101, is just off the middle of that cell.
  const float half = 0.001f, middle = 0.00101f, side = 0.05f;
  Points3f vertices(8, 3);
  for (int i = 0; i < 8; ++i)
    vertices.row(i) << ((i & 1) ? side : -side), middle + ((i & 2) ? half : -half),
        ((i & 4) ? side : -side);
  Triangles3i triangles(12, 3);
  triangles << 0, 1, 3, 0, 3, 2,  4, 6, 7, 4, 7, 5,  0, 4, 5, 0, 5, 1,
               2, 3, 7, 2, 7, 6,  0, 2, 6, 0, 6, 4,  1, 5, 7, 1, 7, 3;
  const Eigen::Vector3d corner(0.08, 0.08, 0.08);
  BodySdf sdf(vertices, triangles, -corner, corner, kVoxel, kBand, "plate");
  constexpr double clearance = 0.002;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> across(-0.03, 0.03), through(0.0002, 0.0018);
  double farthest = 0;
  for (int i = 0; i < 200; ++i) {
    Eigen::Vector3d p(across(random), through(random), across(random));
    const Eigen::Vector3d before = p;
    sdf.push_out(p, clearance);
    farthest = std::max(farthest, (p - before).norm());
    // Out of the plate and past the clearance is at most half + clearance + the voxel's
    // error; a few steps of twice what is missing stay within a centimetre.
    EXPECT_LE((p - before).norm(), 0.01) << before.transpose();
  }
  std::printf("[ sdf      ] plate 2 mm thick: push_out moved points at most %.4f m\n", farthest);
}

TEST(BodySdf, CoarseBoundNeverClaimsMoreThanTheField) {
  BodySdf sdf = sphere_sdf(icosphere(kRadius, 4));
  std::mt19937 random(11);
  std::uniform_real_distribution<double> radius(0, kRadius + 0.07);  // into and out of the box
  int certain = 0, far_and_certain = 0, far = 0;
  for (int i = 0; i < 20000; ++i) {
    Eigen::Vector3d p = random_point_at(random, radius(random));
    for (double threshold : {-0.004, 0.0, 0.002, 0.008}) {
      if (sdf.certainly_farther_than(p, threshold)) {
        ++certain;
        ASSERT_GE(sdf.distance(p), threshold) << p.transpose();
      }
    }
    // Well clear of the sphere (two blocks of 8 voxels), the coarse test decides.
    if (p.norm() > kRadius + 2 * 8 * kVoxel * std::sqrt(3.0)) {
      ++far;
      far_and_certain += sdf.certainly_farther_than(p, 0.002);
    }
  }
  EXPECT_GT(certain, 10000);
  EXPECT_EQ(far_and_certain, far);
}

TEST(BodySdf, SignSurvivesAHoleAndAWindingTurnedRound) {
  Mesh sphere = icosphere(kRadius, 4);
  BodySdf closed = sphere_sdf(sphere);
  // Turned round: the same field.
  Mesh turned = sphere;
  turned.triangles.col(1).swap(turned.triangles.col(2));
  EXPECT_EQ(sphere_sdf(turned).values(), closed.values());
  // A hole of about 3 cm across at the north pole: the sign holds away from it.
  Mesh holed = sphere;
  std::vector<Eigen::Index> kept;
  for (Eigen::Index t = 0; t < sphere.triangles.rows(); ++t) {
    Eigen::Vector3f centroid =
        (sphere.vertices.row(sphere.triangles(t, 0)) + sphere.vertices.row(sphere.triangles(t, 1)) +
         sphere.vertices.row(sphere.triangles(t, 2))) /
        3.0f;
    if (centroid.y() < 0.99 * kRadius) kept.push_back(t);
  }
  ASSERT_LT(kept.size(), static_cast<size_t>(sphere.triangles.rows()));
  holed.triangles = sphere.triangles(kept, Eigen::all);
  BodySdf open = sphere_sdf(holed);
  EXPECT_LT(open.distance(Eigen::Vector3d::Zero()), 0);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> radius(0, kRadius + 0.05);
  int compared = 0;
  for (int i = 0; i < 2000; ++i) {
    double r = radius(random);
    Eigen::Vector3d p = random_point_at(random, r);
    if (std::abs(r - kRadius) < kVoxel || (p - Eigen::Vector3d(0, kRadius, 0)).norm() < 0.04)
      continue;
    EXPECT_EQ(open.distance(p) < 0, r < kRadius) << p.transpose();
    ++compared;
  }
  EXPECT_GT(compared, 1000);
}

TEST(BodySdf, RefusesBadInput) {
  Mesh sphere = icosphere(kRadius, 1);
  Eigen::Vector3d low = Eigen::Vector3d::Constant(-0.2), high = Eigen::Vector3d::Constant(0.2);
  auto expect_refused = [](const auto& build, const std::string& words) {
    try {
      build();
      ADD_FAILURE() << "no error for: " << words;
    } catch (const Error& error) {
      EXPECT_EQ(error.kind(), ErrorKind::bad_input) << error.what();
      EXPECT_EQ(error.file(), "body.obj") << error.what();
      EXPECT_NE(std::string(error.what()).find(words), std::string::npos) << error.what();
    }
  };
  auto build = [&](const Mesh& mesh, Eigen::Vector3d box_low, Eigen::Vector3d box_high,
                   double voxel, double band, int64_t max_voxels = 64'000'000) {
    return [=] {
      BodySdf(mesh.vertices, mesh.triangles, box_low, box_high, voxel, band, "body.obj",
              max_voxels);
    };
  };
  expect_refused(build(Mesh{}, low, high, 0.01, 0.02), "empty");
  Mesh no_triangles{sphere.vertices, Triangles3i(0, 3)};
  expect_refused(build(no_triangles, low, high, 0.01, 0.02), "empty");
  Mesh not_finite = sphere;
  not_finite.vertices(3, 1) = std::numeric_limits<float>::quiet_NaN();
  expect_refused(build(not_finite, low, high, 0.01, 0.02), "vertex 3 is not finite");
  Mesh missing_vertex = sphere;
  missing_vertex.triangles(0, 2) = static_cast<int32_t>(sphere.vertices.rows());
  expect_refused(build(missing_vertex, low, high, 0.01, 0.02), "names a vertex");
  expect_refused(build(sphere, high, low, 0.01, 0.02), "box is empty");
  expect_refused(build(sphere, low, Eigen::Vector3d(0.2, INFINITY, 0.2), 0.01, 0.02), "not finite");
  expect_refused(build(sphere, low, high, 0.0, 0.02), "not a positive number");
  expect_refused(build(sphere, low, high, -0.01, 0.02), "not a positive number");
  expect_refused(build(sphere, low, high, 0.01, 0.005), "narrower than a voxel");
  expect_refused(build(sphere, low, high, 0.001, 0.002), "more than the 64000000 allowed");
  expect_refused(build(sphere, low, high, 0.01, 0.02, 1000), "more than the 1000 allowed");
  // A point-sized box is not empty: it grows by the band.
  EXPECT_EQ(BodySdf(sphere.vertices, sphere.triangles, low, low, 0.01, 0.02, "body.obj").dims(),
            Eigen::Vector3i(5, 5, 5));
}

/// The MakeHuman body (decimetres in the file) in metres, triangulated, with its head
/// measures; nullopt where the data is not there.
struct MakeHumanBody {
  Mesh mesh;
  HeadMeasures head;
  Eigen::Vector3d head_low, head_high;  ///< bounds of the vertices above the neck
};

std::optional<MakeHumanBody> makehuman_body() {
  std::filesystem::path path = std::filesystem::path(HAIR_SOURCE_DIR) / "data/samples/body.obj";
  if (!std::filesystem::exists(path))
    path = std::filesystem::path(HAIR_SHARED_DATA_DIR) / "makehuman/body.obj";
  if (!std::filesystem::exists(path)) return std::nullopt;
  PolyMesh poly = read_mesh(path);
  poly.vertices *= 0.1f;
  MakeHumanBody body;
  body.mesh = {poly.vertices, fan_triangulation(poly.face_offsets, poly.face_vertices)};
  body.head = head_measures(poly, path.string());
  body.head_low = Eigen::Vector3d::Constant(INFINITY);
  body.head_high = Eigen::Vector3d::Constant(-INFINITY);
  for (Eigen::Index v = 0; v < poly.vertices.rows(); ++v) {
    Eigen::Vector3d p = poly.vertices.row(v).cast<double>().transpose();
    if (p.y() < body.head.neck_y) continue;
    body.head_low = body.head_low.cwiseMin(p);
    body.head_high = body.head_high.cwiseMax(p);
  }
  return body;
}

TEST(BodySdf, MakeHumanHeadAgreesWithBruteForce) {
  std::optional<MakeHumanBody> body = makehuman_body();
  if (!body) GTEST_SKIP() << "no MakeHuman body";
  constexpr double voxel = 0.0025, band = 0.04;
  BodySdf sdf(body->mesh.vertices, body->mesh.triangles, body->head_low, body->head_high, voxel,
              band, "body.obj");
  // The centre of the head's box, on its axis between the ears, lies deep inside; 5 cm
  // above the crown is outside.
  Eigen::Vector3d centre = (body->head_low + body->head_high) / 2;
  EXPECT_LT(sdf.distance(centre), -0.03);
  Eigen::Vector3d above(centre.x(), body->head.head_top_y + 0.05, centre.z());
  EXPECT_GT(sdf.distance(above), 0.035);
  // The mouth: a cavity 9 cm deep behind lips parted by under a millimetre. The mesh
  // says it is outside (winding number 0), and so does the field.
  Eigen::Vector3d mouth(0.003, 0.665, 0.10);
  ASSERT_LT(winding_number(body->mesh, mouth), 0.5);
  EXPECT_GT(sdf.distance(mouth), 0.01);

  TriangleMeshDistance exact(body->mesh.vertices, body->mesh.triangles);
  std::mt19937 random(6);
  std::uniform_real_distribution<double> unit(0, 1);
  int inside = 0, near_surface = 0;
  double largest_error = 0;
  for (int i = 0; i < 400; ++i) {
    Eigen::Vector3d p;
    for (int axis = 0; axis < 3; ++axis)
      p[axis] =
          body->head_low[axis] + unit(random) * (body->head_high[axis] - body->head_low[axis]);
    bool reference_inside = winding_number(body->mesh, p) > 0.5;
    double reference = (reference_inside ? -1 : 1) * exact.distance(p);
    double field = sdf.distance(p);
    inside += reference_inside;
    if (std::abs(reference) < voxel) {
      ++near_surface;
      continue;
    }
    // The cell's corners lie within a voxel's diagonal of p; trilinear interpolation of
    // exact distances at them is off by at most 0.87 voxel (the weighted corner distance).
    EXPECT_EQ(field < 0, reference_inside) << p.transpose() << ": " << field << " vs " << reference;
    const double diagonal = std::sqrt(3.0) * voxel;
    if (std::abs(reference) < band - diagonal) {
      largest_error = std::max(largest_error, std::abs(field - reference));
      EXPECT_NEAR(field, reference, 0.87 * voxel) << p.transpose();
    } else if (std::abs(reference) > band + diagonal) {
      EXPECT_FLOAT_EQ(std::abs(field), band) << p.transpose();
    }
  }
  EXPECT_GT(inside, 100);  // the test means something
  std::printf(
      "[ sdf      ] MakeHuman head, voxel %.1f mm, band %.0f mm: 400 random points, %d inside, "
      "%d within a voxel of the surface; largest error %.3f mm in the band\n",
      1e3 * voxel, 1e3 * band, inside, near_surface, 1e3 * largest_error);
}

TEST(BodySdf, VoxelsHoldExactDistances) {
  // OpenVDB's conversion was up to 2.1 mm off here beyond the first voxel.
  std::optional<MakeHumanBody> body = makehuman_body();
  if (!body) GTEST_SKIP() << "no MakeHuman body";
  constexpr double voxel = 0.0025, band = 0.01;
  BodySdf sdf(body->mesh.vertices, body->mesh.triangles, body->head_low, body->head_high, voxel,
              band, "body.obj");
  TriangleMeshDistance exact(body->mesh.vertices, body->mesh.triangles);
  const Eigen::Vector3i dims = sdf.dims();
  int in_band = 0;
  for (size_t i = 0; i < sdf.values().size(); i += 37) {
    Eigen::Vector3i voxel_index(static_cast<int>(i % dims.x()),
                                static_cast<int>((i / dims.x()) % dims.y()),
                                static_cast<int>(i / (static_cast<size_t>(dims.x()) * dims.y())));
    Eigen::Vector3d p = sdf.origin_m() + voxel * voxel_index.cast<double>();
    double expected = std::min(exact.distance(p), band);
    in_band += expected < band;
    ASSERT_NEAR(std::abs(sdf.values()[i]), expected, 1e-7) << p.transpose();
  }
  EXPECT_GT(in_band, 5000);
}

TEST(BodySdf, SameValuesWhateverTheThreadCount) {
  std::optional<MakeHumanBody> body = makehuman_body();
  if (!body) GTEST_SKIP() << "no MakeHuman body";
  auto build = [&] {
    return BodySdf(body->mesh.vertices, body->mesh.triangles, body->head_low, body->head_high,
                   0.004, 0.02, "body.obj");
  };
  int threads_before = omp_get_max_threads();
  omp_set_num_threads(1);
  BodySdf one_thread = build();
  omp_set_num_threads(std::max(4, threads_before));
  EXPECT_EQ(build().values(), one_thread.values());
  omp_set_num_threads(threads_before);
  // Two builds at once, each with its own team of threads.
  std::optional<BodySdf> left, right;
  std::thread other([&] { left.emplace(build()); });
  right.emplace(build());
  other.join();
  EXPECT_EQ(left->values(), one_thread.values());
  EXPECT_EQ(right->values(), one_thread.values());
}

TEST(BodySdf, MakeHumanHeadAndShouldersTimes) {
  std::optional<MakeHumanBody> body = makehuman_body();
  if (!body) GTEST_SKIP() << "no MakeHuman body";
  // About 0.5 x 0.45 x 0.4 m: the head, the neck and the top of the shoulders.
  Eigen::Vector3d centre = (body->head_low + body->head_high) / 2;
  Eigen::Vector3d low(centre.x() - 0.25, body->head.head_top_y - 0.43, centre.z() - 0.2);
  Eigen::Vector3d high(centre.x() + 0.25, body->head.head_top_y + 0.02, centre.z() + 0.2);
  constexpr double voxel = 0.0025, band = 0.01;
  auto start = std::chrono::steady_clock::now();
  BodySdf sdf(body->mesh.vertices, body->mesh.triangles, low, high, voxel, band, "body.obj");
  double build_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  int64_t inside = std::count_if(sdf.values().begin(), sdf.values().end(),
                                 [](float value) { return value < 0; });
  EXPECT_LT(sdf.distance(centre), 0);
  EXPECT_GT(inside, 0);

  constexpr int kSamples = 1'000'000;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<Eigen::Vector3d> points(kSamples);
  for (auto& p : points)
    p = low + (high - low).cwiseProduct(Eigen::Vector3d(unit(random), unit(random), unit(random)));
  start = std::chrono::steady_clock::now();
  double sum = 0;
  for (const auto& p : points) sum += sdf.distance(p);
  double sample_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // Along strands: 1000 straight runs of 1000 points 1 mm apart, as a grower walks.
  for (size_t run = 0; run < 1000; ++run) {
    Eigen::Vector3d direction =
        Eigen::Vector3d(unit(random), unit(random), unit(random)) - Eigen::Vector3d::Constant(0.5);
    direction = 0.001 * direction.normalized();
    for (size_t k = 0; k < 1000; ++k)
      points[run * 1000 + k] = points[run * 1000] + static_cast<double>(k) * direction;
  }
  start = std::chrono::steady_clock::now();
  for (const auto& p : points) sum += sdf.distance(p);
  double walk_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_TRUE(std::isfinite(sum));
  std::printf(
      "[ sdf      ] MakeHuman head and shoulders %.2f x %.2f x %.2f m, voxel %.1f mm, band %.0f "
      "mm: %d x %d x %d = %.1f M voxels (%.1f M inside), built in %.3f s on %u hardware "
      "threads; 1e6 distance() samples in %.3f s at random (%.0f ns each), %.3f s along "
      "strands (%.0f ns)\n",
      high.x() - low.x(), high.y() - low.y(), high.z() - low.z(), 1e3 * voxel, 1e3 * band,
      sdf.dims().x(), sdf.dims().y(), sdf.dims().z(),
      1e-6 * static_cast<double>(sdf.values().size()), 1e-6 * static_cast<double>(inside), build_s,
      std::thread::hardware_concurrency(), sample_s, 1e9 * sample_s / kSamples, walk_s,
      1e9 * walk_s / kSamples);
}

}  // namespace
}  // namespace hair
