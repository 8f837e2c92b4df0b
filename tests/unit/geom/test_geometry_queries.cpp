// Distance and neighbour queries against brute force; the orientation decision table;
// head measures of the MakeHuman body.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "hair/extract/strand_orientation.h"
#include "hair/geom/point_index.h"
#include "hair/geom/triangle_mesh_distance.h"
#include "hair/mesh/body_measures.h"
#include "hair/mesh/mesh_io.h"
#include "unit/synthetic_hair.h"

namespace hair {
namespace {

TEST(TriangleMeshDistance, MatchesBruteForceOnABody) {
  PolyMesh body = testing::snowman_body();
  Triangles3i triangles = fan_triangulation(body.face_offsets, body.face_vertices);
  TriangleMeshDistance distance(body.vertices, triangles);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (int i = 0; i < 200; ++i) {
    Eigen::Vector3d p(0.3 * unit(random), 1.35 + 0.4 * unit(random), 0.3 * unit(random));
    double brute = std::numeric_limits<double>::infinity();
    for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
      Eigen::Vector3d a = body.vertices.row(triangles(t, 0)).cast<double>().transpose();
      Eigen::Vector3d b = body.vertices.row(triangles(t, 1)).cast<double>().transpose();
      Eigen::Vector3d c = body.vertices.row(triangles(t, 2)).cast<double>().transpose();
      brute = std::min(brute, (closest_point_on_triangle(p, a, b, c) - p).norm());
    }
    EXPECT_NEAR(distance.distance(p), brute, 1e-9) << p.transpose();
  }
}

TEST(TriangleMeshDistance, TheAnswerDoesNotDependOnTheQueriesBefore) {
  // Each thread's search starts from the piece its last query of the index found; the
  // answer must be the nearest triangle whatever that was: the same query after a query
  // far away, after queries of another mesh, in a reversed order, and on another thread.
  PolyMesh body = testing::snowman_body();
  Triangles3i triangles = fan_triangulation(body.face_offsets, body.face_vertices);
  TriangleMeshDistance distance(body.vertices, triangles);
  PolyMesh strip = testing::hair_strip({{0, 1.8, 0}, {0, 1.7, 0.1}, {0, 1.6, 0.2}},
                                       Eigen::Vector3d::UnitX(), 0.02, {});
  TriangleMeshDistance other(strip.vertices,
                             fan_triangulation(strip.face_offsets, strip.face_vertices));
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 150; ++i)
    points.emplace_back(0.5 * unit(random), 1.35 + 0.6 * unit(random), 0.5 * unit(random));
  std::vector<TriangleMeshDistance::Nearest> in_order;
  for (const Eigen::Vector3d& p : points) in_order.push_back(distance.nearest(p));
  auto expect_same = [&](size_t i, const TriangleMeshDistance::Nearest& n) {
    EXPECT_EQ(n.distance, in_order[i].distance) << i;
    EXPECT_EQ(n.triangle, in_order[i].triangle) << i;
    EXPECT_EQ(n.closest_point, in_order[i].closest_point) << i;
  };
  for (size_t i = points.size(); i-- > 0;) expect_same(i, distance.nearest(points[i]));
  for (size_t i = 0; i < points.size(); ++i) {
    other.nearest(points[(i * 37) % points.size()]);
    distance.nearest(points[(i * 53 + 7) % points.size()]);
    expect_same(i, distance.nearest(points[i]));
  }
  std::vector<TriangleMeshDistance::Nearest> threaded(points.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (size_t i = 0; i < points.size(); ++i) threaded[i] = distance.nearest(points[i]);
  for (size_t i = 0; i < points.size(); ++i) expect_same(i, threaded[i]);
}

TEST(TriangleMeshDistance, ClosestPointOnTriangleRegions) {
  Eigen::Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_TRUE(
      closest_point_on_triangle({0.2, 0.2, 5}, a, b, c).isApprox(Eigen::Vector3d(0.2, 0.2, 0)));
  EXPECT_TRUE(closest_point_on_triangle({-1, -1, 0}, a, b, c).isApprox(a));
  EXPECT_TRUE(
      closest_point_on_triangle({0.5, -2, 0}, a, b, c).isApprox(Eigen::Vector3d(0.5, 0, 0)));
  EXPECT_TRUE(closest_point_on_triangle({1, 1, 0}, a, b, c).isApprox(Eigen::Vector3d(0.5, 0.5, 0)));
}

/// `count` points drawn uniformly in the unit cube from `random`.
Points3f random_unit_points(Eigen::Index count, std::mt19937& random) {
  std::uniform_real_distribution<float> unit(0, 1);
  Points3f points(count, 3);
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    points.row(i) << unit(random), unit(random), unit(random);
  return points;
}

TEST(PointIndex, NeighboursMatchBruteForceNearestFirst) {
  std::mt19937 random(3);
  const Points3f points = random_unit_points(500, random);
  PointIndex index(points);
  Eigen::Vector3f query(0.5f, 0.5f, 0.5f);
  std::vector<int32_t> within = index.within(query, 0.2f);
  size_t brute = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    brute += (points.row(i).transpose() - query).norm() <= 0.2f;
  EXPECT_EQ(within.size(), brute);
  for (size_t i = 1; i < within.size(); ++i)
    EXPECT_LE((points.row(within[i - 1]).transpose() - query).norm(),
              (points.row(within[i]).transpose() - query).norm());
  std::vector<int32_t> nearest = index.nearest(query, 5);
  ASSERT_EQ(nearest.size(), 5u);
  EXPECT_EQ(nearest[0], within[0]);
  EXPECT_EQ(index.nearest(query, 1000).size(), 500u);
}

TEST(PointIndex, VisitingTheFirstFewWithinARadiusFollowsTheFullListTiesIncluded) {
  // A lattice: many points at exactly the same distance from its centre, so the order of
  // ties (by id) decides which come first.
  Points3f points(9 * 9 * 9, 3);
  Eigen::Index row = 0;
  for (int x = 0; x < 9; ++x)
    for (int y = 0; y < 9; ++y)
      for (int z = 0; z < 9; ++z) points.row(row++) << 0.1f * x, 0.1f * y, 0.1f * z;
  PointIndex index(points);
  for (const Eigen::Vector3f& query :
       {Eigen::Vector3f(0.4f, 0.4f, 0.4f), Eigen::Vector3f(0.43f, 0.4f, 0.37f)}) {
    const std::vector<int32_t> all = index.within(query, 0.25f);
    ASSERT_GT(all.size(), 40u);
    for (size_t count : {size_t{1}, size_t{6}, size_t{7}, size_t{19}, size_t{40}, all.size(),
                         size_t{5000}}) {
      std::vector<int32_t> first;
      index.visit_within(query, 0.25f, [&](int32_t id) {
        first.push_back(id);
        return first.size() < count;
      });
      ASSERT_EQ(first.size(), std::min(all.size(), count)) << count;
      EXPECT_TRUE(std::equal(first.begin(), first.end(), all.begin())) << count;
    }
  }
}

TEST(PointIndex, UnorderedAndAnyWithinAgreeWithWithin) {
  std::mt19937 random(5);
  std::uniform_real_distribution<float> unit(0, 1);
  const Points3f points = random_unit_points(400, random);
  PointIndex index(points);
  for (int q = 0; q < 50; ++q) {
    const Eigen::Vector3f query(unit(random), unit(random), unit(random));
    for (float radius : {0.01f, 0.05f, 0.2f}) {
      std::vector<int32_t> sorted = index.within(query, radius);
      std::vector<int32_t> unordered = index.within_unordered(query, radius);
      EXPECT_EQ(index.any_within(query, radius), !sorted.empty());
      std::sort(sorted.begin(), sorted.end());
      std::sort(unordered.begin(), unordered.end());
      EXPECT_EQ(unordered, sorted);
    }
  }
  EXPECT_FALSE(PointIndex(Points3f(0, 3)).any_within(Eigen::Vector3f::Zero(), 1.0f));
  // visit_within: within()'s ids in its order, as far as the visitor asks.
  const Eigen::Vector3f centre(0.5f, 0.5f, 0.5f);
  const std::vector<int32_t> all = index.within(centre, 0.45f);
  ASSERT_GT(all.size(), 100u);
  for (size_t stop : {size_t{1}, size_t{16}, size_t{17}, size_t{80}, all.size(), all.size() + 5}) {
    std::vector<int32_t> visited;
    index.visit_within(centre, 0.45f, [&](int32_t id) {
      visited.push_back(id);
      return visited.size() < stop;
    });
    ASSERT_EQ(visited.size(), std::min(stop, all.size())) << stop;
    EXPECT_TRUE(std::equal(visited.begin(), visited.end(), all.begin())) << stop;
  }
}

TEST(DecideOrientation, RulesApplyInOrder) {
  OrientationThresholds thresholds;
  MeshConventions conventions{true, 1};
  auto decide = [&](OrientationEvidence e, std::optional<MeshConventions> c) {
    return decide_orientation(e, thresholds, c);
  };
  // Ordered rails that agree, with the head distance agreeing: vertex order.
  auto d = decide({.vertex_order_vote = 1, .has_ordered_rails = true, .scalp_distance_slope = 0.5},
                  std::nullopt);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->rule, OrientationRule::vertex_order);
  EXPECT_FALSE(d->reverse);
  EXPECT_FLOAT_EQ(d->confidence, 1.0f);
  // Ordered rails contradicted by a decisive head distance: the distance wins.
  d = decide({.vertex_order_vote = 1, .has_ordered_rails = true, .scalp_distance_slope = -0.5},
             std::nullopt);
  EXPECT_EQ(d->rule, OrientationRule::scalp_distance);
  EXPECT_TRUE(d->reverse);
  // The same off the head, falling the way the ids run (a braid piece weaving away from
  // the head): the height settles it for the ids...
  thresholds.height_min_head_distance_m = 0.01;
  OrientationEvidence weaving{.vertex_order_vote = 1,
                              .has_ordered_rails = true,
                              .scalp_distance_slope = -0.5,
                              .height_slope = 0.6,
                              .head_distance_min_m = 0.02};
  d = decide(weaving, std::nullopt);
  EXPECT_EQ(d->rule, OrientationRule::vertex_order);
  EXPECT_FALSE(d->reverse);
  // ...but not on the head, nor when it barely falls.
  weaving.head_distance_min_m = 0.005;
  EXPECT_EQ(decide(weaving, std::nullopt)->rule, OrientationRule::scalp_distance);
  weaving.head_distance_min_m = 0.02;
  weaving.height_slope = 0.1;
  EXPECT_TRUE(decide(weaving, std::nullopt)->reverse);
  // Off the head and rising the way the ids run: height sides with the distance.
  weaving.height_slope = -0.6;
  d = decide(weaving, std::nullopt);
  EXPECT_EQ(d->rule, OrientationRule::scalp_distance);
  EXPECT_TRUE(d->reverse);
  // Untrusted ids are ignored.
  d = decide({.vertex_order_vote = -1, .has_ordered_rails = true},
             MeshConventions{false, std::nullopt});
  EXPECT_EQ(d->rule, OrientationRule::height);
  // Nothing decisive: the first pass leaves it open, the second uses the texture...
  OrientationEvidence weak{.uv_growth = -0.9, .height_slope = 0.3};
  EXPECT_FALSE(decide(weak, std::nullopt));
  d = decide(weak, conventions);
  EXPECT_EQ(d->rule, OrientationRule::uv);
  EXPECT_TRUE(d->reverse);  // v falls along the rails, but grows root to tip in this mesh
  // ...or, without a texture convention, height.
  d = decide(weak, MeshConventions{true, std::nullopt});
  EXPECT_EQ(d->rule, OrientationRule::height);
  EXPECT_FALSE(d->reverse);
}

