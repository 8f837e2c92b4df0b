// Tails modelled as closed shells (hair-synth's shell_tail: each tail strip a pouch whose
// rails run down its front, round its tip and back up its back, as Mozilla Hubs' ponytails
// are built): extract parts every rail at its fold into two strands from the band down, so
// no input strand of a tail turns back on itself and each runs the way its true hair does.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <variant>

#include "hair/extract/extract.h"
#include "hair/mesh/mesh_io.h"
#include "hair/synth/synth_eval.h"
#include "hair/synth/synth_model.h"
#include "hair/synth/synth_paint.h"

namespace hair::synth {
namespace {

/// The input strands of the tail's groups (the pieces whose truth is not fixed hair: the
/// caps are), how many turn back (two consecutive segments more than 90 degrees apart),
/// and how many end lower than they start (from the band down).
struct TailStrands {
  int64_t strands = 0;
  int64_t turning_back = 0;
  int64_t hanging_down = 0;
};

TailStrands tail_strands(const SynthModel& model, const ExtractResult& extract) {
  const std::vector<int32_t> patch_of_group = group_patches(model, extract);
  const StrandSet& strands = extract.strands;
  const auto& group = std::get<std::vector<int32_t>>(strands.strand_attributes.at("group"));
  TailStrands tail;
  for (int64_t s = 0; s < strands.strand_count(); ++s) {
    const int32_t patch = patch_of_group[static_cast<size_t>(group[static_cast<size_t>(s)])];
    if (patch < 0 || model.patches[static_cast<size_t>(patch)].style == HairStyle::fixed) continue;
    ++tail.strands;
    const int64_t first = strands.offsets[s], last = strands.offsets[s + 1] - 1;
    if (strands.points(last, 1) < strands.points(first, 1)) ++tail.hanging_down;
    for (int64_t row = first + 1; row < last; ++row) {
      const Eigen::Vector3f before = strands.points.row(row) - strands.points.row(row - 1);
      const Eigen::Vector3f after = strands.points.row(row + 1) - strands.points.row(row);
      if (before.dot(after) < 0) {
        ++tail.turning_back;
        break;
      }
    }
  }
  return tail;
}

TEST(SynthShellTail, RailsFoldedAtTheTipArePartedIntoStrandsFromTheBandDown) {
  PolyMesh body = read_mesh(std::filesystem::path(HAIR_SOURCE_DIR) / "data/samples/body.obj");
  body.vertices *= 0.1f;
  ExtractParams unparted;  // no rail is parted: the folds stay in the input strands
  unparted.parting_min_side_drop = 1;
  for (uint32_t seed : {1u, 2u, 3u}) {
    SCOPED_TRACE("shell_tail, seed " + std::to_string(seed));
    const SynthModel model = generate_model(varied_spec(preset("shell_tail"), seed), body, seed);
    const ExtractParams params;
    const PaintedTextures textures =
        load_painted_textures(model.mesh.materials, params.painted_flow, model.name);
    const ExtractResult parted =
        extract_strands(model.mesh, body, params, model.name, "body", textures);
    const ExtractResult folded =
        extract_strands(model.mesh, body, unparted, model.name, "body", textures);
    const TailStrands tail = tail_strands(model, parted);
    const TailStrands tail_folded = tail_strands(model, folded);
    std::printf(
        "[ shell    ] seed %u: %lld tail strands, %lld turn back, %lld hang down; rails "
        "not parted: %lld of %lld turn back\n",
        seed, static_cast<long long>(tail.strands), static_cast<long long>(tail.turning_back),
        static_cast<long long>(tail.hanging_down), static_cast<long long>(tail_folded.turning_back),
        static_cast<long long>(tail_folded.strands));
    // Each pouch's rails fold at the tip: read whole, a third or more of them turn back.
    ASSERT_GT(tail_folded.strands, 0);
    EXPECT_GT(tail_folded.turning_back, tail_folded.strands / 3);
    // Parted, none does, and every one runs from the band down to the tip.
    ASSERT_GT(tail.strands, tail_folded.strands);
    EXPECT_EQ(tail.turning_back, 0);
    EXPECT_EQ(tail.hanging_down, tail.strands);
  }
}

}  // namespace
}  // namespace hair::synth
