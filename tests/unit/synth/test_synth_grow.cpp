// The grow stage (paper section 4.4) measured against the true strands of synthetic
// hairstyles (issue 5): extract -> typeify -> cluster-middle -> cluster-all -> grow, in
// memory, on every preset with its knobs varied by seeds 1-3, then the distances between
// the grown strands and the true ones in head heights H, printed as a table.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "hair/cluster/hair_clustering.h"
#include "hair/cluster/typeify.h"
#include "hair/extract/extract.h"
#include "hair/extract/scalp.h"
#include "hair/geom/point_index.h"
#include "hair/grow/card_surfaces.h"
#include "hair/grow/strand_growing.h"
#include "hair/grow/strand_sense.h"
#include "hair/mesh/mesh_io.h"
#include "hair/synth/synth_eval.h"
#include "hair/synth/synth_model.h"
#include "unit/clustered_in_memory.h"
#include "unit/mean_column.h"

namespace hair::synth {
namespace {

using hair::testing::kNotMeasured;
constexpr int kStrandCount = 2000;  ///< grown strands per model (the stage grows 10k)
/// True strands per stream (the generator's default). Fidelity is measured to the nearest
/// true strand, so it includes half the spacing of the true strands across a strip: with
/// 8 per stream the mean over presets reads 0.016 H instead of 0.011 H.
constexpr int kTrueStrandsPerStream = 24;
/// Coverage is measured from every third true strand (8 per stream): enough to find the
/// hair that no grown strand reaches, at a third of the cost.
constexpr int kCoverageStrandStride = 3;
constexpr double kFarH = 0.1;  ///< a grown point this far from every true strand left the hair
/// A grown strand rooted under a braid goes through it when its lowest point comes this
/// close to the height of the braid's tip.
constexpr double kBraidTipReachH = 0.05;

/// Distance from a point to the nearest segment of a strand set, over the segments next to
/// the few nearest points (the points are a few mm apart along a strand).
class SegmentDistance {
 public:
  explicit SegmentDistance(const StrandSet& strands) : strands_(strands), index_(strands.points) {
    strand_of_.resize(static_cast<size_t>(strands.point_count()));
    for (int64_t s = 0; s < strands.strand_count(); ++s)
      for (int64_t row = strands.offsets[s]; row < strands.offsets[s + 1]; ++row)
        strand_of_[static_cast<size_t>(row)] = s;
  }

  double operator()(const Eigen::Vector3f& query) const {
    Eigen::Vector3d q = query.cast<double>();
    double best = std::numeric_limits<double>::infinity();
    for (int32_t p : index_.nearest(query, 4)) {
      int64_t s = strand_of_[static_cast<size_t>(p)];
      best = std::min(best, (point(p) - q).norm());
      if (p > strands_.offsets[s]) best = std::min(best, to_segment(q, point(p - 1), point(p)));
      if (p + 1 < strands_.offsets[s + 1])
        best = std::min(best, to_segment(q, point(p), point(p + 1)));
    }
    return best;
  }