TEST(HeadMeasures, MakeHumanBodyHasAHumanHead) {
  std::filesystem::path body_path =
      std::filesystem::path(HAIR_SOURCE_DIR) / "data/samples/body.obj";
  if (!std::filesystem::exists(body_path))
    body_path = std::filesystem::path(HAIR_SHARED_DATA_DIR) / "makehuman/body.obj";
  if (!std::filesystem::exists(body_path)) GTEST_SKIP() << "no MakeHuman body";
  PolyMesh body = read_mesh(body_path);
  body.vertices *= 0.1f;
  HeadMeasures head = head_measures(body, body_path.string());
  EXPECT_NEAR(head.head_top_y, 0.849, 0.001);
  EXPECT_GT(head.head_height, 0.22);  // crown to the neck's waist on an adult
  EXPECT_LT(head.head_height, 0.28);
  EXPECT_LT(head.neck_width, 0.7 * head.head_width);
}

TEST(HeadMeasures, SnowmanNeckIsFound) {
  HeadMeasures head = head_measures(testing::snowman_body(), "snowman");
  EXPECT_GE(head.neck_y, 1.39);
  EXPECT_LE(head.neck_y, 1.57);
  EXPECT_NEAR(head.neck_width, 0.1, 0.01);
}

}  // namespace
}  // namespace hair

