// Interpolation of every strand from guides (paper section 5.2) on a hand-made scene with
// known answers: a 3 x 3 grid of straight guides hanging from a plane (cluster 1), one
// guide of its own for cluster 2, strands among them, a strand that leaves a fixed cap
// (cluster 0), and a braided strand bound to two wisp tetrahedra.
#include <gtest/gtest.h>
#include <omp.h>

#include <Eigen/Geometry>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

#include "hair/core/error.h"
#include "hair/core/frame_range.h"
#include "hair/interp/strand_interpolation.h"
#include "hair/style/hair_style.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;
enum Cluster : int32_t { kCap = 0, kGrid = 1, kSide = 2, kBraid = 3 };
constexpr int kGuideParticles = 6;
constexpr double kLength = 0.2;

struct Scene {
  StrandSet strands;
  InterpolationGuides guides;
  std::vector<float> wisp_rest;  ///< tetrahedra x 7 at rest
};

/// A curled strand from `root` down -Y: `count` points over kLength.
std::vector<Vec3> curled(const Vec3& root, int count, double curl_m) {
  std::vector<Vec3> points;
  for (int i = 0; i < count; ++i) {
    double t = static_cast<double>(i) / (count - 1);
    points.push_back(root +
                     Vec3(curl_m * std::sin(6 * t), -kLength * t, curl_m * (1 - std::cos(6 * t))));
  }
  return points;
}

Scene make_scene() {
  Scene scene;
  std::vector<int32_t> point_cluster;
  auto add_strand = [&](const std::vector<Vec3>& points, const std::vector<int32_t>& clusters) {
    Points3f block(static_cast<Eigen::Index>(points.size()), 3);
    for (size_t i = 0; i < points.size(); ++i)
      block.row(static_cast<Eigen::Index>(i)) = points[i].cast<float>().transpose();
    scene.strands.append_strand(block);
    point_cluster.insert(point_cluster.end(), clusters.begin(), clusters.end());
  };
  // Guides: a 3 x 3 grid 2 cm apart in x and z, and one at x = 0.2 for cluster 2.
  InterpolationGuides& g = scene.guides;
  std::vector<Vec3> guide_points;
  auto add_guide = [&](const Vec3& anchor, int32_t cluster) {
    for (int k = 0; k < kGuideParticles; ++k)
      guide_points.push_back(anchor + Vec3(0, -kLength * k / (kGuideParticles - 1), 0));
    g.offsets.push_back(static_cast<int64_t>(guide_points.size()));
    g.cluster.push_back(cluster);
    g.is_wisp_centre.push_back(0);
    g.strand.push_back(-1);
  };
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) add_guide(Vec3(0.02 * i, 0, 0.02 * j), kGrid);
  add_guide(Vec3(0.2, 0, 0), kSide);
  g.rest_points.resize(static_cast<Eigen::Index>(guide_points.size()), 3);
  for (size_t i = 0; i < guide_points.size(); ++i)
    g.rest_points.row(static_cast<Eigen::Index>(i)) = guide_points[i].cast<float>().transpose();

  // Strands of the grid (curled, 11 to 17 points), one of cluster 2.
  for (int k = 0; k < 12; ++k) {
    Vec3 root(0.003 + 0.0033 * k, 0, 0.005 + 0.0025 * k);
    add_strand(curled(root, 11 + k % 7, 0.004),
               std::vector<int32_t>(static_cast<size_t>(11 + k % 7), kGrid));
  }
  add_strand(curled(Vec3(0.21, 0, 0.01), 9, 0.003), std::vector<int32_t>(9, kSide));
  // A strand over the cap (3 points on y = 0.01) then down the grid.
  {
    std::vector<Vec3> points = {Vec3(-0.03, 0.01, 0.01), Vec3(-0.015, 0.01, 0.01),
                                Vec3(0.0, 0.01, 0.01)};
    for (const Vec3& p : curled(Vec3(0.005, 0, 0.01), 8, 0.002)) points.push_back(p);
    std::vector<int32_t> clusters = {kCap, kCap, kCap};
    clusters.resize(points.size(), kGrid);
    add_strand(points, clusters);
  }
  // A braided strand: its root on the cap, the rest bound to two tetrahedra.
  {
    std::vector<Vec3> points = {Vec3(0.3, 0.01, 0), Vec3(0.3, -0.02, 0.002),
                                Vec3(0.301, -0.06, 0.0), Vec3(0.299, -0.1, 0.001)};
    add_strand(points, {kCap, kBraid, kBraid, kBraid});
    g.wisp_tetrahedron_offsets = {0, 2};
    // Tetrahedron 0 at (0.3, -0.02, 0), identity; 1 at (0.3, -0.08, 0), turned about Y.
    Eigen::Quaterniond turned(Eigen::AngleAxisd(0.3, Vec3::UnitY()));
    scene.wisp_rest = {0.3f,
                       -0.02f,
                       0.0f,
                       1,
                       0,
                       0,
                       0,
                       0.3f,
                       -0.08f,
                       0.0f,
                       static_cast<float>(turned.w()),
                       static_cast<float>(turned.x()),
                       static_cast<float>(turned.y()),
                       static_cast<float>(turned.z())};
    int64_t base = scene.strands.offsets[scene.strands.strand_count() - 1];
    // Point 1 is not bound: it bridges the held root and the wisp.
    for (int i = 2; i < 4; ++i) {
      int32_t t = i < 3 ? 0 : 1;
      Vec3 origin(0.3, t == 0 ? -0.02 : -0.08, 0);
      Eigen::Matrix3d rotation = t == 0 ? Eigen::Matrix3d::Identity() : turned.toRotationMatrix();
      g.binding_point.push_back(base + i);
      g.binding_wisp.push_back(0);
      g.binding_tetrahedron.push_back(t);
      g.binding_local_m.push_back(
          (rotation.transpose() * (points[static_cast<size_t>(i)] - origin)).cast<float>());
    }
    g.wisp_rest_frames = scene.wisp_rest;
  }
  scene.strands.point_attributes["cluster"] = point_cluster;
  g.cluster_simulated_style = {
      static_cast<int8_t>(HairStyle::fixed), static_cast<int8_t>(HairStyle::normal),
      static_cast<int8_t>(HairStyle::normal), static_cast<int8_t>(HairStyle::braided)};
  return scene;
}

