// Stages measured against the truth of synthetic hairstyles, printed as tables
// (docs/synth.md): typeify's group types (Algorithm 1), and which of extract's
// orientation rules decided the groups it orients the wrong way.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>

#include "hair/cluster/typeify.h"
#include "hair/extract/extract.h"
#include "hair/mesh/mesh_io.h"
#include "hair/synth/synth_eval.h"
#include "hair/synth/synth_io.h"
#include "hair/synth/synth_model.h"
#include "unit/clustered_in_memory.h"

namespace hair::synth {
namespace {

struct Measured {
  int groups = 0, right_type = 0, right_orientation = 0;
  std::array<std::array<int, 4>, 4> confusion{};  // [true type][found type]
};

/// Extract (in metres, from the model's mesh in memory) and typeify one model.
Measured measure(const SynthModel& model, const PolyMesh& body_m,
                 const TypeifyParams& typeify_params) {
  ExtractParams extract_params;  // unit_scale 1: the mesh and body are in metres
  ExtractResult extract = extract_strands(model.mesh, body_m, extract_params, model.name, "body");
  std::vector<int32_t> patch_of = group_patches(model, extract);
  std::vector<GroupOrientation> orientation = group_orientations(model, extract, patch_of);
  GroupTypes types = testing::typeify_in_memory(extract, typeify_params);
  Measured measured;
  for (int32_t g = 0; g < extract.group_count(); ++g) {
    int32_t patch = patch_of[static_cast<size_t>(g)];
    if (patch < 0) continue;
    ++measured.groups;
    auto truth = static_cast<size_t>(model.patches[static_cast<size_t>(patch)].type);
    auto found = static_cast<size_t>(types.type[static_cast<size_t>(g)]);
    ++measured.confusion[truth][found];
    measured.right_type += truth == found ? 1 : 0;
    measured.right_orientation +=
        orientation[static_cast<size_t>(g)] == GroupOrientation::root_to_tip ? 1 : 0;
  }
  return measured;
}

/// Sums `one` into `sum`.
void add(Measured& sum, const Measured& one) {
  sum.groups += one.groups;
  sum.right_type += one.right_type;
  sum.right_orientation += one.right_orientation;
  for (size_t t = 0; t < 4; ++t)
    for (size_t f = 0; f < 4; ++f) sum.confusion[t][f] += one.confusion[t][f];
}

void print_confusion(const char* title, const Measured& all) {
  std::printf("[ synth    ] %s: true \\ found    root_free root_connected middle tip\n", title);
  const char* names[] = {"root_free", "root_connected", "middle", "tip"};
  for (size_t t = 0; t < 4; ++t)
    std::printf("[ synth    ] %-15s %9d %14d %6d %3d\n", names[t], all.confusion[t][0],
                all.confusion[t][1], all.confusion[t][2], all.confusion[t][3]);
}

// The type of every group against the truth, with the paper's Algorithm 1 (the default)
// and with the rooted-on-the-scalp rule (root_scalp_distance_h 0.05, docs/typeify.md).
TEST(SynthTypeify, TypesAgainstTheTruthPerPreset) {
  PolyMesh body = read_mesh(std::filesystem::path(HAIR_SOURCE_DIR) / "data/samples/body.obj");
  body.vertices *= 0.1f;
  const TypeifyParams paper;
  const TypeifyParams rooted{.root_scalp_distance_h = 0.05};
  Measured all, all_rooted;
  std::printf("[ synth    ] preset           groups  type right  rooted rule  oriented right\n");
  for (const std::string& name : preset_names()) {
    Measured sum, sum_rooted;
    for (uint32_t seed : {1u, 2u, 3u}) {
      SynthModel model = generate_model(varied_spec(preset(name), seed), body, seed, 2);
      Measured one = measure(model, body, paper);
      EXPECT_EQ(one.groups, static_cast<int>(model.patches.size())) << name << " seed " << seed;
      add(sum, one);
      add(sum_rooted, measure(model, body, rooted));
    }
    std::printf("[ synth    ] %-15s %7d  %10.3f  %11.3f  %14.3f\n", name.c_str(), sum.groups,
                static_cast<double>(sum.right_type) / sum.groups,
                static_cast<double>(sum_rooted.right_type) / sum.groups,
                static_cast<double>(sum.right_orientation) / sum.groups);
    add(all, sum);
    add(all_rooted, sum_rooted);
  }
  const double right = static_cast<double>(all.right_type) / all.groups;
  const double right_rooted = static_cast<double>(all_rooted.right_type) / all.groups;
  std::printf("[ synth    ] all             %7d  %10.3f  %11.3f  %14.3f\n", all.groups, right,
              right_rooted, static_cast<double>(all.right_orientation) / all.groups);
  print_confusion("paper's rule", all);
  print_confusion("rooted rule", all_rooted);
  // Measured: 0.663 and 0.765 of 2035 groups (seeds 1-3 of every preset). A loose floor
  // that catches a broken typeify, not a target; the rooted rule must find the root cards
  // that lie under other cards' lower halves (0.10 better: 0.05 catches its loss).
  EXPECT_GE(right, 0.5);
  EXPECT_GE(right_rooted, right + 0.05);
  EXPECT_GT(all_rooted.confusion[0][0] + all_rooted.confusion[1][1],
            all.confusion[0][0] + all.confusion[1][1] + 100);
}

TEST(SynthExtract, OrientationRuleOfEveryGroupAgainstTheTruth) {
  PolyMesh body = read_mesh(std::filesystem::path(HAIR_SOURCE_DIR) / "data/samples/body.obj");
  body.vertices *= 0.1f;
  const char* rules[] = {"vertex_order", "scalp_distance", "continuation",
                         "uv",           "height",         "parting",
                         "alpha_fade"};
  const char* orders[] = {"natural", "reversed", "shuffled"};
  // (kind of patch, vertex order, rule) -> {right, wrong}
  std::map<std::string, std::array<int, 2>> counts;
  for (uint32_t seed = 1; seed <= 6; ++seed)
    for (const char* name :
         {"braid", "two_braids", "normal_braid", "long_straight", "medium_straight"}) {
      SynthModel model = generate_model(varied_spec(preset(name), seed), body, seed, 2);
      ExtractResult extract = extract_strands(model.mesh, body, ExtractParams{}, name, "body");
      std::vector<int32_t> patch_of = group_patches(model, extract);
      std::vector<GroupOrientation> orientation = group_orientations(model, extract, patch_of);
      for (int32_t g = 0; g < extract.group_count(); ++g) {
        if (patch_of[static_cast<size_t>(g)] < 0) continue;
        const SynthPatch& patch =
            model.patches[static_cast<size_t>(patch_of[static_cast<size_t>(g)])];
        std::string kind = patch.style == HairStyle::braided ? "braid piece"
                           : patch.index_in_stream == 0      ? "first piece"
                                                             : "later piece";
        std::string key = kind + ", " + orders[static_cast<size_t>(patch.order)] + ", " +
                          rules[static_cast<size_t>(extract.group_rule[static_cast<size_t>(g)])];
        ++counts[key][orientation[static_cast<size_t>(g)] == GroupOrientation::root_to_tip ? 0 : 1];
      }
    }
  std::printf("[ synth    ] %-45s %6s %6s\n", "patch, vertex order, rule", "right", "wrong");
  int right = 0, wrong = 0;
  for (const auto& [key, votes] : counts) {
    std::printf("[ synth    ] %-45s %6d %6d\n", key.c_str(), votes[0], votes[1]);
    right += votes[0];
    wrong += votes[1];
  }
  EXPECT_GT(right, wrong);
}

}  // namespace
}  // namespace hair::synth
