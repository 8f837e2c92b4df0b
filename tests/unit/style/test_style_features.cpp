// Style features (paper sections 5.1 and 6.1) on hand-made clusters with known values.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <set>
#include <vector>

#include "hair/core/error.h"
#include "hair/style/style_features.h"
#include "unit/point_rows.h"

namespace hair {
namespace {

using test::rows;

/// A flat square scalp, 2 m wide, in the plane y = 0 (both triangles scalp), with H = 0.25.
StyleFeatureInput flat_scalp_input() {
  StyleFeatureInput input;
  input.body_vertices = rows({{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}});
  input.body_triangles.resize(2, 3);
  input.body_triangles << 0, 1, 2, 0, 2, 3;
  input.scalp_triangle = {1, 1};
  input.head_height_m = 0.25;
  input.source = "test";
  return input;
}

/// Appends a grown strand with a cluster (and group) per point.
void add_strand(StyleFeatureInput& input, const Points3f& points,
                const std::vector<int32_t>& point_cluster,
                const std::vector<int32_t>& point_group) {
  auto& clusters = input.strands.point_attributes["cluster"];
  auto& groups = input.strands.point_attributes["group"];
  if (!std::holds_alternative<std::vector<int32_t>>(clusters)) clusters = std::vector<int32_t>{};
  if (!std::holds_alternative<std::vector<int32_t>>(groups)) groups = std::vector<int32_t>{};
  auto& cluster_ids = std::get<std::vector<int32_t>>(clusters);
  auto& group_ids = std::get<std::vector<int32_t>>(groups);
  cluster_ids.insert(cluster_ids.end(), point_cluster.begin(), point_cluster.end());
  group_ids.insert(group_ids.end(), point_group.begin(), point_group.end());
  input.strands.append_strand(points);
  auto& normals = input.strands.strand_attributes["root_normal"];
  if (!std::holds_alternative<Points3f>(normals)) normals = Points3f(0, 3);
  Points3f& normal_rows = std::get<Points3f>(normals);
  normal_rows.conservativeResize(normal_rows.rows() + 1, 3);
  normal_rows.row(normal_rows.rows() - 1) << 0, 1, 0;
}

/// A straight strand from `root` up along +y, `length` long, `n` points, one cluster.
Points3f vertical(float x, float z, float length, int n = 11) {
  Points3f points(n, 3);
  for (int i = 0; i < n; ++i)
    points.row(i) << x, length * static_cast<float>(i) / static_cast<float>(n - 1), z;
  return points;
}

TEST(ClusterRuns, SplitsStrandsWhereTheirClusterChanges) {
  StyleFeatureInput input = flat_scalp_input();
  input.cluster_count = 3;
  input.group_middle_node = {-1, 4, 5};
  input.group_cluster = {0, 1, 1};
  // Cluster 0 for three points (the root's), cluster 1 for two (following groups 1 and
  // 2, both middle nodes... group 1 twice), then one point of cluster 2: too short a run.
  add_strand(input, rows({{0, 0, 0}, {0, 1, 0}, {0, 2, 0}, {1, 2, 0}, {2, 2, 0}, {3, 2, 0}}),
             {0, 0, 0, 1, 1, 2}, {-1, -1, -1, 1, 1, 2});
  std::vector<ClusterRuns> runs = cluster_runs(input);
  ASSERT_EQ(runs.size(), 3u);
  ASSERT_EQ(runs[0].runs.strand_count(), 1);
  EXPECT_EQ(runs[0].runs.strand_size(0), 3);
  EXPECT_EQ(runs[0].starts_at_root[0], 1);
  EXPECT_EQ(runs[0].ends_at_tip[0], 0);
  EXPECT_EQ(runs[0].middle_node[0], -1);
  EXPECT_TRUE(runs[0].arrival[0].isApprox(Eigen::Vector3d(0, 1, 0)));
  ASSERT_EQ(runs[1].runs.strand_count(), 1);
  EXPECT_EQ(runs[1].starts_at_root[0], 0);
  EXPECT_EQ(runs[1].ends_at_tip[0], 0);  // the strand's last point is cluster 2's
  EXPECT_TRUE(runs[1].arrival[0].isApprox(Eigen::Vector3d(1, 0, 0)));  // from {0,2,0}
  EXPECT_EQ(runs[1].middle_node[0], 4);
  EXPECT_EQ(runs[2].runs.strand_count(), 0);
}

TEST(StyleFeatures, AFewStrandsGrownAstrayDoNotDecideTheLongestLength) {
  // 39 short strands of 0.05 m and one stray of 1 m (4 H): the paper's maximum would be
  // 4 H; its robust form, the 95th percentile, stays with the short hair.
  StyleFeatureInput input = flat_scalp_input();
  input.cluster_count = 1;
  for (int i = 0; i < 40; ++i)
    add_strand(input, vertical(0.01f * static_cast<float>(i), 0, i == 0 ? 1.0f : 0.05f),
               std::vector<int32_t>(11, 0), std::vector<int32_t>(11, -1));
  StyleFeatures robust = style_features(input, {});
  EXPECT_NEAR(robust.paper[0].long_length_h, 0.2, 1e-6);
  EXPECT_NEAR(robust.paper[0].far_scalp_distance_h, 0.2, 1e-6);
  EXPECT_NEAR(robust.paper[0].mean_length_h, (39 * 0.05 + 1.0) / 40 / 0.25, 1e-6);
  StyleFeatureParams maxima;
  maxima.robust_max_quantile = 1;
  StyleFeatures paper = style_features(input, maxima);
  EXPECT_NEAR(paper.paper[0].long_length_h, 4.0, 1e-6);
  EXPECT_NEAR(paper.paper[0].far_scalp_distance_h, 4.0, 1e-6);
}

TEST(StyleFeatures, LengthsAndScalpDistanceOfStraightStrands) {
  StyleFeatureInput input = flat_scalp_input();
  input.cluster_count = 1;
  for (int i = 0; i < 4; ++i)
    add_strand(input, vertical(0.1f * static_cast<float>(i), 0, 0.05f + 0.05f * i),
               std::vector<int32_t>(11, 0), std::vector<int32_t>(11, -1));
  StyleFeatureParams maxima;
  maxima.robust_max_quantile = 1;  // the paper's maxima
  StyleFeatures features = style_features(input, maxima);
  const PaperFeatures& paper = features.paper[0];
  // Lengths 0.05, 0.10, 0.15, 0.20 m with H = 0.25: mean 0.5 H, max 0.8 H.
  EXPECT_NEAR(paper.mean_length_h, 0.5, 1e-6);
  EXPECT_NEAR(paper.long_length_h, 0.8, 1e-6);
  EXPECT_NEAR(paper.far_scalp_distance_h, 0.8, 1e-6);  // the tip of the longest
  EXPECT_DOUBLE_EQ(paper.root_share, 1.0);
  EXPECT_DOUBLE_EQ(paper.tip_share, 1.0);
  EXPECT_EQ(paper.middle_node_count, 0);
  EXPECT_DOUBLE_EQ(paper.twist_h, 0.0);
  EXPECT_EQ(features.strand_count[0], 4);
  EXPECT_EQ(features.point_count[0], 44);
}

TEST(StyleFeatures, SkinDistanceAndDownwardProfilesAlongTheStrands) {
  StyleFeatureInput input = flat_scalp_input();
  input.cluster_count = 2;
  for (int i = 0; i < 3; ++i) {
    float x = 0.1f * static_cast<float>(i);
    // Cluster 0: 0.2 m straight up off the flat body (skin at y = 0): 0, 0.05, ..., 0.2 m
    // from the skin at 0, 25, ..., 100% of the length, with H = 0.25: 0, 0.2, ... 0.8 H;
    // pointing up all along.
    add_strand(input, vertical(x, 0, 0.2f), std::vector<int32_t>(11, 0),
               std::vector<int32_t>(11, -1));
    // Cluster 1: level at 0.1 m above the skin for 0.3 m, then 0.3 m straight down to it.
    add_strand(input, rows({{x, 0.1f, 0}, {x, 0.1f, 0.3f}, {x, -0.2f, 0.3f}}), {1, 1, 1},
               {-1, -1, -1});
  }
  StyleFeatures features = style_features(input, {});
  const PaperFeatures& up = features.paper[0];
  const PaperFeatures& bent = features.paper[1];
  for (int j = 0; j < 5; ++j)
    EXPECT_NEAR(up.skin_distance_h[static_cast<size_t>(j)], 0.2 * j, 1e-6) << j;
  for (double downward : up.downward) EXPECT_NEAR(downward, -1.0, 1e-6);
  // Cluster 1 at 0, 25, 50, 75, 100% (0, 0.15, 0.3, 0.45, 0.6 m along): 0.1 m above the
  // skin for the first three, then 0.05 m below it and 0.2 m below (distances are
  // unsigned): 0.4, 0.4, 0.4, 0.2, 0.8 H.
  const double expected_h[] = {0.4, 0.4, 0.4, 0.2, 0.8};
  for (int j = 0; j < 5; ++j)
    EXPECT_NEAR(bent.skin_distance_h[static_cast<size_t>(j)], expected_h[j], 1e-6) << j;
  // 20 points: edges 0, 6 (level, the first half), 12 and 18 (down, the second).
  EXPECT_NEAR(bent.downward[0], 0.0, 1e-6);
  EXPECT_NEAR(bent.downward[1], 0.0, 1e-6);
  EXPECT_NEAR(bent.downward[2], 1.0, 1e-6);
  EXPECT_NEAR(bent.downward[3], 1.0, 1e-6);
  // The extended row: the paper's seven, tip_share, end_spread_h, then these.
  ASSERT_EQ(features.extended_rows.cols(), 18);
  ASSERT_EQ(extended_feature_names().size(), 18u);
  EXPECT_EQ(extended_feature_names()[9], "skin_distance_0_h");
  EXPECT_EQ(extended_feature_names()[17], "downward_100");
  EXPECT_DOUBLE_EQ(features.extended_rows(1, 12), bent.skin_distance_h[3]);
  EXPECT_DOUBLE_EQ(features.extended_rows(1, 16), bent.downward[3]);
}

TEST(StyleFeatures, GatheringRatioIsZeroForStrandsMeetingAtTheEndAndOneForParallelStrands) {
  StyleFeatureInput input = flat_scalp_input();
  input.cluster_count = 2;
  for (int i = 0; i < 5; ++i) {
    float x = -0.2f + 0.1f * static_cast<float>(i);
    // Cluster 0: from spread roots to one tip, a ponytail's band.
    add_strand(input, rows({{x, 0, 0}, {x / 2, 0.1f, 0}, {0, 0.2f, 0}}), {0, 0, 0}, {-1, -1, -1});
    // Cluster 1: parallel strands.
    add_strand(input, vertical(x, 1, 0.2f, 3), {1, 1, 1}, {-1, -1, -1});
  }
  StyleFeatures features = style_features(input, {});
  EXPECT_NEAR(features.paper[0].gathering_ratio, 0.0, 1e-6);
  EXPECT_NEAR(features.paper[1].gathering_ratio, 1.0, 1e-6);
  // The ends: together at the band; 0.2, 0.1, 0, 0.1, 0.2 m from the centre for the
  // parallel strands, 0.12 m on average, with H = 0.25: 0.48 H.
  EXPECT_NEAR(features.paper[0].end_spread_h, 0.0, 1e-6);
  EXPECT_NEAR(features.paper[1].end_spread_h, 0.48, 1e-6);
  EXPECT_EQ(features.extended_rows.row(1).segment(7, 2),
            Eigen::RowVector2d(1.0, features.paper[1].end_spread_h));
  EXPECT_EQ(features.extended_rows.row(1).head(7), features.paper_rows.row(1));
}

TEST(StyleFeatures, TwistIsTheLargestDistanceOfANodeCentreFromTheCentreOfAllNodes) {
  StyleFeatureInput input = flat_scalp_input();
  input.cluster_count = 1;
  input.group_cluster = {0, 0};
  input.group_middle_node = {0, 1};  // group 0 in middle cluster 0, group 1 in 1
  // Node 0's strands run at x = +0.05, node 1's at x = -0.05: the centre of all is x = 0,
  // each node's centre 0.05 m from it; with H = 0.25, 0.2 H.
  for (int i = 0; i < 5; ++i) {
    add_strand(input, vertical(0.05f, 0.01f * static_cast<float>(i), 0.3f, 31),
               std::vector<int32_t>(31, 0), std::vector<int32_t>(31, 0));
    add_strand(input, vertical(-0.05f, 0.01f * static_cast<float>(i), 0.3f, 31),
               std::vector<int32_t>(31, 0), std::vector<int32_t>(31, 1));
  }
  StyleFeatures features = style_features(input, {});
  EXPECT_EQ(features.paper[0].middle_node_count, 2);
  EXPECT_NEAR(features.paper[0].twist_h, 0.2, 1e-6);

  // A strand that follows node 0 for its first half and node 1 for the second: its
  // halves count for their own nodes at their own places along the cluster.
  StyleFeatureInput halves = input;
  std::vector<int32_t> group(31, 0);
  std::fill(group.begin() + 15, group.end(), 1);
  for (int i = 0; i < 5; ++i)
    add_strand(halves, vertical(0.15f, 0.01f * static_cast<float>(i), 0.3f, 31),
               std::vector<int32_t>(31, 0), group);
  // The centre of all moves to x = 0.05 (15 strands at 0.05, -0.05, 0.15); node 0's
  // points at the root end average (5 * 0.05 + 5 * 0.15) / 10 = 0.1, node 1's there
  // -0.05: 0.1 m from the centre, 0.4 H.
  EXPECT_NEAR(style_features(halves, {}).paper[0].twist_h, 0.4, 1e-6);
}

TEST(StyleFeatures, RawFeaturesHaveThePapers190DimensionsAndKnownValues) {
  EXPECT_EQ(raw_feature_count(17), 190);
  std::vector<std::string> names = raw_feature_names(17);
  ASSERT_EQ(names.size(), 190u);
  EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), 190u);  // all distinct