 private:
  Eigen::Vector3d point(int64_t row) const {
    return strands_.points.row(row).cast<double>().transpose();
  }
  static double to_segment(const Eigen::Vector3d& q, const Eigen::Vector3d& a,
                           const Eigen::Vector3d& b) {
    Eigen::Vector3d ab = b - a;
    double length2 = ab.squaredNorm();
    double t = length2 > 0 ? std::clamp((q - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
    return (a + t * ab - q).norm();
  }

  const StrandSet& strands_;
  PointIndex index_;
  std::vector<int64_t> strand_of_;
};

double mean_of(const std::vector<double>& values) {
  if (values.empty()) return kNotMeasured;
  double sum = 0;
  for (double value : values) sum += value;
  return sum / static_cast<double>(values.size());
}

/// The value at `share` of the sorted values (nearest rank); NaN when there are none.
double quantile(std::vector<double> values, double share) {
  if (values.empty()) return kNotMeasured;
  auto rank = static_cast<size_t>(share * static_cast<double>(values.size() - 1) + 0.5);
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(rank),
                   values.end());
  return values[rank];
}

double share_of(int64_t count, size_t total) {
  return total ? static_cast<double>(count) / static_cast<double>(total) : kNotMeasured;
}

double strand_length(const StrandSet& strands, int64_t s) {
  double length = 0;
  for (int64_t row = strands.offsets[s] + 1; row < strands.offsets[s + 1]; ++row)
    length += (strands.points.row(row) - strands.points.row(row - 1)).cast<double>().norm();
  return length;
}

/// What one model measured; distances in H.
struct GrowScores {
  double fidelity_mean = kNotMeasured, fidelity_p95 = kNotMeasured;
  double coverage_mean = kNotMeasured, coverage_p95 = kNotMeasured;
  double far_share = kNotMeasured;     ///< grown points over kFarH from every true strand
  double length_ratio = kNotMeasured;  ///< median of grown length / nearest true length
  double short_share = kNotMeasured;   ///< grown strands under half that true length
  double braid_reach = kNotMeasured;   ///< braid-rooted grown strands reaching its tip
  /// Grown segments within 30 degrees of the axis of the nearest true segment.
  double along_truth = kNotMeasured;
  /// Of those, the share that run the true way (root to tip, as the true segment): hair
  /// grown along the right lines but the wrong way (from the tips towards the roots) shows
  /// here only.
  double true_way = kNotMeasured;
  /// The coverage mean of the component (layer) whose true strands lie farthest from the
  /// grown ones: a lost layer shows here.
  double worst_layer_coverage = kNotMeasured;
  int64_t strand_count = 0;
  bool finite = true;
};

/// Measures `grown` against the model's true strands.
GrowScores measure(const SynthModel& model, const StrandSet& grown, double h) {
  const StrandSet& truth = model.strands;
  GrowScores scores;
  scores.strand_count = grown.strand_count();
  scores.finite = grown.points.allFinite();

  // (a) Fidelity: from every grown point but the roots to the nearest true segment.
  SegmentDistance to_truth(truth);
  std::vector<double> to_truth_h(static_cast<size_t>(grown.point_count()));
#pragma omp parallel for schedule(static)
  for (int64_t row = 0; row < grown.point_count(); ++row)
    to_truth_h[static_cast<size_t>(row)] = to_truth(grown.points.row(row).transpose()) / h;
  std::vector<double> fidelity;
  int64_t far = 0;
  for (int64_t s = 0; s < grown.strand_count(); ++s)
    for (int64_t row = grown.offsets[s] + 1; row < grown.offsets[s + 1]; ++row) {
      fidelity.push_back(to_truth_h[static_cast<size_t>(row)]);
      if (fidelity.back() > kFarH) ++far;
    }
  scores.fidelity_mean = mean_of(fidelity);
  scores.fidelity_p95 = quantile(fidelity, 0.95);
  scores.far_share = share_of(far, fidelity.size());

  // (b) Coverage: from the points of the true strands to the nearest grown segment.
  std::vector<int64_t> true_rows;
  for (int64_t s = 0; s < truth.strand_count(); s += kCoverageStrandStride)
    for (int64_t row = truth.offsets[s]; row < truth.offsets[s + 1]; ++row)
      true_rows.push_back(row);
  SegmentDistance to_grown(grown);
  std::vector<double> coverage(true_rows.size());
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < true_rows.size(); ++i)
    coverage[i] = to_grown(truth.points.row(true_rows[i]).transpose()) / h;
  scores.coverage_mean = mean_of(coverage);
  scores.coverage_p95 = quantile(coverage, 0.95);
  {
    const auto& true_stream = std::get<std::vector<int32_t>>(truth.strand_attributes.at("stream"));
    std::vector<int64_t> strand_of_row(static_cast<size_t>(truth.point_count()));
    for (int64_t s = 0; s < truth.strand_count(); ++s)
      for (int64_t row = truth.offsets[s]; row < truth.offsets[s + 1]; ++row)
        strand_of_row[static_cast<size_t>(row)] = s;
    std::map<int32_t, std::pair<double, int64_t>> by_layer;
    for (size_t i = 0; i < true_rows.size(); ++i) {
      const int32_t stream_id =
          true_stream[static_cast<size_t>(strand_of_row[static_cast<size_t>(true_rows[i])])];
      auto& [sum, count] = by_layer[model.stream_component[static_cast<size_t>(stream_id)]];
      sum += coverage[i];
      ++count;
    }
    scores.worst_layer_coverage = 0;
    for (const auto& [layer, sum_count] : by_layer)
      scores.worst_layer_coverage = std::max(
          scores.worst_layer_coverage, sum_count.first / static_cast<double>(sum_count.second));
  }

  // (c) Length, against the true strand whose root is nearest the grown root.
  Points3f true_roots(truth.strand_count(), 3);
  std::vector<double> true_length(static_cast<size_t>(truth.strand_count()));
  for (int64_t s = 0; s < truth.strand_count(); ++s) {
    true_roots.row(s) = truth.points.row(truth.offsets[s]);
    true_length[static_cast<size_t>(s)] = strand_length(truth, s);
  }
  PointIndex true_root_index(true_roots);

  // (d) Each braid's tip height: the mean of the lowest points of its true strands.
  const auto& stream = std::get<std::vector<int32_t>>(truth.strand_attributes.at("stream"));
  auto component_of = [&](int64_t true_strand) {
    return model.stream_component[static_cast<size_t>(stream[static_cast<size_t>(true_strand)])];
  };
  std::map<int32_t, double> braid_tip_y;
  std::map<int32_t, int> braid_true_strands;
  for (int64_t s = 0; s < truth.strand_count(); ++s) {
    int32_t component = component_of(s);
    if (model.spec.components[static_cast<size_t>(component)].kind != ComponentSpec::Kind::braid)
      continue;
    braid_tip_y[component] += truth.strand(s).col(1).minCoeff();
    ++braid_true_strands[component];
  }
  for (auto& [component, y] : braid_tip_y) y /= braid_true_strands[component];