/// The guides' points after `move` (applied to each guide's rest particles, with its anchor).
std::vector<float> moved_guides(
    const Scene& scene, const std::function<Vec3(const Vec3& point, const Vec3& anchor)>& move) {
  const InterpolationGuides& g = scene.guides;
  std::vector<float> points;
  for (int64_t guide = 0; guide < g.guide_count(); ++guide) {
    Vec3 anchor = point_of(g.rest_points, g.offsets[static_cast<size_t>(guide)]);
    for (int64_t row = g.offsets[static_cast<size_t>(guide)];
         row < g.offsets[static_cast<size_t>(guide) + 1]; ++row) {
      Vec3 p = move(point_of(g.rest_points, row), anchor);
      points.insert(points.end(), {static_cast<float>(p.x()), static_cast<float>(p.y()),
                                   static_cast<float>(p.z())});
    }
  }
  return points;
}

/// The guides' points at rest (the head still).
std::vector<float> guides_at_rest(const Scene& scene) {
  return moved_guides(scene, [](const Vec3& p, const Vec3&) -> Vec3 { return p; });
}

Vec3 row_of(const std::vector<float>& points, int64_t row) {
  return Vec3(points[3 * row], points[3 * row + 1], points[3 * row + 2]);
}

/// Appends a straight strand of `count` points `step_m` apart down -Y from `root`, all of
/// `cluster`; returns its points and its index.
std::pair<std::vector<Vec3>, int64_t> add_straight_strand(Scene& scene, const Vec3& root,
                                                          double step_m, int count,
                                                          int32_t cluster) {
  std::vector<Vec3> points;
  Points3f block(count, 3);
  for (int i = 0; i < count; ++i) {
    points.push_back(root - Vec3(0, step_m * i, 0));
    block.row(i) = points.back().cast<float>().transpose();
  }
  scene.strands.append_strand(block);
  auto& point_cluster = std::get<std::vector<int32_t>>(scene.strands.point_attributes["cluster"]);
  point_cluster.insert(point_cluster.end(), static_cast<size_t>(count), cluster);
  return {points, scene.strands.strand_count() - 1};
}

TEST(StrandInterpolation, ChoosesBarycentricClumpHeldAndBraided) {
  Scene scene = make_scene();
  StrandBinding binding = bind_strands(scene.strands, scene.guides, {});
  const int64_t count = scene.strands.strand_count();
  for (int64_t s = 0; s < 12; ++s) {
    EXPECT_EQ(binding.method[static_cast<size_t>(s)], InterpolationMethod::barycentric) << s;
    float sum = 0;
    for (size_t k = 0; k < 3; ++k) {
      EXPECT_GE(binding.guides[static_cast<size_t>(s)][k], 0);
      EXPECT_LT(binding.guides[static_cast<size_t>(s)][k], 9);  // the grid's
      EXPECT_GE(binding.weights[static_cast<size_t>(s)][k], 0.0f);
      sum += binding.weights[static_cast<size_t>(s)][k];
    }
    EXPECT_NEAR(sum, 1.0f, 1e-6f);
    EXPECT_EQ(binding.held_count[static_cast<size_t>(s)], 0);
  }
  // Cluster 2's strand: its nearest three guides are of the grid, so its one guide.
  EXPECT_EQ(binding.method[12], InterpolationMethod::clump);
  EXPECT_EQ(binding.guides[12][0], 9);
  EXPECT_EQ(binding.guides[12][1], -1);
  // Over the cap: three points held, then the grid's guides from its last cap point.
  EXPECT_EQ(binding.held_count[13], 3);
  EXPECT_EQ(binding.bound_from[13], scene.strands.strand_size(13));
  EXPECT_NE(binding.method[13], InterpolationMethod::fixed);
  // The braided strand: its root held, a point bridged, the rest bound.
  EXPECT_EQ(binding.method[static_cast<size_t>(count - 1)], InterpolationMethod::braided);
  EXPECT_EQ(binding.held_count[static_cast<size_t>(count - 1)], 1);
  EXPECT_EQ(binding.bound_from[static_cast<size_t>(count - 1)], 2);
  EXPECT_EQ(binding.bridged[static_cast<size_t>(count - 1)], 1);
}

