// Two-level spectral clustering (cluster-middle, cluster-all) measured against the
// truth of synthetic hairstyles, printed as tables (docs/clustering.md): the adjusted
// Rand index (ARI) of the middle clustering against the true streams of the groups
// it clustered, and of the final clustering (before the division at type changes)
// against the true streams, two-level against one-level, with typeify's types and
// with the true types.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "hair/cluster/adjusted_rand_index.h"
#include "hair/cluster/hair_clustering.h"
#include "hair/cluster/typeify.h"
#include "hair/extract/extract.h"
#include "hair/mesh/mesh_io.h"
#include "hair/synth/synth_eval.h"
#include "hair/synth/synth_model.h"
#include "unit/clustered_in_memory.h"
#include "unit/mean_column.h"

namespace hair::synth {
namespace {

using hair::testing::kNotMeasured;

/// ARIs of one model; NaN where there was nothing to measure.
struct ClusteringScores {
  double middle = kNotMeasured;     ///< middle clusters vs true streams, over the groups clustered
  double two_level = kNotMeasured;  ///< final (before split) vs true streams, chained streams
  double one_level = kNotMeasured;  ///< the same with no middle clustering first
  double two_level_components = kNotMeasured;  ///< final vs true components, all groups
  double one_level_components = kNotMeasured;
  double one_level_middle = kNotMeasured;  ///< one level, first-level graph, on middle groups
  /// one level, the paper's graph (papers_one_level()), on middle groups vs true streams
  double one_level_paper_middle = kNotMeasured;
  int middle_groups = 0, chained_groups = 0;
};

/// Labels of `values` at `items`.
std::vector<int32_t> pick(const std::vector<int32_t>& values, const std::vector<int32_t>& items) {
  std::vector<int32_t> picked;
  for (int32_t item : items) picked.push_back(values[static_cast<size_t>(item)]);
  return picked;
}

/// The paper's one level (section 4.2: "a naive application of spectral clustering for
/// the entire set of strand groups"): every group a node, the complete graph over them
/// with the paper's criteria as it states them (f1 over the halves, f3 from the farthest
/// point, each group as extract oriented it, no f4), its bounds (f1 < H/4, f2 < 0.5,
/// f3 < 0.3), the local-similarity halving, k = (0.5, 0.2, 0.3) (the paper's valid
/// region, Figure 4, is not in its text) and the median weight as the affinity scale.
HairClusteringParams papers_one_level() {
  HairClusteringParams params;
  params.split_at_type_change = false;
  GraphClusteringParams& graph = params.graph;
  graph.continuations = 0;
  graph.affinity_scale = 0;
  graph.either_orientation = false;
  graph.halve_best_tip_side = true;
  ConnectivityParams& c = graph.connectivity;
  c.k1 = 0.5;
  c.k2 = 0.2;
  c.k3 = 0.3;
  c.k4 = 0;
  c.f1_max = 0.25;
  c.f2_max = 0.5;
  c.f3_max = 0.3;
  c.f4_max = 1;
  c.flow_direction = FlowDirection::farthest_point;
  c.closeness = Closeness::halves;
  return params;
}

ClusteringScores score(const SynthModel& model, const ExtractResult& extract,
                       const std::vector<hair::GroupType>& types, const StrandSet& centres) {
  std::vector<int32_t> patch_of = group_patches(model, extract);
  std::vector<int32_t> stream(patch_of.size(), -1), component(patch_of.size(), -1);
  std::vector<int> patches_in_stream(model.patches.size() + 1, 0);
  for (const SynthPatch& patch : model.patches)
    ++patches_in_stream[static_cast<size_t>(patch.stream)];
  for (size_t g = 0; g < patch_of.size(); ++g)
    if (patch_of[g] >= 0) {
      stream[g] = model.patches[static_cast<size_t>(patch_of[g])].stream;
      component[g] = model.stream_component[static_cast<size_t>(stream[g])];
    }

  double h = extract.head.head_height;
  HairClusteringParams params;
  MiddleClustering middle = cluster_middle_groups(centres, types, h, GraphClusteringParams{});
  HairClustering two = cluster_hair(centres, types, middle.middle_cluster, h, params);
  HairClustering one = cluster_hair(centres, types, each_middle_group_alone(types), h, params);
  // One level with the first level's graph: every group at once, streams as the aim.
  HairClusteringParams stream_params;
  stream_params.graph = GraphClusteringParams{};
  stream_params.split_at_type_change = false;
  HairClustering one_streams =
      cluster_hair(centres, types, each_middle_group_alone(types), h, stream_params);
  HairClustering one_paper =
      cluster_hair(centres, types, each_middle_group_alone(types), h, papers_one_level());

  ClusteringScores scores;
  std::vector<int32_t> middle_items, chained_items, all_items;
  for (size_t g = 0; g < types.size(); ++g) {
    if (stream[g] < 0) continue;
    all_items.push_back(static_cast<int32_t>(g));
    if (types[g] == hair::GroupType::middle) middle_items.push_back(static_cast<int32_t>(g));
    if (patches_in_stream[static_cast<size_t>(stream[g])] > 1)
      chained_items.push_back(static_cast<int32_t>(g));
  }
  scores.middle_groups = static_cast<int>(middle_items.size());
  scores.chained_groups = static_cast<int>(chained_items.size());
  if (middle_items.size() > 1) {
    scores.middle =
        adjusted_rand_index(pick(middle.middle_cluster, middle_items), pick(stream, middle_items));
    scores.one_level_middle = adjusted_rand_index(
        pick(one_streams.cluster_before_split, middle_items), pick(stream, middle_items));
    scores.one_level_paper_middle = adjusted_rand_index(
        pick(one_paper.cluster_before_split, middle_items), pick(stream, middle_items));
  }
  if (chained_items.size() > 1) {
    scores.two_level = adjusted_rand_index(pick(two.cluster_before_split, chained_items),
                                           pick(stream, chained_items));
    scores.one_level = adjusted_rand_index(pick(one.cluster_before_split, chained_items),
                                           pick(stream, chained_items));
  }
  if (all_items.size() > 1) {
    scores.two_level_components =
        adjusted_rand_index(pick(two.cluster_before_split, all_items), pick(component, all_items));
    scores.one_level_components =
        adjusted_rand_index(pick(one.cluster_before_split, all_items), pick(component, all_items));
  }
  return scores;
}

using Column = hair::testing::MeanColumn;

struct Row {
  Column middle, one_level_middle, one_level_paper_middle, two_level, one_level, two_components,
      one_components, true_middle, true_two_level, true_one_level;
  void add(const ClusteringScores& found, const ClusteringScores& truth) {
    middle.add(found.middle);
    one_level_middle.add(found.one_level_middle);
    one_level_paper_middle.add(found.one_level_paper_middle);
    two_level.add(found.two_level);
    one_level.add(found.one_level);
    two_components.add(found.two_level_components);
    one_components.add(found.one_level_components);
    true_middle.add(truth.middle);
    true_two_level.add(truth.two_level);
    true_one_level.add(truth.one_level);
  }
  void print(const std::string& label) const {
    std::printf(
        "[ synth    ] %-15s | %6.3f %6.3f %6.3f | %6.3f %6.3f %6.3f %6.3f | %6.3f %6.3f %6.3f\n",
        label.c_str(), middle.mean(), one_level_middle.mean(), one_level_paper_middle.mean(),
        two_level.mean(), one_level.mean(), two_components.mean(), one_components.mean(),
        true_middle.mean(), true_two_level.mean(), true_one_level.mean());
  }
};

TEST(SynthClustering, AdjustedRandIndexPerPreset) {
  PolyMesh body = read_mesh(std::filesystem::path(HAIR_SOURCE_DIR) / "data/samples/body.obj");
  body.vertices *= 0.1f;
  std::printf(
      "[ synth    ] %-15s | typeify's types:                                       | true "
      "types:\n",
      "");
  std::printf(
      "[ synth    ] %-15s | middle 1L-mid 1L-ppr |  2L-st  1L-st 2L-cmp 1L-cmp | middle  2L-st  "
      "1L-st\n",
      "preset");
  // Seeds 1-3 chose the defaults (docs/clustering.md); seeds 4-6 are held out.
  Row braided, all, held_out_braided, held_out_all;
  for (const std::string& name : preset_names()) {
    Row row;
    for (uint32_t seed : {1u, 2u, 3u, 4u, 5u, 6u}) {
      SynthModel model = generate_model(varied_spec(preset(name), seed), body, seed, 2);
      ExtractResult extract = extract_strands(model.mesh, body, ExtractParams{}, name, "body");
      GroupTypes found = testing::typeify_in_memory(extract);
      ClusteringScores with_found = score(model, extract, found.type, found.centre_strands);
      std::vector<int32_t> patch_of = group_patches(model, extract);
      std::vector<hair::GroupType> truth = found.type;
      for (size_t g = 0; g < truth.size(); ++g)
        if (patch_of[g] >= 0)
          truth[g] = static_cast<hair::GroupType>(
              static_cast<int8_t>(model.patches[static_cast<size_t>(patch_of[g])].type));
      ClusteringScores with_truth = score(model, extract, truth, found.centre_strands);
      bool held_out = seed > 3;
      bool braid = name.find("braid") != std::string::npos;
      if (!held_out) row.add(with_found, with_truth);
      (held_out ? held_out_all : all).add(with_found, with_truth);
      if (braid) (held_out ? held_out_braided : braided).add(with_found, with_truth);
    }
    row.print(name);
  }
  braided.print("braided presets");
  all.print("all");
  held_out_braided.print("braided, 4-6");
  held_out_all.print("all, seeds 4-6");
  // Measured (docs/clustering.md): middle ARI 0.976 over the braided presets, 0.868 over
  // all; held out: 0.990 and 0.957 (with hair-synth's creased two_braids of before: 0.909,
  // 0.846, 0.936, 0.939; before the continuation offset f4: 0.82, 0.80, 0.81, 0.84).
  // Floors that catch a broken clustering, under the figures: one false link between
  // two streams can take a model from 1.0 to 0.56 (braid seed 1 before f4), 0.05 of the
  // braided mean.
  EXPECT_GT(braided.middle.mean(), 0.9);
  EXPECT_GT(all.middle.mean(), 0.8);
  EXPECT_GT(held_out_braided.middle.mean(), 0.9);
  // The paper's claim (section 4.2): one level over all groups fails on braids. With its
  // complete graph the streams' ARI on the braided presets is 0.13-0.18 (docs).
  EXPECT_GT(braided.middle.mean(), braided.one_level_paper_middle.mean() + 0.5);
  EXPECT_GT(held_out_braided.middle.mean(), held_out_braided.one_level_paper_middle.mean() + 0.5);
}

// The division's continued roots (HairClusteringParams::split_continued_roots) against the
// truth: among the groups typeify types root, a true first piece of its stream starts at
// the root and should stay with the root part; a later piece continues its stream's
// previous piece and should go with the distal part.
TEST(SynthClustering, ContinuedRootsAgainstTheTruth) {
  PolyMesh body = read_mesh(std::filesystem::path(HAIR_SOURCE_DIR) / "data/samples/body.obj");
  body.vertices *= 0.1f;
  std::printf("[ synth    ] %-15s | first piece:   kept continued | later piece: kept continued\n",
              "preset");
  std::array<std::array<int, 2>, 2> all{};  // [later piece][continued]
  for (const std::string& name : preset_names()) {
    std::array<std::array<int, 2>, 2> counts{};
    for (uint32_t seed : {1u, 2u, 3u}) {
      SynthModel model = generate_model(varied_spec(preset(name), seed), body, seed, 2);
      hair::testing::ClusteredInMemory run =
          hair::testing::cluster_in_memory(model.mesh, body, name);
      const GroupTypes& found = run.types;
      const HairClustering& clusters = run.clusters;
      std::vector<int32_t> patch_of = group_patches(model, run.extract);
      for (size_t g = 0; g < found.type.size(); ++g) {
        bool root = found.type[g] == hair::GroupType::root_free ||
                    found.type[g] == hair::GroupType::root_connected;
        if (!root || patch_of[g] < 0) continue;
        bool later = model.patches[static_cast<size_t>(patch_of[g])].index_in_stream > 0;
        ++counts[later ? 1 : 0][clusters.continues_group[g] ? 1 : 0];
      }
    }
    std::printf("[ synth    ] %-15s | %17d %9d | %17d %9d\n", name.c_str(), counts[0][0],
                counts[0][1], counts[1][0], counts[1][1]);
    for (size_t i = 0; i < 2; ++i)
      for (size_t j = 0; j < 2; ++j) all[i][j] += counts[i][j];
  }
  std::printf("[ synth    ] %-15s | %17d %9d | %17d %9d\n", "all", all[0][0], all[0][1], all[1][0],
              all[1][1]);
  // Measured (docs/clustering.md): 2 of 521 first pieces taken for continued, 5 of 33
  // later pieces found (the others start on the scalp, within 0.05 H, where roots are
  // plausible anyway). Without the scalp distance: 113 of 521 and 7 of 33.
  EXPECT_LE(all[0][1] * 100, all[0][0] + all[0][1]);
  EXPECT_GT(all[1][1], all[0][1]);
}

}  // namespace
}  // namespace hair::synth