  std::vector<double> ratios;
  int64_t short_strands = 0, braid_strands = 0, braid_reached = 0;
  for (int64_t s = 0; s < grown.strand_count(); ++s) {
    int32_t nearest =
        true_root_index.nearest(grown.points.row(grown.offsets[s]).transpose(), 1).front();
    ratios.push_back(strand_length(grown, s) / true_length[static_cast<size_t>(nearest)]);
    if (ratios.back() < 0.5) ++short_strands;
    auto tip = braid_tip_y.find(component_of(nearest));
    if (tip == braid_tip_y.end()) continue;
    ++braid_strands;
    if (grown.strand(s).col(1).minCoeff() <= tip->second + kBraidTipReachH * h) ++braid_reached;
  }
  // (e) The flow: each grown segment against the true segment nearest its midpoint.
  std::vector<Eigen::Vector3f> true_direction;
  Points3f true_midpoint(truth.point_count(), 3);
  Eigen::Index true_segments = 0;
  for (int64_t s = 0; s < truth.strand_count(); ++s)
    for (int64_t row = truth.offsets[s] + 1; row < truth.offsets[s + 1]; ++row) {
      Eigen::Vector3f segment = truth.points.row(row) - truth.points.row(row - 1);
      if (!(segment.norm() > 0)) continue;
      true_direction.push_back(segment.normalized());
      true_midpoint.row(true_segments++) =
          0.5f * (truth.points.row(row) + truth.points.row(row - 1));
    }
  true_midpoint.conservativeResize(true_segments, 3);
  PointIndex true_segment_index(true_midpoint);
  int64_t grown_segments = 0, along = 0, true_way = 0;
  for (int64_t s = 0; s < grown.strand_count(); ++s)
    for (int64_t row = grown.offsets[s] + 1; row < grown.offsets[s + 1]; ++row) {
      Eigen::Vector3f segment = grown.points.row(row) - grown.points.row(row - 1);
      if (!(segment.norm() > 0)) continue;
      Eigen::Vector3f midpoint =
          0.5f * (grown.points.row(row) + grown.points.row(row - 1)).transpose();
      const int32_t nearest = true_segment_index.nearest(midpoint, 1).front();
      ++grown_segments;
      const double cosine = segment.normalized().dot(true_direction[static_cast<size_t>(nearest)]);
      if (std::abs(cosine) >= std::cos(30 * M_PI / 180)) {
        ++along;
        true_way += cosine > 0 ? 1 : 0;
      }
    }
  scores.along_truth = share_of(along, static_cast<size_t>(grown_segments));
  scores.true_way = share_of(true_way, static_cast<size_t>(along));