TEST(StrandInterpolation, GuidesInOtherDirectionsGiveClumps) {
  Scene scene = make_scene();
  // Tilt guide 4 (the grid's centre) by 45 degrees: its neighbours no longer agree.
  for (int64_t row = scene.guides.offsets[4] + 1; row < scene.guides.offsets[5]; ++row)
    scene.guides.rest_points(row, 0) += -scene.guides.rest_points(row, 1);
  StrandBinding binding = bind_strands(scene.strands, scene.guides, {});
  int64_t clumps = 0;
  for (int64_t s = 0; s < 12; ++s)
    clumps += binding.method[static_cast<size_t>(s)] == InterpolationMethod::clump;
  EXPECT_GT(clumps, 0);
  InterpolationParams lenient;
  lenient.min_direction_cosine = 0.5;  // cos 45 = 0.71 passes
  binding = bind_strands(scene.strands, scene.guides, lenient);
  for (int64_t s = 0; s < 12; ++s)
    EXPECT_EQ(binding.method[static_cast<size_t>(s)], InterpolationMethod::barycentric);
}

TEST(StrandInterpolation, AClumpFollowsTheGuideShapedLikeItNotTheNearestRoot) {
  Scene scene = make_scene();
  // A second guide of the side cluster, its anchor nearer the side strand's root (7 mm
  // against 14 mm) but running sideways along +X: a long strand hung on it would swing
  // around it. The side strand hangs down -Y like guide 9.
  InterpolationGuides& g = scene.guides;
  const Eigen::Index first = g.rest_points.rows();
  g.rest_points.conservativeResize(first + kGuideParticles, 3);
  for (int k = 0; k < kGuideParticles; ++k)
    g.rest_points.row(first + k) =
        Vec3(0.205 + kLength * k / (kGuideParticles - 1), 0, 0.005).cast<float>().transpose();
  g.offsets.push_back(first + kGuideParticles);
  g.cluster.push_back(kSide);
  g.is_wisp_centre.push_back(0);
  g.strand.push_back(-1);
  StrandBinding binding = bind_strands(scene.strands, g, {});
  constexpr size_t kSideStrand = 12;
  EXPECT_EQ(binding.method[kSideStrand], InterpolationMethod::clump);
  EXPECT_EQ(binding.guides[kSideStrand][0], 9);  // the downward guide, not the nearer one
  // With the sideways guide alone in its cluster, the strand has to take it.
  g.cluster[9] = kGrid;
  binding = bind_strands(scene.strands, g, {});
  EXPECT_EQ(binding.guides[kSideStrand][0], 10);
}

TEST(StrandInterpolation, AShortStrandFollowsTheFirstPartOfItsGuide) {
  // A strand of 4 cm beside the side cluster's guide of 20 cm follows the guide's first
  // 4 cm: bent below 10 cm, the guide leaves it where it was, and its length with it.
  // Spread over the whole guide (its tip following the guide's tip), it would swing out
  // and stretch.
  Scene scene = make_scene();
  const auto [short_strand, strand] =
      add_straight_strand(scene, Vec3(0.205, 0, 0.003), 0.01, 5, kSide);
  const int64_t first = scene.strands.offsets[static_cast<size_t>(strand)];

  StrandBinding binding = bind_strands(scene.strands, scene.guides, {});
  ASSERT_EQ(binding.method[static_cast<size_t>(strand)], InterpolationMethod::clump);
  ASSERT_EQ(binding.guides[static_cast<size_t>(strand)][0], 9);
  // Its tip is 4 cm along a guide of 20: parameter 0.2, not 1.
  EXPECT_NEAR(binding.parameter[static_cast<size_t>(first + 4)], 0.2, 1e-6);

  // The guides bent a quarter turn about Z where they pass 10 cm below their anchors.
  const Eigen::Matrix3d quarter = Eigen::AngleAxisd(std::numbers::pi / 2, Vec3::UnitZ()).matrix();
  std::vector<float> guide_points =
      moved_guides(scene, [&](const Vec3& p, const Vec3& anchor) -> Vec3 {
        const Vec3 kink = anchor + Vec3(0, -0.1, 0);
        return p.y() < kink.y() - 1e-9 ? Vec3(kink + quarter * (p - kink)) : p;
      });
  std::vector<float> points;
  interpolate_frame(binding, scene.strands, {guide_points.data(), scene.wisp_rest.data(), {}},
                    points);
  double length = 0;
  for (int i = 0; i < 5; ++i) {
    EXPECT_LT((row_of(points, first + i) - short_strand[static_cast<size_t>(i)]).norm(), 1e-6)
        << "point " << i;
    if (i > 0) length += (row_of(points, first + i) - row_of(points, first + i - 1)).norm();
  }
  EXPECT_NEAR(length, 0.04, 1e-6);
  // The guide's tip did move: 10 cm of it turned sideways.
  const int64_t guide_tip = scene.guides.offsets[10] - 1;
  EXPECT_GT(
      (row_of(guide_points, guide_tip) - point_of(scene.guides.rest_points, guide_tip)).norm(),
      0.1);
}