  StyleFeatureInput input = flat_scalp_input();
  input.cluster_count = 1;
  add_strand(input, vertical(0.1f, 0, 0.32f), std::vector<int32_t>(11, 0),
             std::vector<int32_t>(11, -1));
  add_strand(input, vertical(-0.1f, 0, 0.32f), std::vector<int32_t>(11, 0),
             std::vector<int32_t>(11, -1));
  StyleFeatures features = style_features(input, {});
  Eigen::RowVectorXd raw = features.raw_rows.row(0);
  auto at = [&](const std::string& name) {
    return raw(std::find(names.begin(), names.end(), name) - names.begin());
  };
  EXPECT_DOUBLE_EQ(at("strand_count"), 2);
  EXPECT_NEAR(at("position_mean_x"), 0, 1e-7);
  EXPECT_NEAR(at("position_variance_x"), 0.01, 1e-7);    // x = +-0.1
  EXPECT_NEAR(at("skin_distance_mean_16"), 0.32, 1e-6);  // the tips, 0.32 m above y = 0
  EXPECT_NEAR(at("skin_distance_variance_16"), 0, 1e-9);
  EXPECT_NEAR(at("average_strand_distance_mean_05"), 0.1, 1e-6);
  EXPECT_NEAR(at("edge_mean_y_00"), 0.02, 1e-6);             // 0.32 m in 16 intervals
  EXPECT_NEAR(at("direction_difference_mean_00"), 0, 1e-6);  // straight up, normal up
  EXPECT_NEAR(at("average_strand_y_16"), 0.32, 1e-6);
}

