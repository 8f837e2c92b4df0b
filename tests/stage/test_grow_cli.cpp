// grow and hair-grow-report as subprocesses: on the braid and ponytail samples after
// extract, typeify, cluster-middle and cluster-all (2000 strands, to stay fast), a valid
// strands.h5 with every root on the scalp; byte-identical reruns whatever the thread
// count; bad input (exit 2, one line, no output, an existing output untouched); the
// report's header, row and refusal.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "hair/core/strand_set.h"
#include "hair/grow/grow_io.h"
#include "hair/h5/attribute.h"
#include "hair/h5/dataset.h"
#include "hair/h5/enum_dataset.h"
#include "hair/h5/file.h"
#include "stage/clean_failures.h"
#include "stage/sample_pipeline.h"
#include "support/run_command.h"

namespace {

namespace fs = std::filesystem;
using hair::test::read_file_bytes;
using hair::test::run_command;
using hair::test::TemporaryDirectory;
using hair::test::text_lines;

constexpr int kStrands = 2000;

using Outputs = hair::test::SampleOutputs;
using hair::test::kBin;
using hair::test::kSamples;
using hair::test::run_stage;

/// The samples' pipeline files, made on first use and kept for the suite. ctest runs
/// every test in a process of its own, so each makes only what it uses.
class GrowCli : public ::testing::Test {
 protected:
  static void TearDownTestSuite() { directory_.reset(); }

  static const TemporaryDirectory& directory() {
    if (!directory_) directory_ = std::make_unique<TemporaryDirectory>("grow_cli");
    return *directory_;
  }
  /// braid01 or ponytail01 up to clusters.h5, and strands.h5 if `grown`.
  static Outputs sample(const std::string& model, bool grown) {
    return hair::test::run_sample_pipeline(
        directory() / model, kSamples / "hair" / (model + ".obj"), grown ? kStrands : 0);
  }