namespace hair {
namespace {

TEST(TriangleMeshDistance, LargeTrianglesAmongSmallOnesStayExact) {
  // One huge triangle beside a fine strip: pieces of the big one must answer for it.
  PolyMesh mesh = testing::hair_strip({{0, 0, 0}, {0, -0.01, 0}, {0, -0.02, 0}},
                                      Eigen::Vector3d::UnitX(), 0.01, {});
  PolyMesh big;
  big.vertices.resize(3, 3);
  big.vertices << 1, 0, 0, 3, 0, 0, 2, 2, 0;
  big.append_face(std::vector<int32_t>{0, 1, 2});
  testing::append_mesh(mesh, big);
  Triangles3i triangles = fan_triangulation(mesh.face_offsets, mesh.face_vertices);
  TriangleMeshDistance distance(mesh.vertices, triangles);
  EXPECT_NEAR(distance.distance({2, 0.5, 0.3}), 0.3, 1e-9);  // above the big one's middle
  EXPECT_EQ(distance.nearest({2, 0.5, 0.3}).triangle, triangles.rows() - 1);
  EXPECT_TRUE(distance.is_within({2, 0.5, 0.3}, 0.31));
  EXPECT_FALSE(distance.is_within({2, 0.5, 0.3}, 0.29));
  EXPECT_NEAR(distance.distance({0, 0.5, 0}), 0.5, 1e-9);
}

}  // namespace
}  // namespace hair