TEST(StrandInterpolation, AStrandFollowsNoGuideFarShorterThanItWhereALongerOneIsNear) {
  // A strand of 60 cm rooted among the grid's guides of 20 cm: barycentric by the
  // paper's tests (same cluster, same direction), but its offsets would reach 40 cm below
  // the guides and turn with their tips.
  Scene scene = make_scene();
  const auto strand = static_cast<size_t>(
      add_straight_strand(scene, Vec3(0.021, 0, 0.019), 0.02, 31, kGrid).second);

  InterpolationParams paper;  // no test of length
  paper.min_guide_length_ratio = 0;
  EXPECT_EQ(bind_strands(scene.strands, scene.guides, paper).method[strand],
            InterpolationMethod::barycentric);
  // With the default, a clump: of its own cluster, whatever the length, where no guide
  // among the candidates is long enough.
  StrandBinding binding = bind_strands(scene.strands, scene.guides, {});
  EXPECT_EQ(binding.method[strand], InterpolationMethod::clump);
  EXPECT_EQ(scene.guides.cluster[static_cast<size_t>(binding.guides[strand][0])], kGrid);
  // A guide of 60 cm of the side cluster (simulated alike) near it: it follows that one.
  InterpolationGuides& g = scene.guides;
  const Eigen::Index first = g.rest_points.rows();
  g.rest_points.conservativeResize(first + 16, 3);
  for (int k = 0; k < 16; ++k)
    g.rest_points.row(first + k) = Vec3(0.03, -0.04 * k, 0.03).cast<float>().transpose();
  g.offsets.push_back(first + 16);
  g.cluster.push_back(kSide);
  g.is_wisp_centre.push_back(0);
  g.strand.push_back(-1);
  binding = bind_strands(scene.strands, g, {});
  EXPECT_EQ(binding.method[strand], InterpolationMethod::clump);
  EXPECT_EQ(binding.guides[strand][0], 10);
  // The grid's own strands, as long as their guides, keep theirs.
  EXPECT_EQ(binding.method[0], InterpolationMethod::barycentric);
}

TEST(StrandInterpolation, AtRestReproducesTheGrownStrands) {
  Scene scene = make_scene();
  StrandBinding binding = bind_strands(scene.strands, scene.guides, {});
  std::vector<float> guide_points = guides_at_rest(scene);
  std::vector<float> points;
  interpolate_frame(binding, scene.strands, {guide_points.data(), scene.wisp_rest.data(), {}},
                    points);
  ASSERT_EQ(static_cast<int64_t>(points.size()), 3 * scene.strands.point_count());
  double worst = 0;
  for (int64_t row = 0; row < scene.strands.point_count(); ++row)
    worst = std::max(worst, (row_of(points, row) - point_of(scene.strands.points, row)).norm());
  EXPECT_LT(worst, 1e-6);
}

TEST(StrandInterpolation, AMotionOfEverythingWithTheHeadIsRigid) {
  Scene scene = make_scene();
  StrandBinding binding = bind_strands(scene.strands, scene.guides, {});
  RigidTransform head;
  head.rotation = Eigen::AngleAxisd(0.7, Vec3(0.3, 1, 0.2).normalized());
  head.translation_m = Vec3(0.05, -0.1, 0.2);
  std::vector<float> guide_points =
      moved_guides(scene, [&](const Vec3& p, const Vec3&) -> Vec3 { return head.apply(p); });
  std::vector<float> wisp = scene.wisp_rest;
  for (int t = 0; t < 2; ++t) {
    float* w = wisp.data() + 7 * t;
    Vec3 origin = head.apply(Vec3(w[0], w[1], w[2]));
    Eigen::Quaterniond q = head.rotation * Eigen::Quaterniond(w[3], w[4], w[5], w[6]);
    float values[7] = {static_cast<float>(origin.x()), static_cast<float>(origin.y()),
                       static_cast<float>(origin.z()), static_cast<float>(q.w()),
                       static_cast<float>(q.x()),      static_cast<float>(q.y()),
                       static_cast<float>(q.z())};
    std::copy(values, values + 7, w);
  }
  std::vector<float> points;
  interpolate_frame(binding, scene.strands, {guide_points.data(), wisp.data(), head}, points);
  for (int64_t row = 0; row < scene.strands.point_count(); ++row)
    EXPECT_LT((row_of(points, row) - head.apply(point_of(scene.strands.points, row))).norm(), 2e-6)
        << "point " << row;
}

TEST(StrandInterpolation, StrandsFollowTheirGuides) {
  Scene scene = make_scene();
  StrandBinding binding = bind_strands(scene.strands, scene.guides, {});
  // Every guide carried 5 cm along +X (head still): interpolated points move with them,
  // held points do not.
  const Vec3 shift(0.05, 0, 0);
  std::vector<float> carried =
      moved_guides(scene, [&](const Vec3& p, const Vec3&) -> Vec3 { return p + shift; });
  std::vector<float> points;
  interpolate_frame(binding, scene.strands, {carried.data(), scene.wisp_rest.data(), {}}, points);
  for (int64_t s = 0; s < 14; ++s) {
    const int64_t begin = scene.strands.offsets[static_cast<size_t>(s)];
    for (int64_t i = 0; i < scene.strands.strand_size(s); ++i) {
      Vec3 expected = point_of(scene.strands.points, begin + i);
      if (i >= binding.held_count[static_cast<size_t>(s)]) expected += shift;
      EXPECT_LT((row_of(points, begin + i) - expected).norm(), 1e-6) << s << " " << i;
    }
  }
  // Every guide swung 90 degrees about +X round its anchor: each interpolated tip swings
  // about the weighted anchor, R p + (I - R) sum_g w_g a_g.
  const Eigen::Matrix3d swing =
      Eigen::AngleAxisd(std::numbers::pi / 2, Vec3::UnitX()).toRotationMatrix();
  std::vector<float> swung = moved_guides(scene, [&](const Vec3& p, const Vec3& anchor) -> Vec3 {
    return anchor + swing * (p - anchor);
  });
  interpolate_frame(binding, scene.strands, {swung.data(), scene.wisp_rest.data(), {}}, points);
  for (int64_t s = 0; s < 13; ++s) {
    Vec3 anchors = Vec3::Zero();
    for (size_t k = 0; k < 3; ++k) {
      int32_t g = binding.guides[static_cast<size_t>(s)][k];
      if (g >= 0)
        anchors += binding.weights[static_cast<size_t>(s)][k] *
                   point_of(scene.guides.rest_points, scene.guides.offsets[static_cast<size_t>(g)]);
    }
    int64_t tip = scene.strands.offsets[static_cast<size_t>(s) + 1] - 1;
    Vec3 expected = swing * point_of(scene.strands.points, tip) + anchors - swing * anchors;
    EXPECT_LT((row_of(points, tip) - expected).norm(), 1e-5) << "strand " << s;
    // Its root stays on the scalp, with the head.
    int64_t root = scene.strands.offsets[static_cast<size_t>(s)];
    EXPECT_LT((row_of(points, root) - point_of(scene.strands.points, root)).norm(), 1e-6);
  }
}