  scores.length_ratio = quantile(ratios, 0.5);
  scores.short_share = share_of(short_strands, ratios.size());
  scores.braid_reach = share_of(braid_reached, static_cast<size_t>(braid_strands));
  return scores;
}

/// Grown strands and the head height H they were grown with.
struct Grown {
  GrowResult result;
  double head_height_m = 0;
  Points3f hair_vertices, body_vertices;  ///< the meshes it was grown in, metres
  Triangles3i hair_triangles, body_triangles;
};

/// Extract, typeify, both clusterings and grow, in memory, as the stages chain them.
Grown grow_model(const SynthModel& model, const PolyMesh& body, const std::string& name,
                 bool join_continued_flow = GrowParams{}.join_continued_flow,
                 const ExtractParams& extract_params = ExtractParams{},
                 double field_air_stop_h = GrowParams{}.field_air_stop_h) {
  hair::testing::ClusteredInMemory run =
      hair::testing::cluster_in_memory(model.mesh, body, name, extract_params);
  ExtractResult& extract = run.extract;
  const double h = run.head_height_m;
  const GroupTypes& found = run.types;
  const HairClustering& clusters = run.clusters;
  GrowInput input;
  input.input_strands = std::move(extract.strands);
  input.group_type = found.type;
  input.group_cluster = clusters.cluster;
  input.cluster_starts_at_root = clusters.cluster_starts_at_root;
  input.body_vertices = std::move(extract.body_vertices);
  input.body_triangles = std::move(extract.body_triangles);
  input.scalp_triangle = std::move(extract.scalp_triangle);
  input.hair_vertices = extract.hair_mesh.vertices;
  fan_triangulation_with_groups(extract.hair_mesh.face_offsets, extract.hair_mesh.face_vertices,
                                extract.face_group, input.hair_triangles,
                                input.hair_triangle_group);
  const PaintedFlow& paint = extract.painted_flow;
  Points3f face_flow = Points3f::Zero(static_cast<Eigen::Index>(paint.direction.size()), 3);
  for (size_t f = 0; f < paint.direction.size(); ++f)
    face_flow.row(static_cast<Eigen::Index>(f)) = paint.direction[f].transpose();
  input.hair_triangle_flow = fan_painted_flow(extract.hair_mesh.face_offsets, face_flow,
                                              paint.coherence, kClearFlowCoherence);
  input.head_height_m = h;
  input.source = name;
  GrowParams params;
  params.strand_count = kStrandCount;
  params.join_continued_flow = join_continued_flow;
  params.field_air_stop_h = field_air_stop_h;
  return {grow_strands(input, params), h, input.hair_vertices, input.body_vertices,
          input.hair_triangles, input.body_triangles};
}

using Column = hair::testing::MeanColumn;

/// One line of the table: the mean of its models (or of its presets' lines).
struct Row {
  Column fidelity_mean, fidelity_p95, coverage_mean, coverage_p95, far_share, length_ratio,
      short_share, braid_reach, along_truth, true_way, worst_layer_coverage;
  double seconds = 0;
  void add(const GrowScores& scores) {
    fidelity_mean.add(scores.fidelity_mean);
    fidelity_p95.add(scores.fidelity_p95);
    coverage_mean.add(scores.coverage_mean);
    coverage_p95.add(scores.coverage_p95);
    far_share.add(scores.far_share);
    length_ratio.add(scores.length_ratio);
    short_share.add(scores.short_share);
    braid_reach.add(scores.braid_reach);
    along_truth.add(scores.along_truth);
    true_way.add(scores.true_way);
    worst_layer_coverage.add(scores.worst_layer_coverage);
  }
  void add(const Row& row) {
    fidelity_mean.add(row.fidelity_mean.mean());
    fidelity_p95.add(row.fidelity_p95.mean());
    coverage_mean.add(row.coverage_mean.mean());
    coverage_p95.add(row.coverage_p95.mean());
    far_share.add(row.far_share.mean());
    length_ratio.add(row.length_ratio.mean());
    short_share.add(row.short_share.mean());
    braid_reach.add(row.braid_reach.mean());
    along_truth.add(row.along_truth.mean());
    true_way.add(row.true_way.mean());
    worst_layer_coverage.add(row.worst_layer_coverage.mean());
    seconds += row.seconds;
  }
  void print(const std::string& label) const {
    std::printf(
        "[ synth    ] %-15s | %6.4f %6.4f | %6.4f %6.4f | %6.4f | %6.3f %6.3f | %6.3f | %6.3f | "
        "%6.3f | %6.4f | %5.1f\n",
        label.c_str(), fidelity_mean.mean(), fidelity_p95.mean(), coverage_mean.mean(),
        coverage_p95.mean(), far_share.mean(), length_ratio.mean(), short_share.mean(),
        braid_reach.mean(), along_truth.mean(), true_way.mean(), worst_layer_coverage.mean(),
        seconds);
  }
};

TEST(SynthGrow, DistanceToTrueStrandsPerPreset) {
  PolyMesh body = read_mesh(std::filesystem::path(HAIR_SOURCE_DIR) / "data/samples/body.obj");
  body.vertices *= 0.1f;
  std::printf(
      "[ synth    ] %-15s | fidelity (H)  | coverage (H)  | >0.1 H | length ratio  | braid  |"
      " along  | true   | worst  | time\n",
      "");
  std::printf(
      "[ synth    ] %-15s |   mean    p95 |   mean    p95 | share  | median   <0.5 | reach  |"
      " truth  | way    | layer  |  (s)\n",
      "preset");
  std::map<std::string, Row> rows;
  Row presets, braided;
  for (const std::string& name : preset_names()) {
    Row& row = rows[name];
    for (uint32_t seed : {1u, 2u, 3u}) {
      SCOPED_TRACE(name + ", seed " + std::to_string(seed));
      auto start = std::chrono::steady_clock::now();
      SynthModel model =
          generate_model(varied_spec(preset(name), seed), body, seed, kTrueStrandsPerStream);
      Grown grown = grow_model(model, body, name);
      GrowScores scores = measure(model, grown.result.strands, grown.head_height_m);
      row.seconds +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      row.add(scores);
      EXPECT_EQ(scores.strand_count, kStrandCount);
      EXPECT_TRUE(scores.finite);
      EXPECT_FALSE(std::isnan(scores.fidelity_mean) || std::isnan(scores.fidelity_p95));
      EXPECT_FALSE(std::isnan(scores.coverage_mean) || std::isnan(scores.coverage_p95));
      EXPECT_FALSE(std::isnan(scores.length_ratio));
      // The true strands never fold back on themselves, nor do the grown strands
      // (GrowParams::max_turn_deg): not where a braid's crossing pieces, read in opposite
      // senses, meet, nor where a strand bridges from card to card (a point pushed back
      // out of the body can still make a rare one).
      int64_t hairpins = 0;
      for (int64_t s = 0; s < grown.result.strands.strand_count(); ++s)
        hairpins += has_hairpin(grown.result.strands.strand(s), 90) ? 1 : 0;
      EXPECT_LE(hairpins, grown.result.strands.strand_count() / 200);
    }
    row.print(name);
    presets.add(row);
    if (name.find("braid") != std::string::npos) braided.add(row);
  }
  presets.print("mean of presets");
  braided.print("braided presets");

  // Floors that catch a regression, with a margin below what grow measured when it landed
  // (commit 01dfda8; 2000 strands, seeds 1-3, per preset the mean of its three models):
  //   fidelity mean 0.0076-0.0116 H, short 0.0208 H, 0.0109 H over the presets; p95 at
  //   most 0.048 H (short); share of grown points over 0.1 H from the truth at most 0.0014;
  //   coverage mean 0.0087-0.0533 H (two_braids), 0.0252 H over the presets;
  //   median length ratio 0.536 (two_braids) to 1.095, 0.813 over the presets;
  //   braid reach: braid 0.596, normal_braid 0.000, two_braids 0.301.
  // They are not the aim: most strands rooted under a braid stop at or near its top, and
  // half_up's ponytail tail (behind a 4.5 cm hidden gap) is not grown at all.
  for (const auto& [name, row] : rows) {
    SCOPED_TRACE(name);
    EXPECT_LT(row.fidelity_mean.mean(), 0.03);
    EXPECT_LT(row.fidelity_p95.mean(), 0.07);
    EXPECT_LT(row.far_share.mean(), 0.01);
    EXPECT_LT(row.coverage_mean.mean(), 0.08);
    EXPECT_GT(row.length_ratio.mean(), 0.4);
  }
  EXPECT_LT(presets.fidelity_mean.mean(), 0.015);
  EXPECT_LT(presets.coverage_mean.mean(), 0.035);
  EXPECT_GT(presets.length_ratio.mean(), 0.7);
  EXPECT_GT(rows.at("braid").braid_reach.mean(), 0.4);
  EXPECT_GT(braided.braid_reach.mean(), 0.2);
}

TEST(SynthGrow, PaintedPresetsAgainstTheirTruth) {
  // The real-meshes issue's presets, grown with their texture and without it (the same
  // mesh, its materials dropped): grown strands within 0.02 H of the true ones on average
  // both ways (coverage and fidelity), and no grown hair where the truth has none (a wig
  // cap read in rings would grow a fringe down the forehead).
  PolyMesh body = read_mesh(std::filesystem::path(HAIR_SOURCE_DIR) / "data/samples/body.obj");
  body.vertices *= 0.1f;
  for (const std::string& name : painted_preset_names()) {
    Row with_paint, without_paint;
    for (uint32_t seed : {1u, 2u, 3u}) {
      SCOPED_TRACE(name + ", seed " + std::to_string(seed));
      SynthModel model =
          generate_model(varied_spec(preset(name), seed), body, seed, kTrueStrandsPerStream);
      Grown grown = grow_model(model, body, name);
      GrowScores scores = measure(model, grown.result.strands, grown.head_height_m);
      with_paint.add(scores);
      // The mohawk's spikes grow from their base (standing_cover_h): 0.0149 H over its
      // seeds; 0.0214 H when whole scalp triangles round the base carried roots and the
      // strands rooted at their sides grew up beside the card.
      EXPECT_LT(scores.fidelity_mean, 0.02);
      EXPECT_LT(scores.coverage_mean, 0.02);
      EXPECT_LT(scores.far_share, 0.005);
      // Grown along the true flow: 85%, but where the grown strands cannot follow their
      // truth. low_tail, shell_tail and the bun: cap strands converge at a band (and the
      // bun's coil);
      // the ringlets: the grown strands run down the tubes' axis, not round their
      // corkscrew, 8 mm in radius; the bob and volume_bob: rooted on the scalp under cards
      // that stand off it, a grown strand climbs to its card within layer_climb_h (0.08 H),
      // steeper than the truth's hair, which climbs over twice the card's height. Each
      // floor lies a few points under what its three seeds give.
      const double along_floor = name == "low_tail"     ? 0.7
                                 : name == "shell_tail" ? 0.78
                                 : name == "bun"        ? 0.74
                                 : name == "ringlets"   ? 0.52
                                 : name == "bob"        ? 0.8
                                 : name == "volume_bob" ? 0.72
                                                        : 0.85;
      EXPECT_GE(scores.along_truth, along_floor);
      // Every true layer reached: cap_over_layer's seed 3 comes nearest, its layer under
      // the cap at 0.0302 H (under 0.03 H before the field stopped at air).
      EXPECT_LT(scores.worst_layer_coverage, 0.033);
      SynthModel plain = model;
      plain.mesh.materials.clear();
      plain.mesh.face_material.clear();
      Grown plain_grown = grow_model(plain, body, name);
      without_paint.add(measure(plain, plain_grown.result.strands, plain_grown.head_height_m));
    }
    with_paint.print(name + " painted");
    without_paint.print(name + " plain");
    // Without its paint, the cap is read across its rings (hair does not circle the head):
    // the grown cap runs along the true hair as with it.
    if (name == "ring_cap") {
      EXPECT_GE(without_paint.along_truth.mean(), with_paint.along_truth.mean() - 0.05);
    }
  }
}

// Grown hair lies where the mesh has hair (GrowParams::field_air_stop_h): the field's band
// reaches 0.06 H round its seeds, past a card's edge, a shell's rim and a spike's base.
// Hair-synth's mohawk (spike cards standing on a strip), bob and volume_bob (shells standing
// off the head) and ring_cap (a cap whose rim ends at the hairline), grown with the field
// stopped where it runs into air and without: chords through air (hair-grow-report's
// definition) on at most 0.5% of the strands with it, coverage and fidelity no worse than
// without by more than 0.002 H.
TEST(SynthGrow, GrownHairLiesWhereTheMeshHasHair) {
  PolyMesh body = read_mesh(std::filesystem::path(HAIR_SOURCE_DIR) / "data/samples/body.obj");
  body.vertices *= 0.1f;
  const auto chord_share = [](const Grown& grown) {
    const hair::TriangleMeshDistance hair_distance(grown.hair_vertices, grown.hair_triangles);
    const hair::TriangleMeshDistance body_distance(grown.body_vertices, grown.body_triangles);
    const hair::KinkMeasures kinks =
        hair::measure_kinks(grown.result.strands, hair_distance, &body_distance, grown.head_height_m);
    return static_cast<double>(kinks.air_chord_strands) / static_cast<double>(kinks.strands);
  };
  for (const std::string name : {"mohawk", "bob", "volume_bob", "ring_cap"})
    for (uint32_t seed : {1u, 2u}) {
      SCOPED_TRACE(name + ", seed " + std::to_string(seed));
      SynthModel model =
          generate_model(varied_spec(preset(name), seed), body, seed, kTrueStrandsPerStream);
      const Grown stopped = grow_model(model, body, name);
      const Grown free = grow_model(model, body, name, GrowParams{}.join_continued_flow,
                                    ExtractParams{}, 0.0);
      const GrowScores with = measure(model, stopped.result.strands, stopped.head_height_m);
      const GrowScores without = measure(model, free.result.strands, free.head_height_m);
      const double chords_with = chord_share(stopped), chords_without = chord_share(free);
      std::printf(
          "[ air      ] %-10s seed %u: air chords %5.2f%% (field not stopped: %5.2f%%), "
          "coverage %.4f H (%.4f), fidelity %.4f H (%.4f), along the truth %.3f (%.3f)\n",
          name.c_str(), seed, 100 * chords_with, 100 * chords_without, with.coverage_mean,
          without.coverage_mean, with.fidelity_mean, without.fidelity_mean, with.along_truth,
          without.along_truth);
      EXPECT_LE(chords_with, 0.005);
      EXPECT_LE(with.coverage_mean, without.coverage_mean + 0.002);
      EXPECT_LE(with.fidelity_mean, without.fidelity_mean + 0.002);
      EXPECT_GE(with.along_truth, without.along_truth - 0.02);
    }
}

// A bob whose shell stands as far off the head as bob01's (hair-synth's volume_bob: its
// cards up to 3 cm farther off below the crown, 3.5-4 cm off the back of the head), its
// truth rooted all over the scalp under them. The hair rooted under the shell is reached
// only where extract counts that scalp as scalp: under hair up to scalp_under_hair_h off
// along the normal (0.15 H by default; compared with 0.1 H, and with 0: by distance alone,
// hair within scalp_distance_h).
TEST(SynthGrow, AVoluminousBobsHairIsRootedUnderItsShell) {
  PolyMesh body = read_mesh(std::filesystem::path(HAIR_SOURCE_DIR) / "data/samples/body.obj");
  body.vertices *= 0.1f;
  // The truth's strands rooted under the cards (those after the cards' own, which a model
  // without rooted_under_volume has alone), as points, and the coverage of them: the mean
  // distance from their points to the nearest grown segment, in H.
  auto under_coverage = [](const SynthModel& model, int64_t on_cards, const Grown& grown) {
    const StrandSet& truth = model.strands;
    SegmentDistance to_grown(grown.result.strands);
    double sum = 0;
    int64_t count = 0;
    for (int64_t row = truth.offsets[on_cards]; row < truth.point_count(); ++row, ++count)
      sum += to_grown(truth.points.row(row).transpose()) / grown.head_height_m;
    return sum / static_cast<double>(std::max<int64_t>(count, 1));
  };
  const ExtractParams by_default;
  ExtractParams nearer = by_default, by_distance = by_default;
  nearer.scalp_under_hair_h = 0.1;
  by_distance.scalp_under_hair_h = 0;
  Column by_default_coverage, nearer_coverage, distance_only;
  Row scores;
  for (uint32_t seed : {1u, 2u, 3u}) {
    SCOPED_TRACE("volume_bob, seed " + std::to_string(seed));
    const HairStyleSpec spec = varied_spec(preset("volume_bob"), seed);
    HairStyleSpec crown_only = spec;
    for (ComponentSpec& component : crown_only.components) component.rooted_under_volume = false;
    const SynthModel model = generate_model(spec, body, seed, kTrueStrandsPerStream);
    const int64_t on_cards =
        generate_model(crown_only, body, seed, kTrueStrandsPerStream).strands.strand_count();
    ASSERT_GT(model.strands.strand_count(), on_cards);
    const Grown grown = grow_model(model, body, "volume_bob");
    scores.add(measure(model, grown.result.strands, grown.head_height_m));
    by_default_coverage.add(under_coverage(model, on_cards, grown));
    nearer_coverage.add(
        under_coverage(model, on_cards, grow_model(model, body, "volume_bob", false, nearer)));
    distance_only.add(
        under_coverage(model, on_cards, grow_model(model, body, "volume_bob", false, by_distance)));
  }
  scores.print("volume_bob");
  std::printf(
      "[ synth    ] volume_bob: the true strands rooted under its shell lie %.4f H from the "
      "grown ones on average (%.4f H with the scalp under hair to 0.1 H, %.4f H by distance "
      "alone)\n",
      by_default_coverage.mean(), nearer_coverage.mean(), distance_only.mean());
  EXPECT_LT(scores.fidelity_mean.mean(), 0.02);
  EXPECT_LT(scores.coverage_mean.mean(), 0.02);
  EXPECT_LT(scores.worst_layer_coverage.mean(), 0.03);
  EXPECT_LT(by_default_coverage.mean(), 0.02);
  EXPECT_LT(by_default_coverage.mean(), distance_only.mean());
  EXPECT_LE(by_default_coverage.mean(), nearer_coverage.mean());
}

// Long hair hangs down past the bottom of the nape, lying on it or standing off it, and its
// truth is rooted far above (hair-synth's long_straight and half_up: the lowest true root
// 0.46-0.48 H above the neck). Extract's scalp under hair standing off the head starts
// scalp_under_hair_min_height_h above the neck (counted from the neck, ponytail01's tail,
// 2-4 cm off its nape, would root hair there): grown roots more than 0.35 H below the lowest true root
// (about 0.11 H above the neck) are then fewer than half as many as without it.
TEST(SynthGrow, LongHairHangingPastTheNapeIsNotRootedUnderIt) {
  PolyMesh body = read_mesh(std::filesystem::path(HAIR_SOURCE_DIR) / "data/samples/body.obj");
  body.vertices *= 0.1f;
  ExtractParams to_the_neck;
  to_the_neck.scalp_under_hair_min_height_h = 0;
  for (const char* name : {"long_straight", "half_up"}) {
    int64_t low_now = 0, low_to_the_neck = 0, grown_count = 0;
    for (uint32_t seed : {1u, 2u, 3u}) {
      SCOPED_TRACE(std::string(name) + ", seed " + std::to_string(seed));
      const SynthModel model =
          generate_model(varied_spec(preset(name), seed), body, seed, kTrueStrandsPerStream);
      const StrandSet& truth = model.strands;
      double lowest_true_root_y = std::numeric_limits<double>::infinity();
      for (int64_t strand = 0; strand < truth.strand_count(); ++strand)
        lowest_true_root_y =
            std::min<double>(lowest_true_root_y, truth.points(truth.offsets[strand], 1));
      auto low_roots = [&](const Grown& grown) {
        const StrandSet& strands = grown.result.strands;
        const double below_y = lowest_true_root_y - 0.35 * grown.head_height_m;
        int64_t low = 0;
        for (int64_t strand = 0; strand < strands.strand_count(); ++strand)
          low += strands.points(strands.offsets[strand], 1) < below_y ? 1 : 0;
        return low;
      };
      const Grown grown = grow_model(model, body, name);
      grown_count += grown.result.strands.strand_count();
      low_now += low_roots(grown);
      low_to_the_neck +=
          low_roots(grow_model(model, body, name, GrowParams{}.join_continued_flow, to_the_neck));
    }
    std::printf(
        "[ synth    ] %s: %lld of %lld grown roots more than 0.35 H below the lowest true root "
        "(%lld with the scalp under hair down to the neck)\n",
        name, static_cast<long long>(low_now), static_cast<long long>(grown_count),
        static_cast<long long>(low_to_the_neck));
    EXPECT_LT(2 * low_now, low_to_the_neck) << name;
    EXPECT_LT(static_cast<double>(low_now), 0.05 * static_cast<double>(grown_count)) << name;
  }
}

// Hair hanging over the face (hair-synth's face_locks: locks framing the face from the
// temples; long_straight and bob, whose front streams and cards hang beside the cheeks)
// lies within scalp_distance_h of the eyes and cheeks, and its truth is rooted above the
// brows. Extract leaves the face out of the scalp (scalp_face_below_top_h): no grown root
// lies on a triangle of the face as face_triangles() finds it below the brow line (0.4 H
// under the crown), where with the face left in the scalp (the rule moved below the neck)
// some do.
TEST(SynthGrow, NoHairIsRootedOnTheFace) {
  PolyMesh body = read_mesh(std::filesystem::path(HAIR_SOURCE_DIR) / "data/samples/body.obj");
  body.vertices *= 0.1f;
  const double top_y = body.vertices.col(1).maxCoeff();
  ExtractParams no_face_rule;
  no_face_rule.scalp_face_below_top_h = 2;  // below the neck: no face
  int64_t on_face_without = 0;
  for (const char* name : {"face_locks", "long_straight", "bob"}) {
    int64_t on_face = 0, grown_count = 0, without = 0;
    for (uint32_t seed : {1u, 2u}) {
      SCOPED_TRACE(std::string(name) + ", seed " + std::to_string(seed));
      const SynthModel model =
          generate_model(varied_spec(preset(name), seed), body, seed, kTrueStrandsPerStream);
      auto roots_on_face = [&](const Grown& grown) {
        const double h = grown.head_height_m;
        const Triangles3i triangles = fan_triangulation(body.face_offsets, body.face_vertices);
        const std::vector<uint8_t> face =
            face_triangles(body.vertices, triangles, top_y - h, top_y - 0.4 * h, kFaceRadiusH * h,
                           kFaceDepthH * h, kFaceHalfWidthH * h);
        const StrandSet& strands = grown.result.strands;
        const auto& root_triangle =
            std::get<std::vector<int32_t>>(strands.strand_attributes.at("root_triangle"));
        int64_t count = 0;
        for (int32_t t : root_triangle) count += face[static_cast<size_t>(t)];
        return count;
      };
      const Grown grown = grow_model(model, body, name);
      grown_count += grown.result.strands.strand_count();
      on_face += roots_on_face(grown);
      without += roots_on_face(
          grow_model(model, body, name, GrowParams{}.join_continued_flow, no_face_rule));
    }
    std::printf(
        "[ synth    ] %s: %lld of %lld grown roots on the face (%lld without the face rule)\n",
        name, static_cast<long long>(on_face), static_cast<long long>(grown_count),
        static_cast<long long>(without));
    EXPECT_EQ(on_face, 0) << name;
    on_face_without += without;
  }
  EXPECT_GT(on_face_without, 50);
}

// Artists hide a card's end under the skin (bob01's front cards run into the forehead):
// short caps whose every grid's tip dives 8 mm under the scalp over its last 12 mm
// (DefectSpec::tucked_share). The true strands still end on the scalp. Grown strands that
// follow such a card end where the body stops them (strands_ended_at_body) instead of
// trembling against it, no two steps in a row hardly advance, and the grown hair stays as
// near the truth as on the same caps untucked.
TEST(SynthGrow, CardsTuckedIntoTheHeadEndTheirStrandsAtTheSkin) {
  PolyMesh body = read_mesh(std::filesystem::path(HAIR_SOURCE_DIR) / "data/samples/body.obj");
  body.vertices *= 0.1f;
  Row flat, tucked;
  int64_t ended_at_body = 0, tucked_patches = 0;
  int64_t flat_groups = 0, flat_right = 0, tucked_groups = 0, tucked_right = 0;
  for (uint32_t seed : {1u, 2u, 3u}) {
    SCOPED_TRACE("short_cap, seed " + std::to_string(seed));
    HairStyleSpec spec = varied_spec(preset("short_cap"), seed);
    const SynthModel untucked = generate_model(spec, body, seed, kTrueStrandsPerStream);
    spec.defects.tucked_share = 1.0;
    const SynthModel model = generate_model(spec, body, seed, kTrueStrandsPerStream);
    for (const SynthPatch& patch : model.patches) tucked_patches += patch.tucked ? 1 : 0;
    // Groups extract reads root to tip, flat and tucked.
    for (const SynthModel* m : {&untucked, &model}) {
      const hair::testing::ClusteredInMemory run =
          hair::testing::cluster_in_memory(m->mesh, body, "short_cap");
      const auto orientations = group_orientations(*m, run.extract, group_patches(*m, run.extract));
      (m == &model ? tucked_groups : flat_groups) += static_cast<int64_t>(orientations.size());
      (m == &model ? tucked_right : flat_right) +=
          std::count(orientations.begin(), orientations.end(), GroupOrientation::root_to_tip);
    }
    // The same true strands: tucking spoils the mesh, not the hair.
    EXPECT_EQ(model.strands.points, untucked.strands.points);

    const Grown grown = grow_model(model, body, "short_cap");
    const GrowResult& result = grown.result;
    ended_at_body += result.strands_ended_at_body;
    const double quarter_step_m = 0.25 * GrowParams{}.step_h * grown.head_height_m;
    int64_t trembling = 0;
    for (int64_t s = 0; s < result.strands.strand_count(); ++s)
      for (int64_t row = result.strands.offsets[s] + 2; row < result.strands.offsets[s + 1];
           ++row) {
        const auto short_step = [&](int64_t r) {
          const GrowRule rule = result.point_rule[static_cast<size_t>(r)];
          return (rule == GrowRule::field || rule == GrowRule::input_strand) &&
                 (result.strands.points.row(r) - result.strands.points.row(r - 1)).norm() <
                     quarter_step_m;
        };
        trembling += short_step(row) && short_step(row - 1) ? 1 : 0;
      }
    EXPECT_EQ(trembling, 0);
    flat.add(measure(untucked, grow_model(untucked, body, "short_cap").result.strands,
                     grown.head_height_m));
    tucked.add(measure(model, result.strands, grown.head_height_m));
  }
  flat.print("short_cap flat");
  tucked.print("short_cap tucked");
  std::printf(
      "[ synth    ] short_cap tucked: %lld tucked patches, %lld strands ended at the body; groups "
      "read root to tip %lld / %lld flat, %lld / %lld tucked\n",
      static_cast<long long>(tucked_patches), static_cast<long long>(ended_at_body),
      static_cast<long long>(flat_right), static_cast<long long>(flat_groups),
      static_cast<long long>(tucked_right), static_cast<long long>(tucked_groups));
  EXPECT_GT(tucked_patches, 0);
  EXPECT_GT(ended_at_body, 0);
  EXPECT_LT(tucked.fidelity_mean.mean(), flat.fidelity_mean.mean() + 0.002);
  EXPECT_LT(tucked.coverage_mean.mean(), flat.coverage_mean.mean() + 0.002);
  EXPECT_LT(tucked.fidelity_mean.mean(), 0.02);
}

// GrowParams::join_continued_flow against truth on the presets whose hair gathers into a
// band: with it, strands whose cards end on the cap join the cards feeding the tail.
TEST(SynthGrow, JoiningTheCardsThatFeedATailAgainstTruth) {
  PolyMesh body = read_mesh(std::filesystem::path(HAIR_SOURCE_DIR) / "data/samples/body.obj");
  body.vertices *= 0.1f;
  for (const std::string name : {"low_tail", "ponytail"}) {
    Row apart, joined;
    for (uint32_t seed : {1u, 2u, 3u}) {
      SCOPED_TRACE(name + ", seed " + std::to_string(seed));
      SynthModel model =
          generate_model(varied_spec(preset(name), seed), body, seed, kTrueStrandsPerStream);
      Grown without = grow_model(model, body, name, false);
      Grown with = grow_model(model, body, name, true);
      apart.add(measure(model, without.result.strands, without.head_height_m));
      joined.add(measure(model, with.result.strands, with.head_height_m));
    }
    apart.print(name + " apart");
    joined.print(name + " joined");
    // The true strands run from the scalp through the band into the tail: joined, fewer
    // grown strands stop short of their true length (low_tail: 0.888 -> 0.945 of it at the
    // median, 13.8% -> 10.4% short), and they stay as close to the truth.
    EXPECT_GT(joined.length_ratio.mean(), apart.length_ratio.mean());
    EXPECT_LT(joined.short_share.mean(), apart.short_share.mean());
    EXPECT_LT(joined.fidelity_mean.mean(), apart.fidelity_mean.mean() + 0.001);
    EXPECT_LT(joined.coverage_mean.mean(), apart.coverage_mean.mean() + 0.0005);
  }
}

}  // namespace
}  // namespace hair::synth
