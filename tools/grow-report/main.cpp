// hair-grow-report: how well the strands of strands.h5 reproduce the hair mesh of the
// extract.h5 they were grown from: coverage, fidelity, points inside the body, roots
// off the scalp, the worst patch's coverage, how the input and the grown strands follow the
// painted flow (against the nearest face, and against the card each strand follows), and
// the strands per cluster (docs/grow.md). Prints one Markdown table row,
// or the header with --header; --clusters prints a table of the strands per cluster,
// --by-rule one of how the grown segments follow the flow by how each was grown, and of
// the air chords by the rule that grew them.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>

#include "hair/core/error.h"
#include "hair/extract/extract_io.h"
#include "hair/extract/painted_flow.h"
#include "hair/grow/flow_by_rule.h"
#include "hair/grow/followed_card_flow.h"
#include "hair/grow/grow_io.h"
#include "hair/grow/grow_measures.h"
#include "hair/grow/strand_sense.h"
#include "hair/h5/dataset.h"
#include "hair/h5/enum_dataset.h"
#include "hair/h5/schema_validation.h"
#include "hair/h5/strand_set_io.h"

namespace {

/// Per triangle of the fan triangulation of faces with `face_offsets`, its face's group.
std::vector<int32_t> triangle_groups(const std::vector<int64_t>& face_offsets,
                                     const std::vector<int32_t>& face_group) {
  std::vector<int32_t> groups;
  for (size_t f = 0; f + 1 < face_offsets.size(); ++f)
    groups.insert(
        groups.end(),
        static_cast<size_t>(std::max<int64_t>(0, face_offsets[f + 1] - face_offsets[f] - 2)),
        face_group[f]);
  return groups;
}

/// "a% (n)" for a share of n judged, or "-" when nothing was judged.
std::string share_text(double share, int64_t judged) {
  if (judged == 0) return "-";
  char text[64];
  std::snprintf(text, sizeof text, "%.1f%%", 100 * share);
  return text;
}

/// What grown strands are judged against: the extract's paint and input strands, and the
/// flow (the paint, or the rails where there is none) within near_m (0.1 H) of the mesh.
struct JudgedFlow {
  hair::ExtractedPaint paint;
  hair::StrandSet input;
  double near_m = 0;
  hair::PaintedFlow flow;
};
JudgedFlow judged_flow_of(const hair::h5::File& extract, double head_height_m) {
  JudgedFlow judged{hair::read_extracted_paint(extract),
                    hair::h5::read_strand_set(extract, "/strands"),
                    0.1 * head_height_m,
                    {}};
  judged.flow = hair::flow_with_rails(judged.paint.mesh, judged.paint.flow, judged.input,
                                      hair::h5::read_vector<int32_t>(extract, "/mesh/face_group"),
                                      judged.near_m);
  return judged;
}

/// A row of the --by-rule table: a tally, its share of `all_judged` and its share along.
void print_tally_row(const char* what, const hair::FlowTally& tally, int64_t all_judged) {
  std::printf("| %s | %lld | %s | %s |\n", what, static_cast<long long>(tally.judged),
              share_text(static_cast<double>(tally.judged) /
                             static_cast<double>(std::max<int64_t>(1, all_judged)),
                         all_judged)
                  .c_str(),
              share_text(static_cast<double>(tally.along) /
                             static_cast<double>(std::max<int64_t>(1, tally.judged)),
                         tally.judged)
                  .c_str());
}

/// The --by-rule table of `label`.
void print_flow_by_rule(const std::string& label, const hair::FlowByRule& tally) {
  int64_t all_judged = 0;
  for (const hair::FlowTally& rule : tally.by_rule) all_judged += rule.judged;
  std::printf(
      "| %s: grown | segments judged | share of them | along the flow |\n"
      "|---|---:|---:|---:|\n",
      label.c_str());
  print_tally_row("along the field", tally.by_rule[1], all_judged);
  const char* steps[] = {"field, 1st step from the root", "field, 2nd step", "field, 3rd step",
                         "field, later steps"};
  for (size_t k = 0; k < tally.field_by_step.size(); ++k)
    print_tally_row(steps[k], tally.field_by_step[k], all_judged);
  print_tally_row("along input strands", tally.by_rule[2], all_judged);
  print_tally_row("bridges between strands", tally.by_rule[3], all_judged);
}

/// The kinked strands' indices, one a line, to `out` (nothing when it is not open).
void write_kinked(std::ofstream& out, const std::string& path, const hair::KinkMeasures& kinks) {
  if (!out.is_open()) return;
  for (const int64_t s : kinks.kinked) out << s << "\n";
  out.flush();
  if (!out) throw hair::Error::runtime(path, "cannot write the kinked strands");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("Measure grown strands against the hair mesh and the body.", "hair-grow-report");
  std::string extract_path, strands_path, name, kinked_path;
  int samples = 20000;
  bool header = false, clusters = false, by_rule = false;
  app.add_flag("--header", header, "print the table's header and exit");
  app.add_flag("--clusters", clusters,
               "print a table of the strands per cluster instead of the measures");
  app.add_flag("--by-rule", by_rule,
               "print a table of how the grown segments run along the flow (as 'grown along "
               "flow' judges them) by how each was grown: along the field (and its first "
               "steps), along input strands, bridges; then the air chords by the rule that "
               "grew most of each one's stretch through air")
      ->excludes("--clusters");
  app.add_option("EXTRACT_H5", extract_path, "extract.h5 the strands were grown from");
  app.add_option("STRANDS_H5", strands_path, "strands.h5 from the grow stage");
  app.add_option("--kinked", kinked_path,
                 "also write the index of every kinked strand (a hairpin or an air chord), one "
                 "a line, to this file")
      ->excludes("--clusters");
  app.add_option("--name", name, "first column (default: the strands file)");
  app.add_option("--samples", samples, "points sampled on the hair mesh")
      ->check(CLI::Range(100, 10'000'000));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "hair-grow-report: error: " << e.what() << "\n";
    return 2;
  }
  if (header) {
    std::printf(
        "| model | strands | points | coverage mean / p95 (H) | fidelity mean / p95 (H) | "
        "points inside body | root to scalp mean / max (H) | worst patch: coverage mean (H) | "
        "input along paint | grown along flow | grown along the followed card | clusters: "
        "strands min / median / max | kinked strands (hairpins / air chords) | curvature "
        "grown / cards (rad/m) |\n"
        "|---|---:|---:|---|---|---:|---|---|---:|---:|---:|---|---|---|\n");
    return 0;
  }
  try {
    if (extract_path.empty() || strands_path.empty())
      throw hair::Error::usage("EXTRACT_H5 and STRANDS_H5 are required");
    // Opened first, so that a path that cannot be written fails before anything is printed.
    std::ofstream kinked_out;
    if (!kinked_path.empty()) {
      kinked_out.open(kinked_path);
      if (!kinked_out) throw hair::Error::bad_input(kinked_path, "cannot be written (--kinked)");
    }
    hair::h5::File extract = hair::h5::File::open_read_only(extract_path);
    hair::h5::require_schema(extract, hair::kExtractSchema);
    hair::GrownStrands grown =
        hair::read_grown_strands(hair::h5::File::open_read_only(strands_path));
    hair::Points3f hair_vertices = hair::h5::read_matrix<float, 3>(extract, "/mesh/vertices");
    hair::Triangles3i hair_triangles =
        hair::fan_triangulation(hair::h5::read_vector<int64_t>(extract, "/mesh/face_offsets"),
                                hair::h5::read_vector<int32_t>(extract, "/mesh/face_vertices"));
    hair::ExtractedBody body = hair::read_extracted_body(extract);
    const auto strand_count_by_cluster = hair::h5::read_vector<int64_t>(
        hair::h5::File::open_read_only(strands_path), "/clusters/strand_count");
    const std::string label = name.empty() ? strands_path : name;
    if (clusters) {
      const std::vector<hair::ClusterPassage> passages = hair::cluster_passages(
          grown.strands, static_cast<int64_t>(strand_count_by_cluster.size()));
      std::printf(
          "| %s: cluster | strands | share | ending in another cluster | passing in from "
          "others |\n|---:|---:|---:|---:|---:|\n",
          label.c_str());
      for (size_t c = 0; c < strand_count_by_cluster.size(); ++c)
        std::printf("| %zu | %lld | %.1f%% | %lld | %lld |\n", c,
                    static_cast<long long>(strand_count_by_cluster[c]),
                    100.0 * static_cast<double>(strand_count_by_cluster[c]) /
                        static_cast<double>(std::max<int64_t>(1, grown.strands.strand_count())),
                    static_cast<long long>(passages[c].rooted_leaving),
                    static_cast<long long>(passages[c].passing_in));
      return 0;
    }
    // The flow grown strands are judged against: the paint, or the rails where there is
    // none, within 0.1 H of the mesh.
    const JudgedFlow judged = judged_flow_of(extract, grown.head_height_m);
    if (by_rule) {
      print_flow_by_rule(
          label, hair::flow_agreement_by_rule(
                     grown.strands,
                     hair::segments_along_painted_flow(judged.paint.mesh, judged.flow,
                                                       grown.strands, hair::kClearFlowCoherence,
                                                       hair::kFlowAgreementAngleDeg, judged.near_m),
                     hair::h5::read_enum_values(hair::h5::File::open_read_only(strands_path),
                                                "/strands/point_rule")));
      // The air chords (kinked strands' second kind) by the rule that grew them.
      const std::vector<int8_t> point_rule = hair::h5::read_enum_values(
          hair::h5::File::open_read_only(strands_path), "/strands/point_rule");
      const hair::TriangleMeshDistance body_distance(body.vertices, body.triangles);
      const hair::KinkMeasures kinks = hair::measure_kinks(
          grown.strands, hair::TriangleMeshDistance(hair_vertices, hair_triangles),
          &body_distance, grown.head_height_m, {}, &point_rule);
      const auto share = [&](int64_t count) {
        return 100.0 * static_cast<double>(count) /
               static_cast<double>(std::max<int64_t>(1, kinks.strands));
      };
      std::printf(
          "\n| %s: air chords by the rule that grew most of the stretch | strands | share of "
          "all strands |\n|---|---:|---:|\n",
          label.c_str());
      const char* names[] = {"the root", "along the field", "along input strands",
                             "bridges between strands"};
      for (size_t r = 1; r < 4; ++r)
        std::printf("| %s | %lld | %.2f%% |\n", names[r],
                    static_cast<long long>(kinks.air_chord_strands_by_rule[r]),
                    share(kinks.air_chord_strands_by_rule[r]));
      std::printf("| all | %lld | %.2f%% |\n", static_cast<long long>(kinks.air_chord_strands),
                  share(kinks.air_chord_strands));
      write_kinked(kinked_out, kinked_path, kinks);
      return 0;
    }
    hair::GrowMeasures m = hair::measure_grown_strands(
        grown.strands, hair_vertices, hair_triangles, body.vertices, body.triangles,
        body.scalp_triangle, grown.head_height_m, samples,
        triangle_groups(hair::h5::read_vector<int64_t>(extract, "/mesh/face_offsets"),
                        hair::h5::read_vector<int32_t>(extract, "/mesh/face_group")));

    // The flow: input strands against the paint where it is clear; grown strands against
    // the judged flow.
    const hair::ExtractedPaint& paint = judged.paint;
    const double near_m = judged.near_m;
    const hair::PaintedFlow& judged_flow = judged.flow;
    int64_t input_judged = 0, grown_judged = 0;
    const double input_along = hair::painted_flow_agreement(
        paint.mesh, paint.flow, judged.input, hair::kClearFlowCoherence,
        hair::kFlowAgreementAngleDeg, near_m, input_judged);
    const double grown_along = hair::painted_flow_agreement(
        paint.mesh, judged_flow, grown.strands, hair::kClearFlowCoherence,
        hair::kFlowAgreementAngleDeg, near_m, grown_judged);
    // The same against the card each strand follows, where cards cross.
    const hair::h5::File strands_file = hair::h5::File::open_read_only(strands_path);
    const auto point_group = grown.strands.point_attributes.find("group");
    if (point_group == grown.strands.point_attributes.end() ||
        !std::holds_alternative<std::vector<int32_t>>(point_group->second))
      throw hair::Error::bad_dataset(strands_path, "/strands/point_attributes/group",
                                     "missing or not integers");
    int64_t followed_judged = 0;
    const double followed_along = hair::followed_card_flow_agreement(
        paint.mesh, hair::h5::read_vector<int32_t>(extract, "/mesh/face_group"), judged_flow,
        grown.strands, std::get<std::vector<int32_t>>(point_group->second),
        hair::h5::read_enum_values(strands_file, "/strands/point_rule"), hair::kClearFlowCoherence,
        hair::kFlowAgreementAngleDeg, near_m, followed_judged);

    std::vector<int64_t> sorted_counts = strand_count_by_cluster;
    std::sort(sorted_counts.begin(), sorted_counts.end());
    std::string cluster_text = "-";
    if (!sorted_counts.empty())
      cluster_text = std::to_string(sorted_counts.size()) + ": " +
                     std::to_string(sorted_counts.front()) + " / " +
                     std::to_string(sorted_counts[sorted_counts.size() / 2]) + " / " +
                     std::to_string(sorted_counts.back());
    std::string worst_text = "-";
    if (m.worst_group >= 0) {
      char text[96];
      std::snprintf(text, sizeof text, "group %d: %.4f", m.worst_group,
                    m.worst_group_coverage_mean_h);
      worst_text = text;
    }
    // The strands' sense: kinks, and curvature against the cards' (their input strands)
    // at a common step of 0.01 H.
    const hair::TriangleMeshDistance body_distance(body.vertices, body.triangles);
    const hair::KinkMeasures kinks = hair::measure_kinks(
        grown.strands, hair::TriangleMeshDistance(hair_vertices, hair_triangles), &body_distance,
        grown.head_height_m);
    write_kinked(kinked_out, kinked_path, kinks);
    const auto strand_share = [&](int64_t count) {
      return 100.0 * static_cast<double>(count) /
             static_cast<double>(std::max<int64_t>(1, kinks.strands));
    };
    const double curvature_step_m = 0.01 * grown.head_height_m;
    const double grown_curvature = hair::mean_curvature_per_m(grown.strands, curvature_step_m);
    const double card_curvature = hair::mean_curvature_per_m(judged.input, curvature_step_m);
    char sense_text[160];
    std::snprintf(sense_text, sizeof sense_text,
                  "%.2f%% (%.2f%% / %.2f%%) | %.1f / %.1f (%.2f)", strand_share(kinks.kinked_strands),
                  strand_share(kinks.hairpin_strands), strand_share(kinks.air_chord_strands),
                  grown_curvature, card_curvature,
                  card_curvature > 0 ? grown_curvature / card_curvature : 0.0);
    std::printf(
        "| %s | %lld | %lld | %.4f / %.4f | %.4f / %.4f | %.2f%% | %.4f / %.4f | %s | %s | %s | %s "
        "| %s | %s |\n",
        label.c_str(), static_cast<long long>(grown.strands.strand_count()),
        static_cast<long long>(grown.strands.point_count()), m.coverage_mean_h, m.coverage_p95_h,
        m.fidelity_mean_h, m.fidelity_p95_h, 100 * m.inside_body_share, m.root_distance_mean_h,
        m.root_distance_max_h, worst_text.c_str(), share_text(input_along, input_judged).c_str(),
        share_text(grown_along, grown_judged).c_str(),
        share_text(followed_along, followed_judged).c_str(), cluster_text.c_str(), sense_text);
  } catch (const hair::Error& e) {
    std::cerr << "hair-grow-report: error: " << e.what() << "\n";
    return e.exit_code();
  } catch (const std::exception& e) {
    std::cerr << "hair-grow-report: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