TEST(StrandInterpolation, BraidedPointsFollowTheirTetrahedra) {
  Scene scene = make_scene();
  StrandBinding binding = bind_strands(scene.strands, scene.guides, {});
  std::vector<float> guide_points = guides_at_rest(scene);
  // The wisp's tetrahedra carried 3 cm along -Z, the head still.
  std::vector<float> wisp = scene.wisp_rest;
  wisp[2] -= 0.03f;
  wisp[9] -= 0.03f;
  std::vector<float> points;
  interpolate_frame(binding, scene.strands, {guide_points.data(), wisp.data(), {}}, points);
  const int64_t s = scene.strands.strand_count() - 1,
                begin = scene.strands.offsets[static_cast<size_t>(s)];
  EXPECT_LT((row_of(points, begin) - point_of(scene.strands.points, begin)).norm(), 1e-7);  // held
  for (int64_t i = 2; i < 4; ++i)
    EXPECT_LT(
        (row_of(points, begin + i) - point_of(scene.strands.points, begin + i) - Vec3(0, 0, -0.03))
            .norm(),
        1e-6);
  // The bridged point moves part of the way, by its share of the arc to the wisp.
  const double share = binding.parameter[static_cast<size_t>(begin + 1)];
  EXPECT_GT(share, 0.0);
  EXPECT_LT(share, 1.0);
  EXPECT_LT((row_of(points, begin + 1) - point_of(scene.strands.points, begin + 1) -
             share * Vec3(0, 0, -0.03))
                .norm(),
            1e-6);
}

/// The largest ratio of a segment's length in `points` to its rest length, over strand `s`.
double largest_stretch(const Scene& scene, const std::vector<float>& points, int64_t s) {
  double largest = 0;
  for (int64_t row = scene.strands.offsets[static_cast<size_t>(s)] + 1;
       row < scene.strands.offsets[static_cast<size_t>(s) + 1]; ++row)
    largest = std::max(
        largest,
        (row_of(points, row) - row_of(points, row - 1)).norm() /
            (point_of(scene.strands.points, row) - point_of(scene.strands.points, row - 1)).norm());
  return largest;
}

/// Appends a strand of `points` (with its points' clusters) to the scene; returns its index.
int64_t add_scene_strand(Scene& scene, const std::vector<Vec3>& points,
                         const std::vector<int32_t>& clusters) {
  Points3f block(static_cast<Eigen::Index>(points.size()), 3);
  for (size_t i = 0; i < points.size(); ++i)
    block.row(static_cast<Eigen::Index>(i)) = points[i].cast<float>().transpose();
  scene.strands.append_strand(block);
  auto& point_cluster = std::get<std::vector<int32_t>>(scene.strands.point_attributes["cluster"]);
  point_cluster.insert(point_cluster.end(), clusters.begin(), clusters.end());
  return scene.strands.strand_count() - 1;
}

/// Appends an unturned wisp tetrahedron at `origin` to the scene's rest frames.
void add_rest_tetrahedron(Scene& scene, const Vec3& origin) {
  scene.wisp_rest.insert(scene.wisp_rest.end(),
                         {static_cast<float>(origin.x()), static_cast<float>(origin.y()),
                          static_cast<float>(origin.z()), 1, 0, 0, 0});
  scene.guides.wisp_rest_frames = scene.wisp_rest;
}

/// Turns tetrahedron `t` of the wisp frames `wisp` (7 floats each) to `rotation`.
void set_rotation(std::vector<float>& wisp, size_t t, const Eigen::Quaterniond& rotation) {
  wisp[7 * t + 3] = static_cast<float>(rotation.w());
  wisp[7 * t + 4] = static_cast<float>(rotation.x());
  wisp[7 * t + 5] = static_cast<float>(rotation.y());
  wisp[7 * t + 6] = static_cast<float>(rotation.z());
}

/// The turn of a swinging braid's top: 0.5 rad about Z.
Eigen::Quaterniond braid_swing() {
  return Eigen::Quaterniond(Eigen::AngleAxisd(0.5, Vec3::UnitZ()));
}

