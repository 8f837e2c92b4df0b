// Two-level clustering (cluster_middle_groups, cluster_hair) on a hand-made scene whose
// clusters are known: two streams hanging side by side, each a cap, four middle pieces
// and a tip, plus a free strand far from both.
#include <gtest/gtest.h>

#include <vector>

#include "hair/cluster/hair_clustering.h"
#include "hair/core/error.h"

namespace hair {
namespace {

constexpr double kHeadHeight = 0.25;

/// A straight centre strand of 8 points from `start` to `end`.
Points3f piece(Eigen::Vector3f start, Eigen::Vector3f end) {
  Points3f strand(8, 3);
  for (int i = 0; i < 8; ++i)
    strand.row(i) = (start + (end - start) * (static_cast<float>(i) / 7)).transpose();
  return strand;
}

struct Scene {
  StrandSet centres;
  std::vector<GroupType> types;
  std::vector<int> stream;  ///< per group; 2 for the free strand
};

/// Streams at x = 0 and x = 0.1 m (beyond the f1 bound H / 4 of each other): a cap (root_connected)
/// 4 cm long, four 4 cm middle pieces and a 4 cm tip, 5 mm apart; the free strand (root_free) at x
/// = 0.5 m.
Scene two_streams() {
  Scene scene;
  std::vector<Points3f> pieces;
  for (int s = 0; s < 2; ++s) {
    float x = 0.1f * static_cast<float>(s);
    for (int p = 0; p < 6; ++p) {
      float top = -0.045f * static_cast<float>(p);
      pieces.push_back(piece({x, top, 0}, {x, top - 0.04f, 0}));
      scene.types.push_back(p == 0   ? GroupType::root_connected
                            : p == 5 ? GroupType::tip
                                     : GroupType::middle);
      scene.stream.push_back(s);
    }
  }
  pieces.push_back(piece({0.5f, 0, 0}, {0.5f, -0.2f, 0}));
  scene.types.push_back(GroupType::root_free);
  scene.stream.push_back(2);
  scene.centres = strand_set_from_polylines(pieces);
  return scene;
}

TEST(HairClustering, MiddlePiecesClusterByStream) {
  Scene scene = two_streams();
  MiddleClustering middle =
      cluster_middle_groups(scene.centres, scene.types, kHeadHeight, GraphClusteringParams{});
  EXPECT_EQ(middle.cluster_count, 2);
  EXPECT_EQ(middle.count_source, ClusterCountSource::eigengap);
  for (size_t g = 0; g < scene.types.size(); ++g) {
    if (scene.types[g] != GroupType::middle) {
      EXPECT_EQ(middle.middle_cluster[g], -1) << g;
      continue;
    }
    for (size_t h = 0; h < scene.types.size(); ++h) {
      if (scene.types[h] == GroupType::middle) {
        EXPECT_EQ(middle.middle_cluster[g] == middle.middle_cluster[h],
                  scene.stream[g] == scene.stream[h])
            << g << " " << h;
      }
    }
  }
  // The chain's consecutive pieces are the graph's edges, nothing across the streams.
  EXPECT_EQ(middle.graph.edges.size(), 6u);
}

TEST(HairClustering, StreamsThenTheCapsDividedFromThem) {
  Scene scene = two_streams();
  MiddleClustering middle =
      cluster_middle_groups(scene.centres, scene.types, kHeadHeight, GraphClusteringParams{});
  HairClustering hair = cluster_hair(scene.centres, scene.types, middle.middle_cluster, kHeadHeight,
                                     HairClusteringParams{});
  // Nodes: two caps, two middle clusters, two tips, the free strand.
  EXPECT_EQ(hair.graph.node_count, 7);
  EXPECT_EQ(hair.clusters_before_split, 3);
  EXPECT_EQ(hair.split_count, 2);
  EXPECT_EQ(hair.cluster_origin.size(), 5u);
  for (size_t g = 0; g < scene.types.size(); ++g)
    for (size_t h = 0; h < scene.types.size(); ++h) {
      EXPECT_EQ(hair.cluster_before_split[g] == hair.cluster_before_split[h],
                scene.stream[g] == scene.stream[h])
          << g << " " << h;
      bool root_g = scene.types[g] == GroupType::root_connected;
      bool root_h = scene.types[h] == GroupType::root_connected;
      EXPECT_EQ(hair.cluster[g] == hair.cluster[h],
                scene.stream[g] == scene.stream[h] && root_g == root_h)
          << g << " " << h;
    }
  // The free strand is in S1, alone.
  EXPECT_EQ(hair.node_in_s1[static_cast<size_t>(hair.node_of_group.back())], 1);
  EXPECT_EQ(hair.cluster_group_count[static_cast<size_t>(hair.cluster.back())], 1);
  // Without the division the caps stay with their streams.
  HairClusteringParams whole;
  whole.split_at_type_change = false;
  HairClustering undivided =
      cluster_hair(scene.centres, scene.types, middle.middle_cluster, kHeadHeight, whole);
  EXPECT_EQ(undivided.cluster, undivided.cluster_before_split);
  EXPECT_EQ(undivided.split_count, 0);
}

/// One stream as braid01's: a 4 cm cap (root_connected), a gap of 3 cm (beyond typeify's
/// reach of 0.08 H, within cluster-all's f1 bound of H / 4), then a 10 cm strip that typeify
/// typed root_connected too, three 4 cm middle pieces and a 4 cm tip, 5 mm apart.
Scene cap_then_rooted_strip() {
  Scene scene;
  std::vector<Points3f> pieces;
  pieces.push_back(piece({0, 0, 0}, {0, -0.04f, 0}));
  scene.types.push_back(GroupType::root_connected);
  pieces.push_back(piece({0, -0.07f, 0}, {0, -0.17f, 0}));
  scene.types.push_back(GroupType::root_connected);
  float top = -0.175f;
  for (int p = 0; p < 4; ++p, top -= 0.045f) {
    pieces.push_back(piece({0, top, 0}, {0, top - 0.04f, 0}));
    scene.types.push_back(p == 3 ? GroupType::tip : GroupType::middle);
  }
  scene.stream.assign(scene.types.size(), 0);
  scene.centres = strand_set_from_polylines(pieces);
  return scene;
}

TEST(HairClustering, ARootTypedStripThatContinuesTheCapIsDividedFromIt) {
  Scene scene = cap_then_rooted_strip();
  MiddleClustering middle =
      cluster_middle_groups(scene.centres, scene.types, kHeadHeight, GraphClusteringParams{});
  HairClusteringParams continued;
  continued.split_continued_roots = true;
  HairClustering hair =
      cluster_hair(scene.centres, scene.types, middle.middle_cluster, kHeadHeight, continued);
  ASSERT_EQ(hair.clusters_before_split, 1);
  EXPECT_EQ(hair.split_count, 1);
  // The cap alone at the root; the strip goes with the middle pieces and the tip.
  EXPECT_EQ(hair.continues_group, (std::vector<uint8_t>{0, 1, 0, 0, 0, 0}));
  EXPECT_EQ(hair.cluster, (std::vector<int32_t>{0, 1, 1, 1, 1, 1}));
  EXPECT_EQ(hair.cluster_starts_at_root, (std::vector<uint8_t>{1, 0}));
  EXPECT_EQ(hair.cluster_group_count, (std::vector<int32_t>{1, 5}));

  // The same with the strip starting 0.12 H from the scalp, the cap on it.
  std::vector<double> scalp_distance_m = {0.0, 0.12 * kHeadHeight, 0.2, 0.2, 0.2, 0.2};
  HairClustering off_scalp = cluster_hair(scene.centres, scene.types, middle.middle_cluster,
                                          kHeadHeight, continued, scalp_distance_m);
  EXPECT_EQ(off_scalp.cluster, hair.cluster);
  // A strip that starts on the scalp (under 0.05 H) starts at a root: it stays.
  scalp_distance_m[1] = 0.03 * kHeadHeight;
  HairClustering on_scalp = cluster_hair(scene.centres, scene.types, middle.middle_cluster,
                                         kHeadHeight, continued, scalp_distance_m);
  EXPECT_EQ(on_scalp.continues_group, (std::vector<uint8_t>(6, 0)));
  EXPECT_EQ(on_scalp.cluster, (std::vector<int32_t>{0, 0, 1, 1, 1, 1}));

  // Without the rule the strip, a root type, stays with the cap.
  HairClusteringParams whole_roots;
  whole_roots.split_continued_roots = false;
  HairClustering before =
      cluster_hair(scene.centres, scene.types, middle.middle_cluster, kHeadHeight, whole_roots);
  EXPECT_EQ(before.cluster, (std::vector<int32_t>{0, 0, 1, 1, 1, 1}));
  EXPECT_EQ(before.continues_group, (std::vector<uint8_t>(6, 0)));

  // A strip that starts beyond the f1 bound of the cap's end is no continuation.
  Scene apart = scene;
  std::vector<Points3f> pieces;
  for (int64_t g = 0; g < scene.centres.strand_count(); ++g)
    pieces.push_back(scene.centres.strand(g));
  pieces[0] = piece({0, 0.1f, 0}, {0, 0.06f, 0});  // 13 cm above the strip: beyond H / 4
  apart.centres = strand_set_from_polylines(pieces);
  HairClustering far =
      cluster_hair(apart.centres, apart.types, middle.middle_cluster, kHeadHeight, continued);
  EXPECT_EQ(far.continues_group, (std::vector<uint8_t>(6, 0)));
}

// Two root groups that start 2 cm apart on either side of a parting and run apart in a
// line: read backwards, each runs into the other, but a root group read backwards ends at
// the scalp, so neither continues the other, even off the scalp.
TEST(HairClustering, RootGroupsOnEitherSideOfAPartingDoNotContinueEachOther) {
  std::vector<Points3f> pieces = {piece({0.01f, 0, 0}, {0.11f, 0, 0}),
                                  piece({-0.01f, 0, 0}, {-0.11f, 0, 0})};
  std::vector<GroupType> types = {GroupType::root_connected, GroupType::root_connected};
  StrandSet centres = strand_set_from_polylines(pieces);
  std::vector<int32_t> no_middle = {-1, -1};
  HairClustering hair =
      cluster_hair(centres, types, no_middle, kHeadHeight, HairClusteringParams{}, {0.1, 0.1});
  ASSERT_EQ(hair.clusters_before_split, 1);
  EXPECT_EQ(hair.continues_group, (std::vector<uint8_t>{0, 0}));
  EXPECT_EQ(hair.cluster_starts_at_root, (std::vector<uint8_t>{1}));
}

TEST(HairClustering, NoMiddleGroupsIsSkippedAndBadInputRefused) {
  Scene scene = two_streams();
  std::vector<GroupType> no_middle(scene.types.size(), GroupType::root_free);
  MiddleClustering middle =
      cluster_middle_groups(scene.centres, no_middle, kHeadHeight, GraphClusteringParams{});
  EXPECT_EQ(middle.count_source, ClusterCountSource::skipped);
  EXPECT_EQ(middle.cluster_count, 0);
  EXPECT_TRUE(middle.graph.edges.empty());
  std::vector<GroupType> too_few(3, GroupType::middle);
  EXPECT_THROW(cluster_middle_groups(scene.centres, too_few, kHeadHeight, GraphClusteringParams{}),
               Error);
  EXPECT_THROW(cluster_middle_groups(scene.centres, scene.types, 0, GraphClusteringParams{}),
               Error);
  // A middle group without a middle cluster.
  std::vector<int32_t> none(scene.types.size(), -1);
  EXPECT_THROW(cluster_hair(scene.centres, scene.types, none, kHeadHeight, HairClusteringParams{}),
               Error);
}

}  // namespace
}  // namespace hair