 private:
  static std::unique_ptr<TemporaryDirectory> directory_;
};
std::unique_ptr<TemporaryDirectory> GrowCli::directory_;

/// No strand stalls: every step moves on, none runs out of points (the default
/// max_points_per_strand), and no two steps in a row along the field or an input strand
/// advance less than a quarter of a step (a strand trembling against the body).
void expect_no_stalls(const hair::StrandSet& strands, const std::vector<int8_t>& rule,
                      double head_height_m) {
  const double quarter_step_m = 0.25 * hair::GrowParams{}.step_h * head_height_m;
  const auto short_step = [&](int64_t row) {
    const auto r = static_cast<hair::GrowRule>(rule[static_cast<size_t>(row)]);
    return (r == hair::GrowRule::field || r == hair::GrowRule::input_strand) &&
           (strands.points.row(row) - strands.points.row(row - 1)).norm() < quarter_step_m;
  };
  for (int64_t s = 0; s < strands.strand_count(); ++s) {
    EXPECT_LT(strands.strand_size(s), hair::GrowParams{}.max_points_per_strand) << "strand " << s;
    for (int64_t row = strands.offsets[s] + 1; row < strands.offsets[s + 1]; ++row) {
      ASSERT_GT((strands.points.row(row) - strands.points.row(row - 1)).norm(), 1e-4f)
          << "strand " << s << ", point " << row - strands.offsets[s];
      ASSERT_FALSE(row > strands.offsets[s] + 1 && short_step(row) && short_step(row - 1))
          << "strand " << s << " trembles at point " << row - strands.offsets[s];
    }
  }
}

/// Checks strands.h5 of `out`: valid, kStrands strands with their attributes, roots on
/// flagged scalp triangles, clusters of clusters.h5, no stalled strand, one rule per point.
void expect_valid_strands(const Outputs& out) {
  auto inspect = run_command(kBin / "hair-inspect", {out.strands.string()});
  EXPECT_EQ(inspect.exit_code, 0) << inspect.out << inspect.err;
  std::vector<std::string> report = text_lines(inspect.out);
  ASSERT_FALSE(report.empty());
  EXPECT_EQ(report.back(), "valid: hairstyle.strands v2");

  hair::h5::File file = hair::h5::File::open_read_only(out.strands);
  hair::GrownStrands grown = hair::read_grown_strands(file);
  hair::GrowInput input = hair::read_grow_input(hair::h5::File::open_read_only(out.extract),
                                                hair::h5::File::open_read_only(out.types),
                                                hair::h5::File::open_read_only(out.clusters));
  const hair::StrandSet& strands = grown.strands;
  ASSERT_EQ(strands.strand_count(), kStrands);
  EXPECT_EQ(grown.head_height_m, input.head_height_m);
  EXPECT_EQ(hair::h5::read_string_attribute(file, "/", "stage"), "grow");
  EXPECT_EQ(hair::h5::read_int64_attribute(file, "/", "strand_count_requested"), kStrands);
  for (const char* name : {"cluster", "root_triangle", "root_normal"})
    EXPECT_TRUE(strands.strand_attributes.contains(name)) << name;

  const auto& cluster = std::get<std::vector<int32_t>>(strands.strand_attributes.at("cluster"));
  const auto& triangle =
      std::get<std::vector<int32_t>>(strands.strand_attributes.at("root_triangle"));
  int32_t cluster_count =
      *std::max_element(input.group_cluster.begin(), input.group_cluster.end()) + 1;
  std::vector<int64_t> per_cluster(static_cast<size_t>(cluster_count), 0);
  for (int64_t s = 0; s < kStrands; ++s) {
    int32_t c = cluster[static_cast<size_t>(s)], t = triangle[static_cast<size_t>(s)];
    ASSERT_GE(c, 0);
    ASSERT_LT(c, cluster_count);
    ++per_cluster[static_cast<size_t>(c)];
    ASSERT_GE(t, 0);
    ASSERT_LT(t, input.body_triangles.rows());
    EXPECT_TRUE(input.scalp_triangle[static_cast<size_t>(t)]) << "strand " << s;
  }
  EXPECT_EQ(hair::h5::read_vector<int64_t>(file, "/clusters/strand_count"), per_cluster);

  std::vector<int8_t> rule =
      hair::h5::read_enum_dataset(file, "/strands/point_rule", hair::grow_rule_members());
  ASSERT_EQ(static_cast<int64_t>(rule.size()), strands.point_count());
  expect_no_stalls(strands, rule, input.head_height_m);

  std::map<int8_t, int64_t> per_rule;
  for (int8_t r : rule) ++per_rule[r];
  for (int64_t s = 0; s < kStrands; ++s)
    EXPECT_EQ(rule[static_cast<size_t>(strands.offsets[s])],
              static_cast<int8_t>(hair::GrowRule::root));
  EXPECT_EQ(per_rule[static_cast<int8_t>(hair::GrowRule::root)], kStrands);
  // Both phases happen: the cap's field, then the input strands below it.
  EXPECT_GT(per_rule[static_cast<int8_t>(hair::GrowRule::field)], 0);
  EXPECT_GT(per_rule[static_cast<int8_t>(hair::GrowRule::input_strand)], 0);

  // Every point has a cluster and a group: the root's cluster without a group at the root
  // and along the field; the followed group's cluster along input strands. Strands run
  // from one cluster into another (the cap into the braid or the tail).
  const auto& point_cluster =
      std::get<std::vector<int32_t>>(strands.point_attributes.at("cluster"));
  const auto& point_group = std::get<std::vector<int32_t>>(strands.point_attributes.at("group"));
  ASSERT_EQ(static_cast<int64_t>(point_cluster.size()), strands.point_count());
  ASSERT_EQ(static_cast<int64_t>(point_group.size()), strands.point_count());
  int64_t crossing = 0;
  for (int64_t s = 0; s < kStrands; ++s) {
    auto root = static_cast<size_t>(strands.offsets[s]);
    EXPECT_EQ(point_cluster[root], cluster[static_cast<size_t>(s)]) << "strand " << s;
    bool crosses = false;
    for (auto row = root; row < static_cast<size_t>(strands.offsets[s + 1]); ++row) {
      auto r = static_cast<hair::GrowRule>(rule[row]);
      if (r == hair::GrowRule::root || r == hair::GrowRule::field) {
        ASSERT_EQ(point_group[row], -1) << "strand " << s;
        ASSERT_EQ(point_cluster[row], point_cluster[root]) << "strand " << s;
      } else {
        ASSERT_GE(point_group[row], 0) << "strand " << s;
        ASSERT_LT(point_group[row], static_cast<int32_t>(input.group_cluster.size()));
        if (r == hair::GrowRule::input_strand) {
          ASSERT_EQ(point_cluster[row], input.group_cluster[static_cast<size_t>(point_group[row])]);
        }
      }
      crosses = crosses || point_cluster[row] != point_cluster[root];
    }
    crossing += crosses;
  }
  EXPECT_GT(crossing, kStrands / 50);
  std::printf("[ grow     ] %s: %lld strands run through more than one cluster\n",
              out.strands.parent_path().filename().c_str(), static_cast<long long>(crossing));
  std::printf("[ grow     ] %s: %lld points; field %lld, input_strand %lld, bridge %lld\n",
              out.strands.parent_path().filename().c_str(),
              static_cast<long long>(strands.point_count()),
              static_cast<long long>(per_rule[static_cast<int8_t>(hair::GrowRule::field)]),
              static_cast<long long>(per_rule[static_cast<int8_t>(hair::GrowRule::input_strand)]),
              static_cast<long long>(per_rule[static_cast<int8_t>(hair::GrowRule::bridge)]));
}

TEST_F(GrowCli, GrowsTheBraidSample) { expect_valid_strands(sample("braid01", true)); }

TEST_F(GrowCli, GrowsThePonytailSample) { expect_valid_strands(sample("ponytail01", true)); }

// The paper's section 4.4 and its Figure 11: a ponytail's tail carries the hair that feeds
// it. All of ponytail01's hair is pulled back from the scalp into a band and on into a
// tail that hangs down the back, below the neck, where no other hair of the mesh reaches:
// a strand that ends there has run through the band. Its points are continuous from the
// root (no jump between points longer than a growing step and a bridge allow). And the
// hair is pulled back: few strands end well in front of their root.
TEST_F(GrowCli, ThePonytailsCapStrandsRunThroughTheBandIntoTheTail) {
  const Outputs out = sample("ponytail01", true);
  const double neck_y_m =
      hair::h5::read_double_attribute(hair::h5::File::open_read_only(out.extract), "/", "neck_y_m");
  // The share of strands whose tip hangs in the tail, the longest jump between two points
  // of such a strand, in H, and the share of strands whose tip lies over 0.2 H in front
  // of their root (+z: the body faces +z).
  const auto tail_share = [&](const fs::path& path, double& longest_jump_h, double& forward_share) {
    const hair::GrownStrands grown = hair::read_grown_strands(hair::h5::File::open_read_only(path));
    const hair::StrandSet& strands = grown.strands;
    int64_t into_tail = 0, forward = 0;
    longest_jump_h = 0;
    for (int64_t s = 0; s < strands.strand_count(); ++s) {
      const int64_t tip = strands.offsets[s + 1] - 1;
      if (strands.points(tip, 2) - strands.points(strands.offsets[s], 2) >
          0.2 * grown.head_height_m)
        ++forward;
      if (strands.points(tip, 1) >= neck_y_m) continue;
      ++into_tail;
      for (int64_t row = strands.offsets[s]; row < tip; ++row)
        longest_jump_h = std::max(
            longest_jump_h,
            static_cast<double>((strands.points.row(row + 1) - strands.points.row(row)).norm()) /
                grown.head_height_m);
    }
    forward_share = static_cast<double>(forward) / static_cast<double>(strands.strand_count());
    return static_cast<double>(into_tail) / static_cast<double>(strands.strand_count());
  };
  const fs::path joined = out.strands.parent_path() / "joined.h5";
  std::vector<std::string> arguments = out.grow_inputs();
  arguments.insert(arguments.end(), {"--strand_count", std::to_string(kStrands),
                                     "--join_continued_flow=true", "-o", joined.string()});
  run_stage("grow", arguments);
  double jump_default_h = 0, jump_joined_h = 0, forward_default = 0, forward_joined = 0;
  const double share_default = tail_share(out.strands, jump_default_h, forward_default);
  const double share_joined = tail_share(joined, jump_joined_h, forward_joined);
  std::printf(
      "ponytail01: %.1f%% of %d strands end in the tail (%.1f%% joining the cards that "
      "feed it); longest jump %.3f H (%.3f H); %.1f%% end over 0.2 H in front of their root "
      "(%.1f%%)\n",
      100 * share_default, kStrands, 100 * share_joined, jump_default_h, jump_joined_h,
      100 * forward_default, 100 * forward_joined);
  // The target: 80%. The cap's strands that end short of the band (their cards
  // end on the cap) enter the tail's pieces across the gap (continued_tip_off_scalp_h);
  // joining the cards that feed it adds little to that. What stays out: the cards at the
  // front of the crown, read from the crown to the hairline (extract's continuation
  // rule), whose strands grow forward, away from the band; they are most of the strands
  // that end in front of their root. Entering a piece of the tail's cluster that lies
  // over the scalp (one of those front cards, typed tip) doubled them (15.5% of 10,000).
  EXPECT_GE(share_default, 0.8);
  EXPECT_GE(share_joined, 0.8);
  EXPECT_LE(forward_default, 0.1);
  EXPECT_LE(forward_joined, 0.1);
  EXPECT_LE(jump_default_h, 0.1);
  EXPECT_LE(jump_joined_h, 0.1);
}

// bob01's front cards run into the forehead. Strands that followed them used to tremble
// there, each step pushed back out of the body where it began: three fifths of the
// segments grown along bob01's input strands, most across the painted flow (75% of the
// grown segments along it, against 99% of extract's). They now end where the body stops
// them: no trembling, and the grown strands follow the paint as the input strands do.
TEST_F(GrowCli, Bob01sStrandsEndWhereItsFrontCardsDiveIntoTheForehead) {
  const fs::path mesh = fs::path(HAIR_SHARED_DATA_DIR) / "makehuman" / "hair" / "bob01.obj";
  if (!fs::exists(mesh)) GTEST_SKIP() << mesh << " not found";
  const Outputs out = hair::test::run_sample_pipeline(directory() / "bob01", mesh, kStrands);
  const hair::GrownStrands grown =
      hair::read_grown_strands(hair::h5::File::open_read_only(out.strands));
  expect_no_stalls(grown.strands,
                   hair::h5::read_enum_dataset(hair::h5::File::open_read_only(out.strands),
                                               "/strands/point_rule", hair::grow_rule_members()),
                   grown.head_height_m);

  // hair-grow-report's "grown along flow" column.
  const fs::path report = kBin / "hair-grow-report";
  const std::vector<std::string> header = text_lines(run_command(report, {"--header"}).out);
  const auto row = run_command(report, {out.extract.string(), out.strands.string()});
  ASSERT_EQ(row.exit_code, 0) << row.err;
  const auto cells_of = [](const std::string& line) {
    std::vector<std::string> cells;
    std::string cell;
    for (char c : line.substr(1)) {
      if (c != '|') {
        cell += c;
        continue;
      }
      cells.push_back(cell.substr(cell.find_first_not_of(' '),
                                  cell.find_last_not_of(' ') - cell.find_first_not_of(' ') + 1));
      cell.clear();
    }
    return cells;
  };
  ASSERT_FALSE(header.empty());
  const std::vector<std::string> names = cells_of(header[0]),
                                 values = cells_of(text_lines(row.out)[0]);
  const auto column = std::find(names.begin(), names.end(), "grown along flow");
  ASSERT_NE(column, names.end()) << header[0];
  const std::string along = values.at(static_cast<size_t>(column - names.begin()));
  std::printf("[ grow     ] bob01, %d strands: grown along flow %s\n", kStrands, along.c_str());
  EXPECT_GE(std::stod(along), 85.0);  // the real-meshes issue's target; 74.8% before
}

TEST_F(GrowCli, ReproducibleRunsAreByteIdenticalWhateverTheThreadCount) {
  const Outputs braid = sample("braid01", false);
  // The first run uses every core (the default), the second too, the third one thread.
  std::string first;
  for (const std::vector<std::string>& extra :
       {std::vector<std::string>{}, std::vector<std::string>{},
        std::vector<std::string>{"--threads", "1"}}) {
    fs::path again = directory() / "again.h5";
    std::vector<std::string> arguments = braid.grow_inputs();
    arguments.insert(arguments.end(),
                     {"--strand_count", std::to_string(kStrands), "-o", again.string()});
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    run_stage("grow", arguments);
    if (first.empty()) {
      first = read_file_bytes(again);
      ASSERT_FALSE(first.empty());
    } else {
      EXPECT_TRUE(read_file_bytes(again) == first)
          << "grow " << (extra.empty() ? "" : extra[1] + " thread(s)") << " wrote other bytes";
    }
    fs::remove(again);
  }
}

TEST_F(GrowCli, WrongInputsFailCleanly) {
  const Outputs braid = sample("braid01", false), ponytail = sample("ponytail01", false);
  const TemporaryDirectory& directory = GrowCli::directory();
  hair::test::write_text_file(directory / "text.h5", "not HDF5\n");
  const std::string extract = braid.extract.string(), types = braid.types.string(),
                    clusters = braid.clusters.string();
  const std::vector<hair::test::FailureCase> cases = {
      {{(directory / "missing.h5").string(), types, clusters}, "missing.h5"},
      {{(directory / "text.h5").string(), types, clusters}, "not an HDF5 file"},
      {{hair::test::copy_with_nan(braid.extract, directory / "nan_strand.h5", "/strands/points")
            .string(),
        types, clusters},
       "/strands/points: expected finite values"},
      {{hair::test::copy_with_nan(braid.extract, directory / "nan_body.h5", "/body/vertices")
            .string(),
        types, clusters},
       "/body/vertices: expected finite values"},
      {{types, extract, clusters}, "expected hairstyle.extract"},
      {{extract, clusters, types}, "expected hairstyle.types"},
      {{extract, types, braid.middle.string()}, "expected hairstyle.clusters"},
      {{extract, types, ponytail.clusters.string()}, "another model"},
      {{extract, ponytail.types.string(), clusters}, "another model"},
      {{extract, types, clusters, "--step_h", "5"}, "step_h"},
      {{extract, types, clusters, "--strand_count", "0"}, "strand_count"},
      {{extract, types, clusters, "--continued_tip_off_scalp_h", "-0.1"},
       "continued_tip_off_scalp_h"},
      {{extract, types, clusters, "--continued_tip_off_scalp_h", "nan"},
       "continued_tip_off_scalp_h"},
      {{extract, types, clusters, "--scalp_cover_h", "1e-6"}, "no scalp triangle"},
      {{extract, types, clusters, "--standing_cover_h", "0"}, "standing_cover_h"},
      {{extract, types, clusters, "--standing_cover_h", "nan"}, "standing_cover_h"},
      {{extract, types, clusters, "--min_typed_root_scalp_share", "1.5"},
       "min_typed_root_scalp_share"},
      {{extract, types, clusters, "--gather_along_field_h", "-0.5"}, "gather_along_field_h"},
      {{extract, types, clusters, "--gather_along_field_h", "nan"}, "gather_along_field_h"},
      {{hair::test::copy_with_nan(braid.extract, directory / "nan_mesh.h5", "/mesh/vertices")
            .string(),
        types, clusters},
       "/mesh/vertices: expected finite values"},
      {{hair::test::copy_with_shorter_vector(braid.extract, directory / "short_groups.h5",
                                             "/mesh/face_group", 3)
            .string(),
        types, clusters},
       "/mesh/face_group: expected shape"},
      {{extract, types, clusters, "--follow_card_keep_h", "-0.001"}, "follow_card_keep_h"},
      {{extract, types, clusters, "--follow_card_keep_h", "nan"}, "follow_card_keep_h"},
      {{extract, types, clusters, "--follow_card_pull", "1.5"}, "follow_card_pull"},
      {{extract, types}, "CLUSTERS_H5"},
  };
  hair::test::expect_clean_failures(kBin / "grow", "grow", cases, directory / "failures",
                                    braid.clusters);
}

TEST_F(GrowCli, ReportPrintsAHeaderAndOneRowPerRun) {
  const Outputs braid = sample("braid01", true);
  const fs::path report = kBin / "hair-grow-report";
  auto header = run_command(report, {"--header"});
  EXPECT_EQ(header.exit_code, 0) << header.err;
  std::vector<std::string> header_lines = text_lines(header.out);
  ASSERT_EQ(header_lines.size(), 2u) << header.out;
  EXPECT_TRUE(header_lines[0].starts_with("| model | strands | points |")) << header_lines[0];
  EXPECT_TRUE(header_lines[1].starts_with("|---|")) << header_lines[1];

  auto row = run_command(report, {braid.extract.string(), braid.strands.string(), "--name",
                                  "braid01", "--samples", "500"});
  EXPECT_EQ(row.exit_code, 0) << row.err;
  std::vector<std::string> row_lines = text_lines(row.out);
  ASSERT_EQ(row_lines.size(), 1u) << row.out;
  std::printf("[ grow     ] %s\n", row_lines[0].c_str());
  int64_t points =
      hair::read_grown_strands(hair::h5::File::open_read_only(braid.strands)).strands.point_count();
  EXPECT_TRUE(row_lines[0].starts_with("| braid01 | 2000 | " + std::to_string(points) + " | "))
      << row_lines[0];
  // As many columns as the header.
  EXPECT_EQ(std::count(row_lines[0].begin(), row_lines[0].end(), '|'),
            std::count(header_lines[0].begin(), header_lines[0].end(), '|'));
  // The kinked strands' cell, "a% (b% / c%)": the hairpins' share b. No step of a grown
  // strand turns by more than 90 degrees (max_turn_deg), where braid01's field flips
  // between its crossing pieces or a strand hands over from the field to a bridge or a
  // piece: under 1% of strands has a hairpin (a point pushed back out of the body can
  // still make one).
  const std::string kinked_cell = row_lines[0].substr(
      row_lines[0].rfind('|', row_lines[0].rfind('|', row_lines[0].size() - 2) - 1));
  const size_t open = kinked_cell.find('(');
  ASSERT_NE(open, std::string::npos) << kinked_cell;
  EXPECT_LT(std::stod(kinked_cell.substr(open + 1)), 1.0) << kinked_cell;

  // --clusters: a table of the strands of every cluster, adding up to all the strands.
  auto clusters = run_command(
      report, {braid.extract.string(), braid.strands.string(), "--name", "braid01", "--clusters"});
  EXPECT_EQ(clusters.exit_code, 0) << clusters.err;
  std::vector<std::string> cluster_lines = text_lines(clusters.out);
  const auto per_cluster = hair::h5::read_vector<int64_t>(
      hair::h5::File::open_read_only(braid.strands), "/clusters/strand_count");
  ASSERT_EQ(cluster_lines.size(), per_cluster.size() + 2) << clusters.out;
  int64_t listed = 0;
  for (size_t c = 0; c < per_cluster.size(); ++c) {
    const std::string& line = cluster_lines[c + 2];
    EXPECT_TRUE(
        line.starts_with("| " + std::to_string(c) + " | " + std::to_string(per_cluster[c]) + " | "))
        << line;
    listed += per_cluster[c];
  }
  EXPECT_EQ(listed, 2000);

  // --by-rule: the segments "grown along flow" judges, by how each was grown; weighted by
  // their counts, the three rules' shares along give that column's figure.
  const std::filesystem::path kinked_file = directory() / "kinked.txt";
  auto by_rule = run_command(report, {braid.extract.string(), braid.strands.string(), "--name",
                                      "braid01", "--by-rule", "--kinked", kinked_file.string()});
  EXPECT_EQ(by_rule.exit_code, 0) << by_rule.err;
  std::vector<std::string> rule_lines = text_lines(by_rule.out);
  // The flow table (9 lines), a blank line, and the air chords by rule (6 lines).
  ASSERT_EQ(rule_lines.size(), 16u) << by_rule.out;
  auto cells = [](const std::string& line) {
    std::vector<std::string> out;
    std::stringstream stream(line);
    for (std::string cell; std::getline(stream, cell, '|');) {
      cell.erase(0, cell.find_first_not_of(' '));
      cell.erase(cell.find_last_not_of(' ') + 1);
      out.push_back(cell);
    }
    return out;  // out[0] is the empty text before the first '|'
  };
  double judged = 0, along = 0;
  for (const char* rule : {"along the field", "along input strands", "bridges between strands"}) {
    const auto row_of_rule = std::find_if(rule_lines.begin(), rule_lines.end(), [&](const auto& l) {
      return l.starts_with(std::string("| ") + rule + " |");
    });
    ASSERT_NE(row_of_rule, rule_lines.end()) << rule << "\n" << by_rule.out;
    const std::vector<std::string> row_cells = cells(*row_of_rule);
    const double count = std::stod(row_cells[2]);
    judged += count;
    if (row_cells[4] != "-") along += count * std::stod(row_cells[4]) / 100;
  }
  ASSERT_GT(judged, 0);
  const std::vector<std::string> measures = cells(row_lines[0]);
  EXPECT_NEAR(100 * along / judged, std::stod(measures[10]), 0.1) << by_rule.out << row_lines[0];
  // The air chords by rule sum to all of them, the share the row's kinks column gives
  // ("kinked% (hairpins% / air chords%)").
  int64_t chords_by_rule = 0;
  for (size_t i = 12; i < 15; ++i) chords_by_rule += std::stoll(cells(rule_lines[i])[2]);
  const std::vector<std::string> all_chords = cells(rule_lines[15]);
  ASSERT_EQ(all_chords[1], "all") << by_rule.out;
  EXPECT_EQ(chords_by_rule, std::stoll(all_chords[2])) << by_rule.out;
  const std::string& kinks = measures[13];
  const double row_chord_share = std::stod(kinks.substr(kinks.find('/') + 1));
  EXPECT_NEAR(std::stod(all_chords[3]), row_chord_share, 0.005) << by_rule.out << row_lines[0];
  // --kinked: one strand index a line, increasing, as many as the row's kinked share says.
  std::ifstream kinked_in(kinked_file);
  std::vector<int64_t> kinked;
  for (int64_t s; kinked_in >> s;) kinked.push_back(s);
  const double kinked_share = std::stod(kinks.substr(0, kinks.find('%')));
  EXPECT_NEAR(100.0 * static_cast<double>(kinked.size()) / 2000, kinked_share, 0.026);
  EXPECT_TRUE(std::is_sorted(kinked.begin(), kinked.end()));
  for (const int64_t s : kinked) EXPECT_TRUE(s >= 0 && s < 2000) << s;
  // A --kinked path that cannot be written: exit 2, one line naming it, nothing printed.
  const std::string unwritable = (directory() / "missing_folder" / "kinked.txt").string();
  auto refused = run_command(report, {braid.extract.string(), braid.strands.string(),
                                      "--by-rule", "--kinked", unwritable});
  EXPECT_EQ(refused.exit_code, 2);
  ASSERT_EQ(text_lines(refused.err).size(), 1u) << refused.err;
  EXPECT_NE(refused.err.find(unwritable), std::string::npos) << refused.err;
  EXPECT_TRUE(refused.out.empty()) << refused.out;

  auto missing =
      run_command(report, {braid.extract.string(), (directory() / "missing.h5").string()});
  EXPECT_EQ(missing.exit_code, 2);
  ASSERT_EQ(text_lines(missing.err).size(), 1u) << missing.err;
  EXPECT_NE(missing.err.find("missing.h5"), std::string::npos) << missing.err;
  EXPECT_TRUE(missing.out.empty()) << missing.out;
}

}  // namespace