/// The wisp at rest but for tetrahedron `t`, turned by braid_swing() and its origin moved
/// `shift_m` along `axis` (0: X, 1: Y, 2: Z).
std::vector<float> turned_wisp(const Scene& scene, size_t t, size_t axis, float shift_m) {
  std::vector<float> wisp = scene.wisp_rest;
  wisp[7 * t + axis] += shift_m;
  set_rotation(wisp, t, braid_swing());
  return wisp;
}

/// Appends strand `points` (with its points' clusters) to the scene, its points from
/// `first_bound` on bound to the wisp's third tetrahedron, added unturned at `origin` (a
/// strand running into a braid); returns the strand's index.
int64_t add_strand_into_braid(Scene& scene, const std::vector<Vec3>& points,
                              const std::vector<int32_t>& clusters, int first_bound,
                              const Vec3& origin) {
  const int64_t s = add_scene_strand(scene, points, clusters),
                begin = scene.strands.offsets[static_cast<size_t>(s)];
  add_rest_tetrahedron(scene, origin);
  scene.guides.wisp_tetrahedron_offsets = {0, 3};
  for (int i = first_bound; i < static_cast<int>(points.size()); ++i) {
    scene.guides.binding_point.push_back(begin + i);
    scene.guides.binding_wisp.push_back(0);
    scene.guides.binding_tetrahedron.push_back(2);
    scene.guides.binding_local_m.push_back((points[static_cast<size_t>(i)] - origin).cast<float>());
  }
  return s;
}

TEST(StrandInterpolation, ACapStrandRunningIntoABraidIsBridgedNotTorn) {
  // A strand over the cap (20 points 5 mm apart, fixed) that runs on into a braid (6 points
  // bound to a third wisp tetrahedron), as grow makes of a cap feeding a braid. The
  // braid's top then swings: the tetrahedron turns 0.5 rad about Z and moves 3 cm, the
  // head still. Held right up to the braid (wisp_bridge_length_m 0), the segment across
  // the junction tears; bridged over the last 8 cm of the cap, the move spreads over it.
  Scene scene = make_scene();
  std::vector<Vec3> points;
  std::vector<int32_t> clusters;
  for (int i = 0; i < 20; ++i) {
    points.push_back(Vec3(0.4 - 0.005 * (19 - i), 0.01, 0.05));
    clusters.push_back(kCap);
  }
  for (int k = 1; k <= 6; ++k) {
    points.push_back(Vec3(0.4, 0.01 - 0.005 * k, 0.05));
    clusters.push_back(kBraid);
  }
  const Vec3 origin(0.4, -0.01, 0.05);
  const int64_t s = add_strand_into_braid(scene, points, clusters, 20, origin),
                begin = scene.strands.offsets[static_cast<size_t>(s)];
  std::vector<float> wisp = turned_wisp(scene, 2, 2, -0.03f);
  const std::vector<float> guide_points = guides_at_rest(scene);

  InterpolationParams held_up_to_the_braid;
  held_up_to_the_braid.wisp_bridge_length_m = 0;
  StrandBinding binding = bind_strands(scene.strands, scene.guides, held_up_to_the_braid);
  EXPECT_EQ(binding.held_count[static_cast<size_t>(s)], 20);
  EXPECT_EQ(binding.bound_from[static_cast<size_t>(s)], 20);
  std::vector<float> torn;
  interpolate_frame(binding, scene.strands, {guide_points.data(), wisp.data(), {}}, torn);
  const double torn_stretch = largest_stretch(scene, torn, s);

  binding = bind_strands(scene.strands, scene.guides, {});  // the default: 8 cm
  EXPECT_EQ(binding.method[static_cast<size_t>(s)], InterpolationMethod::braided);
  EXPECT_EQ(binding.bridged[static_cast<size_t>(s)], 1);
  // Held up to the first point that leaves at least 8 cm of bridge to the braid.
  const int64_t held = binding.held_count[static_cast<size_t>(s)];
  const double bridge_m = 0.005 * static_cast<double>(20 - (held - 1));
  EXPECT_GE(bridge_m, InterpolationParams{}.wisp_bridge_length_m - 1e-6);
  EXPECT_LT(bridge_m - 0.005, InterpolationParams{}.wisp_bridge_length_m);
  std::vector<float> bridged;
  interpolate_frame(binding, scene.strands, {guide_points.data(), wisp.data(), {}}, bridged);
  const double bridged_stretch = largest_stretch(scene, bridged, s);
  std::printf("[ interp   ] cap into a braid: largest stretch %.2f held up to it, %.2f bridged\n",
              torn_stretch, bridged_stretch);
  EXPECT_GT(torn_stretch, 3.0);
  EXPECT_LT(bridged_stretch, 1.5);
  // The cap's first points stay with the head, the braid's with its tetrahedron.
  for (int64_t i = 0; i < held; ++i)
    EXPECT_LT((row_of(bridged, begin + i) - points[static_cast<size_t>(i)]).norm(), 1e-6);
  const Vec3 moved_origin = origin - Vec3(0, 0, 0.03);
  for (int i = 20; i < 26; ++i)
    EXPECT_LT((row_of(bridged, begin + i) -
               (moved_origin + braid_swing() * (points[static_cast<size_t>(i)] - origin)))
                  .norm(),
              1e-5);
}

