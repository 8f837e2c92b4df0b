// The synthetic hair generator (common/hair/synth, issue 3): every patch labelled, the
// patches of a stream chained root to tip, determinism, and every preset's mesh read by
// extract_strands with one group per patch, oriented as the truth says.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <stdexcept>

#include "hair/core/error.h"
#include "hair/extract/extract.h"
#include "hair/geom/triangle_mesh_distance.h"
#include "hair/mesh/mesh_io.h"
#include "hair/synth/synth_eval.h"
#include "hair/synth/synth_io.h"
#include "hair/synth/synth_model.h"

namespace hair::synth {
namespace {

const PolyMesh& body_m() {
  static const PolyMesh body = [] {
    PolyMesh mesh = read_mesh(std::filesystem::path(HAIR_SOURCE_DIR) / "data/samples/body.obj");
    mesh.vertices *= 0.1f;
    return mesh;
  }();
  return body;
}

/// `model` as extract reads it: through the OBJ text hair-synth writes (decimetres), in a
/// temporary file named `stem`.obj, on the body in decimetres too.
ExtractResult extract_through_obj(const SynthModel& model, const std::string& stem) {
  const std::filesystem::path obj = std::filesystem::temp_directory_path() / (stem + ".obj");
  {
    std::ofstream file(obj, std::ios::binary);
    if (!file) throw std::runtime_error("cannot write " + obj.string());
    file << obj_text(model, 0.1);
  }
  PolyMesh hair = read_mesh(obj);
  std::filesystem::remove(obj);
  PolyMesh body = body_m();
  body.vertices *= 10.0f;
  ExtractParams params;
  params.unit_scale = 0.1;
  return extract_strands(hair, body, params, obj.string(), "body.obj");
}

class SynthPreset : public ::testing::TestWithParam<std::string> {};

TEST_P(SynthPreset, EveryPatchLabelledAndPartitioningTheMesh) {
  SynthModel model = generate_model(preset(GetParam()), body_m(), 7);
  ASSERT_FALSE(model.patches.empty());
  int64_t next_vertex = 0, next_face = 0;
  int32_t streams = static_cast<int32_t>(model.stream_style.size());
  EXPECT_EQ(model.stream_centres.strand_count(), streams);
  for (const SynthPatch& patch : model.patches) {
    EXPECT_GE(patch.stream, 0);
    EXPECT_LT(patch.stream, streams);
    EXPECT_EQ(patch.first_vertex, next_vertex);
    EXPECT_EQ(patch.first_face, next_face);
    EXPECT_GT(patch.face_count, 0);
    EXPECT_EQ(patch.vertex_count % patch.rails, 0);
    next_vertex += patch.vertex_count;
    next_face += patch.face_count;
  }
  EXPECT_EQ(next_vertex, model.mesh.vertex_count());
  EXPECT_EQ(next_face, model.mesh.face_count());
  EXPECT_EQ(model.mesh.corner_uv.rows(),
            static_cast<Eigen::Index>(model.mesh.face_vertices.size()));
  EXPECT_TRUE(model.mesh.vertices.allFinite());
  EXPECT_TRUE(model.strands.points.allFinite());
  EXPECT_GE(model.strands.strand_count(), streams);  // every stream has true strands
  EXPECT_EQ(static_cast<int64_t>(model.strand_point_style.size()), model.strands.point_count());
  // Every style of a patch is the style of some true-strand points, and no other is.
  std::set<HairStyle> patch_styles,
      point_styles(model.strand_point_style.begin(), model.strand_point_style.end());
  for (const SynthPatch& patch : model.patches) patch_styles.insert(patch.style);
  EXPECT_EQ(patch_styles, point_styles);
}

TEST_P(SynthPreset, PatchesOfAStreamChainRootToTip) {
  SynthModel model = generate_model(preset(GetParam()), body_m(), 7);
  Triangles3i triangles = fan_triangulation(body_m().face_offsets, body_m().face_vertices);
  TriangleMeshDistance body(body_m().vertices, triangles);
  std::map<int32_t, std::vector<const SynthPatch*>> by_stream;
  for (const SynthPatch& patch : model.patches) by_stream[patch.stream].push_back(&patch);
  ASSERT_EQ(by_stream.size(), model.stream_style.size());
  // Mean position of the vertices of a patch at arc length `along` (its first or last row).
  auto row_centre = [&](const SynthPatch& patch, float along) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    int count = 0;
    for (int64_t v = patch.first_vertex; v < patch.first_vertex + patch.vertex_count; ++v)
      if (std::abs(model.vertex_along_m[static_cast<size_t>(v)] - along) < 1e-6f) {
        sum += model.mesh.vertices.row(v).cast<double>().transpose();
        ++count;
      }
    EXPECT_GT(count, 0);
    return Eigen::Vector3d(sum / std::max(count, 1));
  };
  for (const auto& [stream, patches] : by_stream) {
    ASSERT_FALSE(patches.empty());
    // The root lies on the head.
    EXPECT_LT(
        body.distance(row_centre(*patches.front(), static_cast<float>(patches.front()->start_m))),
        0.02)
        << "stream " << stream;
    EXPECT_EQ(patches.front()->start_m, 0.0);
    for (size_t k = 0; k < patches.size(); ++k) {
      const SynthPatch& patch = *patches[k];
      EXPECT_EQ(patch.index_in_stream, static_cast<int32_t>(k));
      GroupType expected = patches.size() == 1       ? GroupType::root_free
                           : k == 0                  ? GroupType::root_connected
                           : k + 1 == patches.size() ? GroupType::tip
                                                     : GroupType::middle;
      EXPECT_EQ(patch.type, expected) << "stream " << stream << " patch " << k;
      EXPECT_LT(patch.start_m, patch.end_m);
      if (k == 0) continue;
      const SynthPatch& before = *patches[k - 1];
      // The next patch starts where this one ends, up to the hidden gap (at most the
      // largest band gap, 4.5 cm) or an overlap.
      EXPECT_GT(patch.start_m, before.start_m);
      EXPECT_LT(patch.start_m - before.end_m, 0.05);
      Eigen::Vector3d end = row_centre(before, static_cast<float>(before.end_m));
      Eigen::Vector3d start = row_centre(patch, static_cast<float>(patch.start_m));
      EXPECT_LT((end - start).norm(), 0.06) << "stream " << stream << " patch " << k;
    }
  }
}

TEST_P(SynthPreset, SameSeedSameModelOtherSeedOtherModel) {
  HairStyleSpec spec = preset(GetParam());
  SynthModel first = generate_model(spec, body_m(), 11);
  SynthModel again = generate_model(spec, body_m(), 11);
  SynthModel other = generate_model(spec, body_m(), 12);
  EXPECT_EQ(obj_text(first, 0.1), obj_text(again, 0.1));
  EXPECT_TRUE(first.strands.points == again.strands.points);
  EXPECT_NE(obj_text(first, 0.1), obj_text(other, 0.1));
}

/// Share of extracted strands running root to tip by the truth (arc length along the
/// stream growing from the strand's first point to its last), and the check that each
/// group is exactly one patch.
TEST_P(SynthPreset, ExtractFindsEveryPatchOrientedAsTheTruthSays) {
  for (uint32_t seed : {1u, 2u, 3u}) {
    SynthModel model = generate_model(varied_spec(preset(GetParam()), seed), body_m(), seed);
    // Through the OBJ text as hair-synth writes it, in decimetres.
    ExtractResult result =
        extract_through_obj(model, "hair_synth_test_" + GetParam() + "_" + std::to_string(seed));
    ASSERT_EQ(result.group_count(), static_cast<int32_t>(model.patches.size()))
        << GetParam() << " seed " << seed;

    // Per group: its patch, and whether its strands run root to tip, tip to root or
    // across (a rail read across the hair: both ends at the same arc length).
    std::vector<int32_t> group_patch = group_patches(model, result);
    std::vector<GroupOrientation> orientation = group_orientations(model, result, group_patch);
    std::array<std::array<int, 3>, 3> by_order{};  // [vertex order][agree, reversed, across]
    int agreeing_groups = 0;
    for (int32_t g = 0; g < result.group_count(); ++g) {
      auto verdict = static_cast<size_t>(orientation[static_cast<size_t>(g)]);
      agreeing_groups += verdict == 0 ? 1 : 0;
      ASSERT_GE(group_patch[static_cast<size_t>(g)], 0) << "group " << g << " spans patches";
      auto order = static_cast<size_t>(
          model.patches[static_cast<size_t>(group_patch[static_cast<size_t>(g)])].order);
      ++by_order[order][verdict];
    }
    std::vector<int32_t> sorted = group_patch;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(std::unique(sorted.begin(), sorted.end()), sorted.end()) << "two groups on one patch";
    double share = static_cast<double>(agreeing_groups) / result.group_count();
    std::printf(
        "[ synth    ] %-15s seed %u: %3zu patches, %.3f root to tip; natural %d/%d/%d, "
        "reversed %d/%d/%d, shuffled %d/%d/%d (right/wrong way/across)\n",
        GetParam().c_str(), seed, model.patches.size(), share, by_order[0][0], by_order[0][1],
        by_order[0][2], by_order[1][0], by_order[1][1], by_order[1][2], by_order[2][0],
        by_order[2][1], by_order[2][2]);
    // Measured over the presets, seeds 1-3: 0.71 (two_braids) to 1.0 (short). Wrong ones
    // are mostly patches numbered tip to root (extract trusts vertex order unless the
    // head distance overrules it) and braid pieces; see docs/synth.md. Hair lying on the
    // scalp (short_cap: 0.4-1.0) keeps its distance to the head, so nothing overrules
    // vertex order there, and a few grids, each a whole stream, make a model's share
    // swing with its reversed share (up to 0.3): only its natural-order grids are held
    // to being right (below).
    bool lies_on_scalp = model.spec.components[0].kind == ComponentSpec::Kind::short_cap;
    if (!lies_on_scalp) {
      EXPECT_GE(share, 0.65) << GetParam() << " seed " << seed;
    }
    // Hair numbered root to tip away from braids is never read the wrong way (a few
    // short wavy pieces are read across).
    if (model.spec.components.size() == 1 &&
        model.spec.components[0].kind != ComponentSpec::Kind::braid) {
      EXPECT_EQ(by_order[0][1], 0) << GetParam() << " seed " << seed;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Presets, SynthPreset, ::testing::ValuesIn(preset_names()),
                         [](const auto& test_info) { return test_info.param; });

/// Cards written as exporters write them: every quad split into two triangles along its
/// shorter diagonal in 3D (glTF, game engines). On a wavy, twisted or braided card the added
/// edge is then often no triangle's longest; extract pairs the triangles back into the
/// artist's quads and reads every patch as one group, oriented as with quads (ringlets'
/// tubes: most of their triangles).
TEST(SynthTriangulated, CardsSplitAlongTheirShorterDiagonalsReadAsTheirQuads) {
  for (const char* name : {"long_wavy", "ringlets", "braid", "bob"}) {
    for (uint32_t seed : {1u, 2u}) {
      HairStyleSpec quads_spec = varied_spec(preset(name), seed);
      quads_spec.defects.triangulate_share = 0;
      quads_spec.defects.shorter_diagonal_share = 1;  // the same random numbers drawn
      HairStyleSpec triangles_spec = quads_spec;
      triangles_spec.defects.triangulate_share = 1;
      const SynthModel quads = generate_model(quads_spec, body_m(), seed);
      const SynthModel triangles = generate_model(triangles_spec, body_m(), seed);
      // Two triangles a quad (less the few a tube's collapsed tip makes degenerate).
      ASSERT_GE(triangles.mesh.face_count(), 19 * quads.mesh.face_count() / 10) << name;
      const std::string stem = std::string("hair_synth_triangulated_") + name;
      const ExtractResult from_quads = extract_through_obj(quads, stem + "_quads");
      const ExtractResult from_triangles = extract_through_obj(triangles, stem + "_triangles");
      // A ringlet's tube twists round its axis: some of its quads have a corner more than
      // max_quad_corner_deviation_deg off a right angle in 3D and stay two triangles, which
      // parts the tube's rails there (its strands come in pieces).
      const bool tubes = std::string(name) == "ringlets";
      EXPECT_GE(static_cast<double>(from_triangles.stats.triangles_paired),
                (tubes ? 0.94 : 0.97) * static_cast<double>(triangles.mesh.face_count()))
          << name << " seed " << seed;
      if (tubes) continue;
      ASSERT_EQ(from_triangles.group_count(), static_cast<int32_t>(triangles.patches.size()))
          << name << " seed " << seed;
      // As many input strands as from the quads, within a few: rails are whole again.
      EXPECT_NEAR(static_cast<double>(from_triangles.strands.strand_count()),
                  static_cast<double>(from_quads.strands.strand_count()),
                  0.05 * static_cast<double>(from_quads.strands.strand_count()))
          << name << " seed " << seed;
      const std::vector<int32_t> group_patch = group_patches(triangles, from_triangles);
      const std::vector<GroupOrientation> orientation =
          group_orientations(triangles, from_triangles, group_patch);
      const std::vector<GroupOrientation> quad_orientation =
          group_orientations(quads, from_quads, group_patches(quads, from_quads));
      const auto agreeing = [](const std::vector<GroupOrientation>& o) {
        return std::count(o.begin(), o.end(), GroupOrientation{});
      };
      EXPECT_GE(agreeing(orientation), agreeing(quad_orientation) - 1) << name << " seed " << seed;
    }
  }
}

TEST(SynthPresets, UnknownPresetIsAUsageError) { EXPECT_THROW(preset("beehive"), hair::Error); }

TEST(SynthPresets, CorpusCyclingThePresetsMeetsTheIssuesMinimums) {
  // What `hair-synth corpus --count 60` builds.
  std::array<int, 4> totals{};
  int mixed = 0;
  std::vector<CorpusEntry> plan = corpus_plan(60, 1);
  ASSERT_EQ(plan.size(), 60u);
  EXPECT_EQ(plan[13].name, "medium_straight_013");  // 13 mod 11 presets
  EXPECT_EQ(plan[5].preset, "short_cap");
  for (const CorpusEntry& entry : plan) {
    mixed += entry.spec.components.size() > 1 ? 1 : 0;
    SynthModel model = generate_model(entry.spec, body_m(), entry.seed, 2);
    auto counts = streams_by_style(model);
    for (size_t s = 0; s < 4; ++s) totals[s] += counts[s];
  }
  std::printf(
      "[ synth    ] corpus of 60: streams normal %d, fixed %d, short %d, braided %d; "
      "%d mixed models\n",
      totals[0], totals[1], totals[2], totals[3], mixed);
  for (int total : totals) EXPECT_GE(total, 15);
  EXPECT_GE(mixed, 10);
}

TEST(SynthPresets, ThePaintedCorpusCyclesEighteenPresetsAndDrawsTheArtistsFamilies) {
  // What `hair-synth corpus --painted --count 90` plans (the style classifiers' corpus).
  std::vector<CorpusEntry> plain = corpus_plan(90, 1), painted = corpus_plan(90, 1, true);
  ASSERT_EQ(painted.size(), 90u);
  EXPECT_EQ(painted[11].preset, "ring_cap");  // after the eleven presets
  EXPECT_EQ(painted[17].preset, "ringlets");
  EXPECT_EQ(painted[18].preset, "long_straight");
  // The bob is a painted preset but stays out of the corpus (in_training_corpus()).
  for (const CorpusEntry& entry : painted) EXPECT_NE(entry.preset, "bob");
  EXPECT_FALSE(in_training_corpus("bob"));
  EXPECT_TRUE(in_training_corpus("ringlets"));
  int swept_back = 0, waist_long = 0, braids = 0, caps = 0, loose = 0, gathered = 0;
  int lifted = 0, tapered = 0, woven = 0;
  for (size_t i = 0; i < painted.size(); ++i) {
    const CorpusEntry& entry = painted[i];
    HairStyleSpec varied = varied_spec(preset(entry.preset), entry.seed);
    for (size_t c = 0; c < entry.spec.components.size(); ++c) {
      const ComponentSpec& drawn = entry.spec.components[c];
      const ComponentSpec& base = varied.components[c];
      if (drawn.kind == ComponentSpec::Kind::short_cap) {
        ++caps;
        if (drawn.band_azimuth_deg != base.band_azimuth_deg) {
          ++swept_back;  // whorl at the top of the forehead
          EXPECT_LE(std::abs(drawn.band_azimuth_deg), 30.0);
          EXPECT_GE(drawn.band_polar_deg, 35.0);
          EXPECT_LE(drawn.band_polar_deg, 50.0);
        }
      }
      if (drawn.cap_drape) {
        ++loose;  // drawn back low and loose over the ears, with volume
        EXPECT_GE(drawn.band_polar_deg, 95.0);
        EXPECT_LE(drawn.band_polar_deg, 110.0);
        EXPECT_GE(drawn.cap_volume_m, 0.015);
        EXPECT_LE(drawn.cap_volume_m, 0.045);
        EXPECT_EQ(drawn.bun_radius_m, 0.0);
      }
      if ((drawn.kind == ComponentSpec::Kind::braid ||
           (drawn.kind == ComponentSpec::Kind::ponytail && drawn.bun_radius_m == 0)) &&
          drawn.polar_max_deg >= 100)
        ++gathered;
      if (drawn.kind == ComponentSpec::Kind::braid) {
        ++braids;
        // Lifted only where loose hair with volume gathers into it, by at most that volume.
        if (drawn.braid_lift_m > 0) {
          ++lifted;
          EXPECT_GT(drawn.cap_volume_m, 0);
          EXPECT_LE(drawn.braid_lift_m, drawn.cap_volume_m);
        }
        if (drawn.braid_tip_width_share < 1) {
          ++tapered;
          EXPECT_GE(drawn.braid_tip_width_share, 0.4);
          EXPECT_LE(drawn.braid_tip_width_share, 0.7);
        }
        if (drawn.braid_cards_per_lobe > 1) {
          ++woven;
          EXPECT_GE(drawn.braid_cards_per_lobe, 3);
          EXPECT_LE(drawn.braid_cards_per_lobe, 5);
          EXPECT_GE(entry.spec.defects.braid_piece_length_m, 0.05);
        }
        double ratio = drawn.length_max_m / base.length_max_m;
        if (ratio > 1.0) {
          ++waist_long;
          EXPECT_GE(ratio, 1.5 - 1e-12);
          EXPECT_LE(ratio, 2.0 + 1e-12);
        }
      }
    }
  }
  // Every other knob as varied_spec draws it: the plain corpus's models of the same index
  // and preset are the same but for the families.
  EXPECT_EQ(plain[5].preset, painted[5].preset);
  EXPECT_EQ(plain[5].spec.defects.gap_m, painted[5].spec.defects.gap_m);
  std::printf(
      "[ synth    ] painted corpus of 90: %d of %d short caps swept back, %d of %d braids "
      "waist-long, %d of %d tails and braids loose\n",
      swept_back, caps, waist_long, braids, loose, gathered);
  EXPECT_GE(swept_back, 1);
  EXPECT_LT(swept_back, caps);
  EXPECT_GE(waist_long, 1);
  EXPECT_LT(waist_long, braids);
  EXPECT_GE(loose, 1);
  EXPECT_LT(loose, gathered);
  std::printf("[ synth    ] of its %d braids: %d lifted, %d narrowing, %d woven from cards\n",
              braids, lifted, tapered, woven);
  for (int family : {lifted, tapered, woven}) {
    EXPECT_GE(family, 1);
    EXPECT_LT(family, braids);
  }
}

/// Hair lying on the head (short_cap): one grid per stream, short and root-free, lying
/// 2-5 mm off the scalp from near the crown down to the hairline, within its drawn
/// length; a layered cut (normal_pieces_max 2) gives a root and a tip piece, both short.
/// The largest angle, in degrees, between consecutive steps of `points`, `stride` points
/// apart, over the points from `first` on.
double largest_turn_deg(const std::vector<Eigen::Vector3d>& points, size_t stride, size_t first) {
  double largest = 0;
  for (size_t i = std::max(first, stride); i + stride < points.size(); ++i) {
    Eigen::Vector3d before = points[i] - points[i - stride], after = points[i + stride] - points[i];
    double cosine = std::clamp(before.normalized().dot(after.normalized()), -1.0, 1.0);
    largest = std::max(largest, std::acos(cosine) * 180 / std::numbers::pi);
  }
  return largest;
}

// A braid 3 cm wide bends over a shoulder with a radius of a few centimetres. two_braids'
// braids hang over the shoulders, where their axes used to be pushed off the body within
// a step or two: up to 79 degrees between 4 mm steps, and streams folding by up to 169
// degrees over 2 cm (docs/synth.md).
TEST(SynthBraid, AxesAndStreamsHaveNoCreaseOverTheShoulders) {
  for (uint32_t seed : {1u, 2u, 3u, 4u}) {
    SynthModel model = generate_model(varied_spec(preset("two_braids"), seed), body_m(), seed, 2);
    std::vector<int> braided;
    for (int s = 0; s < static_cast<int>(model.stream_style.size()); ++s)
      if (model.stream_style[static_cast<size_t>(s)] == HairStyle::braided) braided.push_back(s);
    ASSERT_EQ(braided.size(), 6u);
    for (size_t b = 0; b < braided.size(); b += 3) {
      // The three streams end on the same axis points: their mean is the axis there
      // (the offsets of the three phases sum to zero).
      Eigen::Index shortest = std::numeric_limits<Eigen::Index>::max();
      for (size_t k = 0; k < 3; ++k)
        shortest = std::min(shortest, model.stream_centres.strand(braided[b + k]).rows());
      auto tail = static_cast<size_t>(shortest / 2);
      std::vector<Eigen::Vector3d> axis(tail, Eigen::Vector3d::Zero());
      for (size_t k = 0; k < 3; ++k) {
        auto centre = model.stream_centres.strand(braided[b + k]);
        for (size_t i = 0; i < tail; ++i)
          axis[i] += centre.row(centre.rows() - static_cast<Eigen::Index>(tail - i))
                         .cast<double>()
                         .transpose() /
                     3.0;
        std::vector<Eigen::Vector3d> stream;
        for (Eigen::Index i = centre.rows() - static_cast<Eigen::Index>(tail); i < centre.rows();
             ++i)
          stream.push_back(centre.row(i).cast<double>().transpose());
        // Points 2 apart (about 1 cm): the weave itself turns by up to 78 degrees there on
        // braid and normal_braid, hanging down the back (seeds 1-6).
        EXPECT_LT(largest_turn_deg(stream, 2, 0), 85.0) << "seed " << seed << " stream " << k;
      }
      // Between 4 mm steps: a bend of 3 cm radius turns by 7.6 degrees.
      EXPECT_LT(largest_turn_deg(axis, 1, 0), 8.0) << "seed " << seed << " braid " << b / 3;
    }
  }
}

/// The point of `model`'s stream `s` centre at arc length `along_m` (clamped to its ends).
Eigen::Vector3d stream_point_at(const SynthModel& model, int64_t s, double along_m) {
  const StrandSet& centres = model.stream_centres;
  double walked = 0;
  for (int64_t p = centres.offsets[s] + 1; p < centres.offsets[s + 1]; ++p) {
    Eigen::Vector3d a = centres.points.row(p - 1).cast<double>().transpose(),
                    b = centres.points.row(p).cast<double>().transpose();
    double step = (b - a).norm();
    if (walked + step >= along_m && step > 0) return a + (b - a) * ((along_m - walked) / step);
    walked += step;
  }
  return centres.points.row(centres.offsets[s + 1] - 1).cast<double>().transpose();
}

/// A braid's streams and where each one's braid begins and ends along its centre (its
/// braided patches).
struct BraidPart {
  std::vector<int64_t> stream;
  std::vector<double> begin_m, end_m;
};
BraidPart braid_part(const SynthModel& model) {
  std::map<int64_t, std::pair<double, double>> range;
  for (const SynthPatch& patch : model.patches) {
    if (patch.style != HairStyle::braided) continue;
    auto [it, added] = range.try_emplace(patch.stream, patch.start_m, patch.end_m);
    if (!added)
      it->second = {std::min(it->second.first, patch.start_m),
                    std::max(it->second.second, patch.end_m)};
  }
  BraidPart part;
  for (const auto& [stream, span] : range) {
    part.stream.push_back(stream);
    part.begin_m.push_back(span.first);
    part.end_m.push_back(span.second);
  }
  return part;
}

/// The braid's width at `share` of the way down its braided part: the largest distance
/// between two of its streams' centres there.
double braid_width_at(const SynthModel& model, const BraidPart& part, double share) {
  std::vector<Eigen::Vector3d> points;
  for (size_t k = 0; k < part.stream.size(); ++k)
    points.push_back(stream_point_at(model, part.stream[k],
                                     part.begin_m[k] + share * (part.end_m[k] - part.begin_m[k])));
  double widest = 0;
  for (size_t a = 0; a < points.size(); ++a)
    for (size_t b = a + 1; b < points.size(); ++b)
      widest = std::max(widest, (points[a] - points[b]).norm());
  return widest;
}

// Braids as artists make them (braid01's, issue 26): the lobes woven from several of the
// cap's cards, the top standing off the head where loose hair gathers, the braid narrowing
// to its tie. Each against the preset's braid of the same seed.
TEST(SynthBraid, WovenFromCardsLiftedOffTheHeadAndNarrowingToTheTie) {
  Triangles3i triangles = fan_triangulation(body_m().face_offsets, body_m().face_vertices);
  TriangleMeshDistance body(body_m().vertices, triangles);
  const uint32_t seed = 3;
  HairStyleSpec plain = preset("braid"), woven = plain, lifted = plain, tapered = plain;
  woven.components[0].braid_cards_per_lobe = 4;
  lifted.components[0].braid_lift_m = 0.03;
  tapered.components[0].braid_tip_width_share = 0.5;
  const SynthModel plain_model = generate_model(plain, body_m(), seed, 2);
  const BraidPart plain_braid = braid_part(plain_model);
  ASSERT_EQ(plain_braid.stream.size(), 3u);

  // Woven: four cards a lobe, each its own stream from its own root; extract reads every
  // piece as one group, as on the preset (at least 65% root to tip, above).
  const SynthModel woven_model = generate_model(woven, body_m(), seed, 2);
  EXPECT_EQ(braid_part(woven_model).stream.size(), 12u);
  {
    ExtractResult result = extract_through_obj(woven_model, "hair_synth_woven");
    ASSERT_EQ(result.group_count(), static_cast<int32_t>(woven_model.patches.size()));
    std::vector<int32_t> group_patch = group_patches(woven_model, result);
    std::vector<GroupOrientation> orientation =
        group_orientations(woven_model, result, group_patch);
    int agreeing = 0;
    for (GroupOrientation verdict : orientation) agreeing += static_cast<int>(verdict) == 0;
    std::printf("[ synth    ] woven braid: %zu patches, %.3f root to tip\n",
                woven_model.patches.size(), static_cast<double>(agreeing) / result.group_count());
    EXPECT_GE(static_cast<double>(agreeing) / result.group_count(), 0.65);
  }

  // Lifted: the braid's top stands off the body by about the lift more than the preset's.
  auto top_off_body_m = [&](const SynthModel& model) {
    const BraidPart part = braid_part(model);
    double sum = 0;
    for (size_t k = 0; k < part.stream.size(); ++k)
      sum += body.distance(stream_point_at(model, part.stream[k], part.begin_m[k]));
    return sum / static_cast<double>(part.stream.size());
  };
  const double plain_top_m = top_off_body_m(plain_model);
  const double lifted_top_m = top_off_body_m(generate_model(lifted, body_m(), seed, 2));

  // Tapered: as wide as the preset's at the top, about half as wide near the tip.
  const SynthModel tapered_model = generate_model(tapered, body_m(), seed, 2);
  const BraidPart tapered_braid = braid_part(tapered_model);
  double top_ratio = 0, tip_ratio = 0;
  for (double share : {0.05, 0.1, 0.15})
    top_ratio += braid_width_at(tapered_model, tapered_braid, share) /
                 braid_width_at(plain_model, plain_braid, share) / 3;
  for (double share : {0.85, 0.9, 0.95})
    tip_ratio += braid_width_at(tapered_model, tapered_braid, share) /
                 braid_width_at(plain_model, plain_braid, share) / 3;
  std::printf(
      "[ synth    ] braid top %.3f m off the body, lifted 3 cm: %.3f m; tapered to 0.5: width "
      "%.2f of the preset's at the top, %.2f near the tip\n",
      plain_top_m, lifted_top_m, top_ratio, tip_ratio);
  EXPECT_GT(lifted_top_m - plain_top_m, 0.02);
  EXPECT_GT(top_ratio, 0.85);
  EXPECT_LT(tip_ratio, 0.7);
}

TEST(SynthShortCap, GridsLieOnTheScalpFromTheCrownDownToTheHairline) {
  Triangles3i triangles = fan_triangulation(body_m().face_offsets, body_m().face_vertices);
  TriangleMeshDistance body(body_m().vertices, triangles);
  HairStyleSpec spec = preset("short_cap");
  spec.defects.jitter_m = 0;
  SynthModel model = generate_model(spec, body_m(), 4);
  ASSERT_EQ(model.patches.size(), static_cast<size_t>(spec.components[0].stream_count));
  for (const SynthPatch& patch : model.patches) {
    EXPECT_EQ(patch.type, GroupType::root_free);
    EXPECT_EQ(patch.style, HairStyle::short_hair);
    EXPECT_EQ(patch.rails, spec.defects.cap_rails);
  }
  // Every vertex 3 mm (root) to 4.5 mm (tip) off the body: lying on the scalp.
  for (Eigen::Index v = 0; v < model.mesh.vertices.rows(); ++v) {
    double distance = body.distance(model.mesh.vertices.row(v).cast<double>().transpose());
    EXPECT_GT(distance, 0.002) << "vertex " << v;
    EXPECT_LT(distance, 0.005) << "vertex " << v;
  }
  // Streams run down from near the top of the head, no longer than drawn; none reaches
  // below the nape's hairline (115 degrees from the crown: about ear height).
  float top_y = body_m().vertices.col(1).maxCoeff();
  for (int64_t s = 0; s < model.stream_centres.strand_count(); ++s) {
    auto first = model.stream_centres.offsets[static_cast<size_t>(s)];
    auto last = model.stream_centres.offsets[static_cast<size_t>(s) + 1] - 1;
    Eigen::Vector3f root = model.stream_centres.points.row(first).transpose();
    Eigen::Vector3f tip = model.stream_centres.points.row(last).transpose();
    EXPECT_GT(root.y(), top_y - 0.04f) << "stream " << s;
    EXPECT_LT(tip.y(), root.y() - 0.02f) << "stream " << s;
    EXPECT_GT(tip.y(), top_y - 0.15f) << "stream " << s;
    float length = 0;
    for (auto i = first; i < last; ++i)
      length +=
          (model.stream_centres.points.row(i + 1) - model.stream_centres.points.row(i)).norm();
    EXPECT_LE(length, spec.components[0].length_max_m + 0.005) << "stream " << s;
    EXPECT_GT(length, 0.05) << "stream " << s;
  }

  spec.defects.normal_pieces_max = 2;
  SynthModel layered = generate_model(spec, body_m(), 4);
  int root_pieces = 0, tip_pieces = 0;
  for (const SynthPatch& patch : layered.patches) {
    EXPECT_EQ(patch.style, HairStyle::short_hair);
    root_pieces += patch.type == GroupType::root_connected ? 1 : 0;
    tip_pieces += patch.type == GroupType::tip ? 1 : 0;
  }
  EXPECT_GT(root_pieces, 0);
  EXPECT_EQ(root_pieces, tip_pieces);
}

TEST(SynthSpec, JsonRoundTripsEveryPresetAndRefusesBadKnobs) {
  std::vector<std::string> names = preset_names();
  names.insert(names.end(), painted_preset_names().begin(), painted_preset_names().end());
  for (const std::string& name : names) {
    HairStyleSpec spec = varied_spec(preset(name), 5);
    EXPECT_NO_THROW(check_spec(spec)) << name;
    EXPECT_EQ(spec_json(spec_from_json(spec_json(spec))), spec_json(spec)) << name;
  }
  nlohmann::json json = spec_json(preset("short"));
  json["defects"]["reversed_share"] = 2.0;
  EXPECT_THROW(spec_from_json(json), hair::Error);
  json = spec_json(preset("short"));
  json["defects"]["shorter_diagonal_share"] = -0.5;
  EXPECT_THROW(spec_from_json(json), hair::Error);
  json = spec_json(preset("short"));
  json["defects"]["rails"] = 3;
  EXPECT_THROW(spec_from_json(json), hair::Error);
  json = spec_json(preset("short"));
  json["components"][0]["kind"] = "mohawk";
  EXPECT_THROW(spec_from_json(json), hair::Error);
  json = spec_json(preset("short"));
  json["components"][0]["stream_count"] = "many";
  EXPECT_THROW(spec_from_json(json), hair::Error);
  // A tube needs three sides at least; a bun's radius and a ringlet's pitch their ranges.
  json = spec_json(preset("ringlets"));
  EXPECT_EQ(json["components"][1]["tube_sides"], 6);
  json["components"][1]["tube_sides"] = 2;
  EXPECT_THROW(spec_from_json(json), hair::Error);
  json = spec_json(preset("ringlets"));
  json["components"][1]["ringlet_pitch_m"] = 0.0;
  EXPECT_THROW(spec_from_json(json), hair::Error);
  json = spec_json(preset("bun"));
  json["components"][0]["bun_radius_m"] = -0.01;
  EXPECT_THROW(spec_from_json(json), hair::Error);
  // A shell open at the crown: its hole round-trips and stays within 90 degrees.
  json = spec_json(preset("swirl_shell"));
  EXPECT_EQ(json["components"][0]["grid_crown_hole_deg"], 12.0);
  json["components"][0]["grid_crown_hole_deg"] = 95.0;
  EXPECT_THROW(spec_from_json(json), hair::Error);
  json["components"][0]["grid_crown_hole_deg"] = -1.0;
  EXPECT_THROW(spec_from_json(json), hair::Error);
  // A loose cap: its volume round-trips and stays within 10 cm.
  json = spec_json(preset("low_tail"));
  EXPECT_EQ(json["components"][0]["cap_volume_m"], 0.0);
  json["components"][0]["cap_volume_m"] = 0.03;
  json["components"][0]["cap_drape"] = true;
  EXPECT_EQ(spec_from_json(json).components[0].cap_volume_m, 0.03);
  EXPECT_TRUE(spec_from_json(json).components[0].cap_drape);
  json["components"][0]["cap_volume_m"] = 0.2;
  EXPECT_THROW(spec_from_json(json), hair::Error);
  // A braid as artists make them: lift, taper and cards a lobe round-trip, within range.
  json = spec_json(preset("braid"));
  EXPECT_EQ(json["components"][0]["braid_cards_per_lobe"], 1);
  json["components"][0]["braid_lift_m"] = 0.02;
  json["components"][0]["braid_tip_width_share"] = 0.5;
  json["components"][0]["braid_cards_per_lobe"] = 4;
  EXPECT_EQ(spec_from_json(json).components[0].braid_lift_m, 0.02);
  EXPECT_EQ(spec_from_json(json).components[0].braid_tip_width_share, 0.5);
  EXPECT_EQ(spec_from_json(json).components[0].braid_cards_per_lobe, 4);
  for (const auto& [key, value] : std::vector<std::pair<std::string, double>>{
           {"braid_lift_m", -0.01}, {"braid_tip_width_share", 0.0}, {"braid_cards_per_lobe", 0}}) {
    json = spec_json(preset("braid"));
    json["components"][0][key] = value;
    EXPECT_THROW(spec_from_json(json), hair::Error) << key;
  }
  // A swirling cap painted without a fade: its swirl round-trips, its minimum no more than
  // its maximum, the fade a flag.
  json = spec_json(preset("swirl_cap"));
  EXPECT_EQ(json["components"][0]["swirl_min_deg"], 50.0);
  EXPECT_EQ(json["defects"]["painted_fade"], false);
  EXPECT_FALSE(spec_from_json(json).defects.painted_fade);
  EXPECT_EQ(spec_from_json(json).components[0].swirl_max_deg, 80.0);
  json["components"][0]["swirl_min_deg"] = 90.0;
  EXPECT_THROW(spec_from_json(json), hair::Error);
  json = spec_json(preset("swirl_cap"));
  json["components"][0]["swirl_max_deg"] = 200.0;
  EXPECT_THROW(spec_from_json(json), hair::Error);
  // A bob's volume round-trips and stays within 10 cm.
  json = spec_json(preset("bob"));
  EXPECT_EQ(json["components"][0]["hang_volume_m"], 0.012);
  json["components"][0]["hang_volume_m"] = 0.15;
  EXPECT_THROW(spec_from_json(json), hair::Error);
  // Its hair rooted under the cards round-trips, and only normal hair has it.
  json = spec_json(preset("bob"));
  EXPECT_EQ(json["components"][0]["rooted_under_volume"], true);
  EXPECT_TRUE(spec_from_json(json).components[1].rooted_under_volume);
  json = spec_json(preset("ring_cap"));
  json["components"][0]["rooted_under_volume"] = true;
  EXPECT_THROW(spec_from_json(json), hair::Error);
  // Tucked tips: a share, a length of at least 2 mm, a depth of at most 5 cm.
  json = spec_json(preset("short_cap"));
  EXPECT_EQ(json["defects"]["tucked_share"], 0.0);
  json["defects"]["tucked_share"] = 0.5;
  EXPECT_EQ(spec_from_json(json).defects.tucked_share, 0.5);
  for (const auto& [key, value] : std::vector<std::pair<std::string, double>>{
           {"tucked_share", 1.5}, {"tuck_length_m", 0.0}, {"tuck_depth_m", 0.2}}) {
    json = spec_json(preset("short_cap"));
    json["defects"][key] = value;
    EXPECT_THROW(spec_from_json(json), hair::Error) << key;
  }
}

TEST(SynthPresets, TheBunCoilsRoundItsBandAndTheRingletsWindRoundTheirAxis) {
  PolyMesh body = read_mesh(std::filesystem::path(HAIR_SOURCE_DIR) / "data/samples/body.obj");
  body.vertices *= 0.1f;
  // The bun: every stream is fixed hair, and its last 5 cm stay within 4.5 cm of the
  // centre of its stream ends (a coil of 3 cm radius, rising 1 cm a turn), where a tail
  // would hang 5 cm down.
  SynthModel bun = generate_model(preset("bun"), body, 1);
  ASSERT_GT(bun.stream_centres.strand_count(), 10);
  Eigen::Vector3f centre = Eigen::Vector3f::Zero();
  for (int64_t s = 0; s < bun.stream_centres.strand_count(); ++s)
    centre += bun.stream_centres.points.row(bun.stream_centres.offsets[s + 1] - 1).transpose();
  centre /= static_cast<float>(bun.stream_centres.strand_count());
  for (int64_t s = 0; s < bun.stream_centres.strand_count(); ++s) {
    EXPECT_EQ(bun.stream_style[static_cast<size_t>(s)], HairStyle::fixed);
    const int64_t last = bun.stream_centres.offsets[s + 1] - 1;
    float along = 0;
    for (int64_t row = last; row > bun.stream_centres.offsets[s] && along < 0.05f; --row) {
      EXPECT_LT((bun.stream_centres.points.row(row).transpose() - centre).norm(), 0.045f);
      along += (bun.stream_centres.points.row(row) - bun.stream_centres.points.row(row - 1)).norm();
    }
  }
  // The ringlets: tubes of 6 sides (closed: every vertex in 3 or 4 quads of its tube), and
  // each ringlet's centre turns round its hanging axis: its horizontal direction from its
  // running mean over a pitch sweeps all round.
  SynthModel ringlets = generate_model(preset("ringlets"), body, 1);
  int tubes = 0;
  for (const SynthPatch& patch : ringlets.patches) {
    if (patch.rails != 6 || patch.style != HairStyle::normal) continue;
    ++tubes;
    std::vector<int> faces_at(static_cast<size_t>(patch.vertex_count), 0);
    for (int64_t f = patch.first_face; f < patch.first_face + patch.face_count; ++f)
      for (int32_t v : ringlets.mesh.face(f))
        ++faces_at[static_cast<size_t>(v - patch.first_vertex)];
    for (int count : faces_at) EXPECT_GE(count, 2);  // no open edge round the tube
  }
  EXPECT_GE(tubes, 15);
  int winding = 0;
  for (size_t s = 0; s < ringlets.stream_style.size(); ++s) {
    if (ringlets.stream_component[s] != 1) continue;
    const auto first = ringlets.stream_centres.offsets[s],
               end = ringlets.stream_centres.offsets[s + 1];
    double turned = 0;
    Eigen::Vector2d previous = Eigen::Vector2d::Zero();
    for (int64_t row = first + 12; row + 4 < end; row += 2) {  // past the 3 cm fade-in
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      int n = 0;
      for (int64_t k = std::max(first, row - 4); k <= row + 4; ++k, ++n)
        mean += ringlets.stream_centres.points.row(k).cast<double>().transpose();
      const Eigen::Vector3d off =
          ringlets.stream_centres.points.row(row).cast<double>().transpose() - mean / n;
      const Eigen::Vector2d flat(off.x(), off.z());
      if (flat.norm() < 1e-4) continue;
      if (previous.norm() > 0)
        turned += std::abs(
            std::atan2(previous.x() * flat.y() - previous.y() * flat.x(), previous.dot(flat)));
      previous = flat;
    }
    if (turned > 2 * M_PI) ++winding;
  }
  EXPECT_GE(winding, 15);
}

/// Measures of the cap (the fixed points) of a tail's true strands: the farthest any cap
/// point lies from the body, and the share of the strands rooted on the front half of the
/// head whose cap passes over the side of the head at ear level (|x| at least 0.8 head
/// half-widths, below the roots) before it reaches the band at the nape.
struct CapMeasures {
  double farthest_off_body_m = 0;
  double front_over_the_ears = 0;
};

CapMeasures measure_cap(const SynthModel& model, const TriangleMeshDistance& body,
                        double head_half_width_m, double head_centre_z_m) {
  CapMeasures measures;
  int front = 0, over_ears = 0;
  for (int64_t s = 0; s < model.strands.strand_count(); ++s) {
    const int64_t first = model.strands.offsets[s], end = model.strands.offsets[s + 1];
    const Eigen::Vector3f root = model.strands.points.row(first).transpose();
    bool passes_ear = false;
    for (int64_t p = first; p < end; ++p) {
      if (model.strand_point_style[static_cast<size_t>(p)] != HairStyle::fixed) break;
      const Eigen::Vector3d point = model.strands.points.row(p).cast<double>().transpose();
      measures.farthest_off_body_m = std::max(measures.farthest_off_body_m, body.distance(point));
      passes_ear |= std::abs(point.x()) >= 0.8 * head_half_width_m && point.y() < root.y() - 0.03;
    }
    if (root.z() > head_centre_z_m) {
      ++front;
      over_ears += passes_ear;
    }
  }
  measures.front_over_the_ears = front > 0 ? static_cast<double>(over_ears) / front : 0;
  return measures;
}

TEST(SynthPresets, ALooseLowTailsCapStandsOffTheHeadAndFallsOverTheEars) {
  // The low tail as the preset draws it: a cap close over the head (at most 2.5 cm off the
  // body where its grids gather into the band), straight back from the roots to the band.
  // Loose (cap_volume_m 3 cm, cap_drape): the cap stands well off the head and the hair
  // from the front falls over the ears before it sweeps back to the nape, as braid01's.
  Triangles3i triangles = fan_triangulation(body_m().face_offsets, body_m().face_vertices);
  TriangleMeshDistance body(body_m().vertices, triangles);
  Eigen::Vector3f low = Eigen::Vector3f::Constant(1e9f), high = -low;
  for (Eigen::Index v = 0; v < body_m().vertices.rows(); ++v) {
    if (body_m().vertices(v, 1) < body_m().vertices.col(1).maxCoeff() - 0.12f) continue;
    low = low.cwiseMin(body_m().vertices.row(v).transpose());
    high = high.cwiseMax(body_m().vertices.row(v).transpose());
  }
  const double half_width_m = 0.5 * (high.x() - low.x()), centre_z_m = 0.5 * (low.z() + high.z());
  HairStyleSpec close = preset("low_tail"), loose = close;
  loose.components[0].cap_volume_m = 0.03;
  loose.components[0].cap_drape = true;
  const CapMeasures close_cap =
      measure_cap(generate_model(close, body_m(), 3), body, half_width_m, centre_z_m);
  const CapMeasures loose_cap =
      measure_cap(generate_model(loose, body_m(), 3), body, half_width_m, centre_z_m);
  std::printf(
      "[ synth    ] low tail's cap: farthest %.3f m off the body close, %.3f m loose; front "
      "strands over the ears %.2f close, %.2f loose\n",
      close_cap.farthest_off_body_m, loose_cap.farthest_off_body_m, close_cap.front_over_the_ears,
      loose_cap.front_over_the_ears);
  EXPECT_LT(close_cap.farthest_off_body_m, 0.025);
  EXPECT_GT(loose_cap.farthest_off_body_m, 0.035);
  EXPECT_LT(loose_cap.farthest_off_body_m, 0.06);
  EXPECT_LT(close_cap.front_over_the_ears, 0.2);
  EXPECT_GT(loose_cap.front_over_the_ears, 0.8);
}

/// Per stream of `model`, the body distance of its centre at `share` of its arc length;
/// the median over the streams.
double median_stream_distance(const SynthModel& model, const TriangleMeshDistance& body,
                              double share) {
  std::vector<double> distances;
  const StrandSet& centres = model.stream_centres;
  for (int64_t s = 0; s < centres.strand_count(); ++s) {
    const int64_t first = centres.offsets[s], end = centres.offsets[s + 1];
    std::vector<double> along{0.0};
    for (int64_t p = first + 1; p < end; ++p)
      along.push_back(along.back() +
                      (centres.points.row(p) - centres.points.row(p - 1)).cast<double>().norm());
    const double target = share * along.back();
    int64_t p = first;
    while (p + 1 < end && along[static_cast<size_t>(p + 1 - first)] < target) ++p;
    distances.push_back(body.distance(centres.points.row(p).cast<double>().transpose()));
  }
  std::nth_element(distances.begin(), distances.begin() + distances.size() / 2, distances.end());
  return distances[distances.size() / 2];
}

TEST(SynthPresets, ABobsCardsStandOffTheHeadBelowTheCrownAndTurnInAtTheTips) {
  // bob01's and bob02's rails lie 1-1.5 cm farther off the body from the middle of their
  // length on than cards hugging the head; the bob preset lifts its cards by up to
  // hang_volume_m = 1.2 cm (nothing at the root, back in at the tips).
  Triangles3i triangles = fan_triangulation(body_m().face_offsets, body_m().face_vertices);
  TriangleMeshDistance body(body_m().vertices, triangles);
  HairStyleSpec bob = preset("bob"), hugging = bob;
  EXPECT_DOUBLE_EQ(bob.components[0].hang_volume_m, 0.012);
  for (ComponentSpec& component : hugging.components) component.hang_volume_m = 0;
  const SynthModel standing = generate_model(bob, body_m(), 1);
  const SynthModel flat = generate_model(hugging, body_m(), 1);
  const double root_lift_m =
      median_stream_distance(standing, body, 0.0) - median_stream_distance(flat, body, 0.0);
  const double middle_lift_m =
      median_stream_distance(standing, body, 0.5) - median_stream_distance(flat, body, 0.5);
  const double tip_lift_m =
      median_stream_distance(standing, body, 1.0) - median_stream_distance(flat, body, 1.0);
  std::printf("[ synth    ] bob: lifted %.4f m at the root, %.4f m halfway, %.4f m at the tip\n",
              root_lift_m, middle_lift_m, tip_lift_m);
  EXPECT_NEAR(root_lift_m, 0.0, 1e-6);
  EXPECT_GT(middle_lift_m, 0.008);
  EXPECT_LT(middle_lift_m, 0.0125);
  EXPECT_LT(tip_lift_m, 0.5 * middle_lift_m);
}

TEST(SynthPresets, ABobsTruthIsRootedAllOverTheScalpUnderItsCards) {
  // A voluminous cut's outer cards stand off the head and the scalp under them carries
  // hair (bob01's and bob02's shells, 2-4 cm off): the bob's truth gains strands rooted
  // there that rise to the cards and run on along them; its mesh stays as it was.
  Triangles3i triangles = fan_triangulation(body_m().face_offsets, body_m().face_vertices);
  TriangleMeshDistance body(body_m().vertices, triangles);
  HairStyleSpec bob = preset("bob"), crown_only = bob;
  for (ComponentSpec& component : crown_only.components) component.rooted_under_volume = false;
  const SynthModel model = generate_model(bob, body_m(), 1);
  const SynthModel cards = generate_model(crown_only, body_m(), 1);
  EXPECT_EQ(model.mesh.vertices, cards.mesh.vertices);
  EXPECT_EQ(model.mesh.face_vertices, cards.mesh.face_vertices);
  EXPECT_EQ(model.stream_centres.points, cards.stream_centres.points);
  const StrandSet& truth = model.strands;
  const int64_t on_cards = cards.strands.strand_count();
  ASSERT_GT(truth.strand_count(), on_cards);
  // The card-rooted strands first, as they were.
  EXPECT_EQ(truth.points.topRows(cards.strands.point_count()), cards.strands.points);
  // The card roots lie round the crown; the new roots on the scalp below it, down the sides
  // and the back, each on the scalp, and every strand ends on its stream's card.
  const Eigen::Vector3d top = cards.strands.points.colwise().maxCoeff().cast<double>().transpose();
  const double lift_m = bob.defects.scalp_lift_m;
  const auto& stream = std::get<std::vector<int32_t>>(truth.strand_attributes.at("stream"));
  int64_t low_roots = 0, steep_first_steps = 0;
  double highest_card_root_drop_m = 0;
  for (int64_t s = 0; s < on_cards; ++s)
    highest_card_root_drop_m =
        std::max(highest_card_root_drop_m, top.y() - truth.points(truth.offsets[s], 1));
  for (int64_t s = on_cards; s < truth.strand_count(); ++s) {
    const Eigen::Vector3d root = truth.points.row(truth.offsets[s]).cast<double>().transpose();
    EXPECT_NEAR(body.distance(root), lift_m, 0.002) << "root of strand " << s;
    if (top.y() - root.y() > highest_card_root_drop_m) ++low_roots;
    const Eigen::Vector3d second =
        truth.points.row(truth.offsets[s] + 1).cast<double>().transpose();
    // The first step leaves the scalp along the card: it rises by less than 45 degrees.
    const Eigen::Vector3d step = second - root;
    const double rise_m = body.distance(second) - body.distance(root);
    if (rise_m > std::sqrt(0.5) * step.norm()) ++steep_first_steps;
    // Its tip on its stream's centre curve, within the card's half width.
    const Eigen::Vector3d tip =
        truth.points.row(truth.offsets[s + 1] - 1).cast<double>().transpose();
    const StrandSet& centres = model.stream_centres;
    const int32_t id = stream[static_cast<size_t>(s)];
    double nearest_m = std::numeric_limits<double>::infinity();
    for (int64_t row = centres.offsets[id]; row < centres.offsets[id + 1]; ++row)
      nearest_m =
          std::min(nearest_m, (centres.points.row(row).cast<double>().transpose() - tip).norm());
    EXPECT_LT(nearest_m, 0.5 * 0.06 * 1.2 + 0.004) << "tip of strand " << s;
  }
  const int64_t under = truth.strand_count() - on_cards;
  std::printf(
      "[ synth    ] bob: %lld strands on the cards, %lld rooted under them (%lld below "
      "every card root), %lld leaving the scalp steeper than 45 degrees\n",
      static_cast<long long>(on_cards), static_cast<long long>(under),
      static_cast<long long>(low_roots), static_cast<long long>(steep_first_steps));
  EXPECT_GT(under, on_cards / 4);
  EXPECT_GT(low_roots, under / 2);
  EXPECT_LT(steep_first_steps, under / 20);
}

}  // namespace
}  // namespace hair::synth