TEST(StyleFeatures, AreTheSameWhateverTheThreadCount) {
  StyleFeatureInput input = flat_scalp_input();
  input.cluster_count = 2;
  for (int i = 0; i < 200; ++i) {
    float angle = 0.1f * static_cast<float>(i);
    Points3f points(8, 3);
    for (int k = 0; k < 8; ++k)
      points.row(k) << std::cos(angle) * 0.01f * k, 0.02f * k, std::sin(angle * k) * 0.01f;
    add_strand(input, points, std::vector<int32_t>(8, i % 2), std::vector<int32_t>(8, -1));
  }
  int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  StyleFeatures one = style_features(input, {});
  omp_set_num_threads(std::max(2, threads));
  StyleFeatures many = style_features(input, {});
  omp_set_num_threads(threads);
  EXPECT_EQ(one.paper_rows, many.paper_rows);
  EXPECT_EQ(one.raw_rows, many.raw_rows);
}

TEST(StyleFeatures, RefuseStrandsWithoutPointClustersOrWithClustersOutOfRange) {
  StyleFeatureInput input = flat_scalp_input();
  input.cluster_count = 1;
  input.strands.append_strand(vertical(0, 0, 0.1f));
  input.strands.strand_attributes["root_normal"] = rows({{0, 1, 0}});
  try {
    style_features(input, {});
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("point attribute 'cluster'"), std::string::npos)
        << error.what();
  }
  StyleFeatureInput out_of_range = flat_scalp_input();
  out_of_range.cluster_count = 1;
  add_strand(out_of_range, vertical(0, 0, 0.1f), std::vector<int32_t>(11, 3),
             std::vector<int32_t>(11, -1));
  EXPECT_THROW(style_features(out_of_range, {}), Error);
}

}  // namespace
}  // namespace hair