TEST(StrandInterpolation, AStrandRootedRightByTheBraidsTopIsBridgedIntoTheBraid) {
  // A strand rooted 1.5 cm from a braid's top (3 cap points 5 mm apart, fixed) that runs on
  // down the braid (20 points bound to a wisp tetrahedron), as grow makes of a root beside
  // the braid's top (braid01's nape). The braid's top swings, turning as in the test above
  // and moving 5 cm. Bridged over the 1.5 cm from its root alone, the bridge tears; bridged
  // over 8 cm, its first bound points giving way, the move spreads over the bridge.
  Scene scene = make_scene();
  std::vector<Vec3> points;
  std::vector<int32_t> clusters;
  for (int i = 0; i < 3; ++i) {
    points.push_back(Vec3(0.4 - 0.005 * (3 - i), 0.01, 0.05));
    clusters.push_back(kCap);
  }
  for (int k = 0; k < 20; ++k) {
    points.push_back(Vec3(0.4, 0.01 - 0.005 * k, 0.05));
    clusters.push_back(kBraid);
  }
  const Vec3 origin(0.4, -0.01, 0.05);
  const int64_t s = add_strand_into_braid(scene, points, clusters, 3, origin),
                begin = scene.strands.offsets[static_cast<size_t>(s)];
  std::vector<float> wisp = turned_wisp(scene, 2, 2, -0.05f);
  const std::vector<float> guide_points = guides_at_rest(scene);
  const auto si = static_cast<size_t>(s);

  InterpolationParams short_bridge;
  short_bridge.wisp_bridge_length_m = 0.015;  // what lies between the root and the braid
  StrandBinding binding = bind_strands(scene.strands, scene.guides, short_bridge);
  EXPECT_EQ(binding.held_count[si], 1);
  EXPECT_EQ(binding.bound_from[si], 3);
  std::vector<float> frame;
  interpolate_frame(binding, scene.strands, {guide_points.data(), wisp.data(), {}}, frame);
  const double short_stretch = largest_stretch(scene, frame, s);

  binding = bind_strands(scene.strands, scene.guides, {});  // the default: 8 cm
  EXPECT_EQ(binding.method[si], InterpolationMethod::braided);
  EXPECT_EQ(binding.bridged[si], 1);
  EXPECT_EQ(binding.held_count[si], 1);  // the root
  const int64_t bound_from = binding.bound_from[si];
  const double bridge_m = 0.005 * static_cast<double>(bound_from);
  EXPECT_GE(bridge_m, InterpolationParams{}.wisp_bridge_length_m - 1e-6);
  EXPECT_LT(bridge_m - 0.005, InterpolationParams{}.wisp_bridge_length_m);
  for (int64_t i = 0; i < 23; ++i)  // bridged points are no longer bound
    EXPECT_EQ(binding.tetrahedron[static_cast<size_t>(begin + i)] >= 0, i >= bound_from) << i;
  interpolate_frame(binding, scene.strands, {guide_points.data(), wisp.data(), {}}, frame);
  const double long_stretch = largest_stretch(scene, frame, s);
  std::printf("[ interp   ] rooted by a braid: largest stretch %.2f over 1.5 cm, %.2f over 8 cm\n",
              short_stretch, long_stretch);
  EXPECT_GT(short_stretch, 2.5);
  EXPECT_LT(long_stretch, 1.5);
  EXPECT_LT((row_of(frame, begin) - points[0]).norm(), 1e-6);  // the root stays
  const Vec3 moved_origin = origin - Vec3(0, 0, 0.05);
  for (int64_t i = bound_from; i < 23; ++i)
    EXPECT_LT((row_of(frame, begin + i) -
               (moved_origin + braid_swing() * (points[static_cast<size_t>(i)] - origin)))
                  .norm(),
              1e-5);
}

TEST(StrandInterpolation, ABraidedStrandBendsAtASeamBetweenTetrahedraNotTears) {
  // A braided strand of 16 points 5 mm apart down -Y, its first 8 bound to one wisp
  // tetrahedron and the rest to the next (the two new tetrahedra 2 and 3 of the scene's
  // wisp), as a braid's strand passes from piece to piece. The second tetrahedron then
  // turns 0.5 rad about Z about its origin and moves 2 cm along X, the first still: each
  // point carried by its own tetrahedron alone, the segment across the seam tears; with
  // the seam blended over 2 cm (the default), the turn bends the strand there instead.
  Scene scene = make_scene();
  std::vector<Vec3> points;
  for (int i = 0; i < 16; ++i) points.push_back(Vec3(0.5, -0.005 * i, 0.05));
  const int64_t s = add_scene_strand(scene, points, std::vector<int32_t>(points.size(), kBraid)),
                begin = scene.strands.offsets[static_cast<size_t>(s)];
  const Vec3 first_origin(0.5, -0.01, 0.05), second_origin(0.5, -0.05, 0.05);
  add_rest_tetrahedron(scene, first_origin);
  add_rest_tetrahedron(scene, second_origin);
  scene.guides.wisp_tetrahedron_offsets = {0, 4};
  for (int i = 0; i < 16; ++i) {
    const bool second = i >= 8;
    scene.guides.binding_point.push_back(begin + i);
    scene.guides.binding_wisp.push_back(0);
    scene.guides.binding_tetrahedron.push_back(second ? 3 : 2);
    scene.guides.binding_local_m.push_back(
        (points[static_cast<size_t>(i)] - (second ? second_origin : first_origin)).cast<float>());
  }
  std::vector<float> wisp = turned_wisp(scene, 3, 0, 0.02f);
  const std::vector<float> guide_points = guides_at_rest(scene);

  InterpolationParams apart;
  apart.wisp_seam_length_m = 0;
  StrandBinding binding = bind_strands(scene.strands, scene.guides, apart);
  EXPECT_EQ(binding.method[static_cast<size_t>(s)], InterpolationMethod::braided);
  std::vector<float> torn;
  interpolate_frame(binding, scene.strands, {guide_points.data(), wisp.data(), {}}, torn);
  const double torn_stretch = largest_stretch(scene, torn, s);

  binding = bind_strands(scene.strands, scene.guides, {});
  // The points within 2 cm of the seam (between points 7 and 8, 2.5 mm from each): four
  // on each side.
  EXPECT_EQ(binding.seam_offsets[static_cast<size_t>(s) + 1] -
                binding.seam_offsets[static_cast<size_t>(s)],
            8);
  std::vector<float> at_rest, blended;
  interpolate_frame(binding, scene.strands, {guide_points.data(), scene.wisp_rest.data(), {}},
                    at_rest);
  for (int i = 0; i < 16; ++i)
    EXPECT_LT((row_of(at_rest, begin + i) - points[static_cast<size_t>(i)]).norm(), 1e-6);
  interpolate_frame(binding, scene.strands, {guide_points.data(), wisp.data(), {}}, blended);
  const double blended_stretch = largest_stretch(scene, blended, s);
  std::printf("[ interp   ] braid seam: largest stretch %.2f apart, %.2f blended over 2 cm\n",
              torn_stretch, blended_stretch);
  EXPECT_GT(torn_stretch, 2.0);
  EXPECT_LT(blended_stretch, 1.5);
  // Beyond 2 cm of the seam each point moves with its own tetrahedron alone.
  for (int i : {0, 1, 2, 3})
    EXPECT_LT((row_of(blended, begin + i) - points[static_cast<size_t>(i)]).norm(), 1e-6);
  const Vec3 moved = second_origin + Vec3(0.02, 0, 0);
  for (int i : {12, 13, 14, 15})
    EXPECT_LT((row_of(blended, begin + i) -
               (moved + braid_swing() * (points[static_cast<size_t>(i)] - second_origin)))
                  .norm(),
              1e-6);
}

TEST(StrandInterpolation, TheSameWhateverTheThreadCount) {
  Scene scene = make_scene();
  StrandBinding binding = bind_strands(scene.strands, scene.guides, {});
  std::vector<float> swung = moved_guides(scene, [](const Vec3& p, const Vec3& anchor) -> Vec3 {
    return anchor + Eigen::AngleAxisd(0.4, Vec3::UnitZ()) * (p - anchor);
  });
  std::vector<float> one, two;
  int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  interpolate_frame(binding, scene.strands, {swung.data(), scene.wisp_rest.data(), {}}, one);
  omp_set_num_threads(2);
  interpolate_frame(binding, scene.strands, {swung.data(), scene.wisp_rest.data(), {}}, two);
  omp_set_num_threads(threads);
  EXPECT_EQ(one, two);
}

TEST(StrandInterpolation, RefusesParametersOutOfRange) {
  Scene scene = make_scene();
  InterpolationParams params;
  params.candidate_guides = 2;
  EXPECT_THROW(bind_strands(scene.strands, scene.guides, params), Error);
  params = {};
  params.min_direction_cosine = 2;
  EXPECT_THROW(bind_strands(scene.strands, scene.guides, params), Error);
  params = {};
  params.min_guide_length_ratio = 1.5;
  EXPECT_THROW(bind_strands(scene.strands, scene.guides, params), Error);
  params = {};
  params.wisp_bridge_length_m = -0.01;
  EXPECT_THROW(bind_strands(scene.strands, scene.guides, params), Error);
  params.wisp_bridge_length_m = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(bind_strands(scene.strands, scene.guides, params), Error);
  params = {};
  params.wisp_seam_length_m = -0.01;
  EXPECT_THROW(bind_strands(scene.strands, scene.guides, params), Error);
  params.wisp_seam_length_m = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(bind_strands(scene.strands, scene.guides, params), Error);
}

TEST(FrameRange, ParsesSlicesAndRefusesEmptyOrPastTheEnd) {
  EXPECT_EQ(parse_frame_range("", 10).first, 0);
  EXPECT_EQ(parse_frame_range("", 10).end, 10);
  EXPECT_EQ(parse_frame_range("3:7", 10).first, 3);
  EXPECT_EQ(parse_frame_range("3:7", 10).count(), 4);
  EXPECT_EQ(parse_frame_range("4:", 10).end, 10);
  EXPECT_EQ(parse_frame_range(":2", 10).first, 0);
  EXPECT_EQ(parse_frame_range("5", 10).count(), 1);
  EXPECT_EQ(parse_frame_range(":", 10).count(), 10);
  for (const char* bad : {"7:3", "3:3", "0:11", "10", "a:b", "-1:2", "1:2:3", "x"}) {
    try {
      parse_frame_range(bad, 10);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::usage);
      EXPECT_NE(std::string(e.what()).find("--frames"), std::string::npos);
    }
  }
}

}  // namespace
}  // namespace hair
