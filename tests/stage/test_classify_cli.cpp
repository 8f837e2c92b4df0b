// classify as a subprocess with the model file kept in the repository (models/): on the
// braid and ponytail samples after extract to grow (10,000 strands, as the model was
// trained), a valid styles.h5 whose styles are the (braid01: braided and fixed;
// ponytail01: fixed and normal); byte-identical reruns whatever the thread count; bad
// input (exit 2, one line, no output, an existing output untouched); the picture.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "hair/grow/grow_io.h"
#include "hair/h5/attribute.h"
#include "hair/h5/dataset.h"
#include "hair/h5/enum_dataset.h"
#include "hair/h5/file.h"
#include "hair/style/hair_style.h"
#include "hair/style/style_io.h"
#include "hair/style/style_training.h"
#include "hair/synth/synth_io.h"
#include "hair/synth/synth_model.h"
#include "stage/clean_failures.h"
#include "stage/sample_pipeline.h"
#include "support/run_command.h"

namespace {

namespace fs = std::filesystem;
using hair::test::kBin;
using hair::test::kSamples;
using hair::test::read_file_bytes;
using hair::test::run_command;
using hair::test::run_stage;
using hair::test::SampleOutputs;
using hair::test::TemporaryDirectory;
using hair::test::text_lines;

// The default model (Makefile.pipeline's STYLE_MODEL) and the one on the paper's features.
const fs::path kModel = fs::path(HAIR_SOURCE_DIR) / "models" / "style_extended.yml";
const fs::path kPaperModel = fs::path(HAIR_SOURCE_DIR) / "models" / "style_paper.yml";

class ClassifyCli : public ::testing::Test {
 protected:
  static void TearDownTestSuite() { directory_.reset(); }
  static const TemporaryDirectory& directory() {
    if (!directory_) directory_ = std::make_unique<TemporaryDirectory>("classify_cli");
    return *directory_;
  }
  /// braid01 or ponytail01 up to strands.h5 (10,000 strands).
  static SampleOutputs sample(const std::string& model) {
    return hair::test::run_sample_pipeline(directory() / model,
                                           kSamples / "hair" / (model + ".obj"), 10000);
  }
  static std::vector<std::string> inputs(const SampleOutputs& out) {
    return {out.extract.string(), out.clusters.string(), out.strands.string(), "--model",
            kModel.string()};
  }
  /// styles.h5 of a sample, made on first use.
  static fs::path styles(const SampleOutputs& out) {
    fs::path path = out.strands.parent_path() / "styles.h5";
    if (!fs::exists(path)) {
      std::vector<std::string> arguments = inputs(out);
      arguments.insert(arguments.end(), {"-o", path.string()});
      run_stage("classify", arguments);
    }
    return path;
  }

 private:
  static std::unique_ptr<TemporaryDirectory> directory_;
};
std::unique_ptr<TemporaryDirectory> ClassifyCli::directory_;

/// The styles of the clusters of a valid styles.h5, as words, and checks of its datasets.
std::multiset<std::string> styles_found(const fs::path& path) {
  auto inspect = run_command(kBin / "hair-inspect", {path.string()});
  EXPECT_EQ(inspect.exit_code, 0) << inspect.out << inspect.err;
  std::vector<std::string> report = text_lines(inspect.out);
  EXPECT_FALSE(report.empty());
  if (!report.empty()) {
    EXPECT_EQ(report.back(), "valid: hairstyle.styles v5");
  }
  hair::h5::File file = hair::h5::File::open_read_only(path);
  EXPECT_EQ(hair::h5::read_string_attribute(file, "/", "stage"), "classify");
  EXPECT_EQ(hair::h5::read_string_attribute(file, "/", "classifier"), "svm");
  std::vector<int8_t> style = hair::read_cluster_styles(file);
  std::vector<int64_t> strands = hair::h5::read_vector<int64_t>(file, "/clusters/strand_count");
  std::multiset<std::string> words;
  for (size_t c = 0; c < style.size(); ++c) {
    EXPECT_EQ(style[c] < 0, strands[c] == 0) << "cluster " << c;
    if (style[c] >= 0) words.insert(hair::hair_style_name(static_cast<hair::HairStyle>(style[c])));
  }
  return words;
}

TEST_F(ClassifyCli, TheBraidHasABraidedAndAFixedCluster) {
  std::multiset<std::string> words = styles_found(styles(sample("braid01")));
  EXPECT_GE(words.count("braided"), 1u);
  EXPECT_GE(words.count("fixed"), 1u);
}

TEST_F(ClassifyCli, ThePonytailHasAFixedCapAndANormalTail) {
  std::multiset<std::string> words = styles_found(styles(sample("ponytail01")));
  EXPECT_GE(words.count("fixed"), 1u);
  EXPECT_GE(words.count("normal"), 1u);
  EXPECT_EQ(words.count("braided"), 0u);
}

TEST_F(ClassifyCli, ThePapersFeaturesModelClassifiesThePonytailToo) {
  const SampleOutputs ponytail = sample("ponytail01");
  fs::path path = directory() / "paper.h5";
  run_stage("classify",
            {ponytail.extract.string(), ponytail.clusters.string(), ponytail.strands.string(),
             "--model", kPaperModel.string(), "-o", path.string()});
  std::multiset<std::string> words = styles_found(path);
  EXPECT_GE(words.count("fixed"), 1u);
  EXPECT_GE(words.count("normal"), 1u);
  EXPECT_EQ(hair::h5::read_string_attribute(hair::h5::File::open_read_only(path), "/",
                                            "model_feature_set"),
            "paper");
}

TEST_F(ClassifyCli, ReproducibleRunsAreByteIdenticalWhateverTheThreadCount) {
  const SampleOutputs braid = sample("braid01");
  const std::string first = read_file_bytes(styles(braid));
  for (const char* threads : {"1", "2"}) {
    fs::path again = directory() / "again.h5";
    std::vector<std::string> arguments = inputs(braid);
    arguments.insert(arguments.end(), {"--threads", threads, "-o", again.string()});
    run_stage("classify", arguments);
    EXPECT_TRUE(read_file_bytes(again) == first) << threads << " thread(s) wrote other bytes";
    fs::remove(again);
  }
}

TEST_F(ClassifyCli, DrawsTheStylesInThePapersColours) {
  const SampleOutputs ponytail = sample("ponytail01");
  fs::path png = directory() / "styles.png";
  auto result =
      run_command(kBin / "hair-render",
                  {styles(ponytail).string(), "--strands", ponytail.strands.string(), "--extract",
                   ponytail.extract.string(), "--size", "128", "-o", png.string()});
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_GT(fs::file_size(png), 1000u);
  auto no_strands = run_command(
      kBin / "hair-render",
      {styles(ponytail).string(), "--extract", ponytail.extract.string(), "-o", png.string()});
  EXPECT_EQ(no_strands.exit_code, 2);
  EXPECT_NE(no_strands.err.find("needs --strands"), std::string::npos) << no_strands.err;
}

TEST_F(ClassifyCli, EveryClusterCarriesItsConfidenceAndTheUnsureOnesAreMarked) {
  const SampleOutputs ponytail = sample("ponytail01");
  // The checks of one styles.h5 made with `unsure_below`; returns how many clusters the
  // criteria decided and how many are unsure.
  const auto check = [](const fs::path& path, double unsure_below) {
    hair::h5::File file = hair::h5::File::open_read_only(path);
    const std::vector<int8_t> style = hair::read_cluster_styles(file);
    const std::vector<int8_t> svm_style =
        hair::h5::read_enum_dataset(file, "/clusters/svm_style", hair::style_members());
    const hair::StyleCertainty certainty = hair::read_style_certainty(file);
    const auto decision =
        hair::h5::read_matrix<double, Eigen::Dynamic>(file, "/clusters/svm_decision_values");
    const std::vector<int8_t> classes =
        hair::h5::read_enum_dataset(file, "/classes/style", hair::style_members());
    const auto not_fixed = hair::h5::read_vector<uint8_t>(file, "/clusters/fixed_ruled_out");
    const auto root_share = hair::h5::read_vector<double>(file, "/features/root_share");
    const auto tip_share = hair::h5::read_vector<double>(file, "/features/tip_share");
    const auto gathering = hair::h5::read_vector<double>(file, "/features/gathering_ratio");
    EXPECT_DOUBLE_EQ(certainty.unsure_below, unsure_below);
    int ruled = 0, unsure = 0;
    const auto fixed = static_cast<int8_t>(hair::HairStyle::fixed);
    for (size_t c = 0; c < style.size(); ++c) {
      SCOPED_TRACE("cluster " + std::to_string(c));
      EXPECT_EQ(certainty.pinned[c], 0);
      // Fixed is ruled out where the strands start at the roots and end in the cluster
      // without gathering (the default thresholds); the style is then never fixed.
      if (style[c] >= 0) {
        EXPECT_EQ(not_fixed[c],
                  root_share[c] >= 0.9 && tip_share[c] >= 0.9 && gathering[c] >= 0.5 ? 1 : 0);
        if (not_fixed[c] && !certainty.ruled[c]) {
          EXPECT_NE(style[c], fixed);
        }
      }
      if (style[c] < 0) {
        EXPECT_EQ(certainty.confidence[c], 0.0);
        EXPECT_EQ(certainty.unsure[c], 0);
        EXPECT_EQ(certainty.ruled[c], 0);
        continue;
      }
      if (certainty.ruled[c]) {  // the paper's criteria decided: sure
        ++ruled;
        EXPECT_EQ(certainty.confidence[c], 1.0);
        EXPECT_EQ(certainty.unsure[c], 0);
        continue;
      }
      // The SVM's margin: the smallest decision value of the contests of the style it
      // gave, signed for it (pairs i < j in order, > 0 for i), within [0, 1]; where fixed is
      // ruled out, over the contests against the other styles.
      if (!not_fixed[c] || svm_style[c] != fixed) {
        EXPECT_EQ(style[c], svm_style[c]);
      }
      const auto k = std::find(classes.begin(), classes.end(), style[c]) - classes.begin();
      const auto out = not_fixed[c]
                           ? std::find(classes.begin(), classes.end(), fixed) - classes.begin()
                           : static_cast<Eigen::Index>(classes.size());
      double margin = 1.0;
      Eigen::Index pair = 0;
      for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(classes.size()); ++i)
        for (Eigen::Index j = i + 1; j < static_cast<Eigen::Index>(classes.size()); ++j, ++pair) {
          if (i == out || j == out) continue;
          const double value = decision(static_cast<Eigen::Index>(c), pair);
          if (i == k) margin = std::min(margin, value);
          if (j == k) margin = std::min(margin, -value);
        }
      EXPECT_DOUBLE_EQ(certainty.confidence[c], std::clamp(margin, 0.0, 1.0));
      EXPECT_EQ(certainty.unsure[c], certainty.confidence[c] < unsure_below ? 1 : 0);
      unsure += certainty.unsure[c];
    }
    return std::pair{ruled, unsure};
  };
  // By default (unsure below 0.6): ponytail01's cap, gathered into the band, is decided by
  // the fixed rule; every cluster's flag follows its confidence.
  const auto [ruled, unsure] = check(styles(ponytail), 0.6);
  EXPECT_GE(ruled, 1);
  std::printf("[ classify ] ponytail01: %d clusters decided by the criteria, %d unsure\n", ruled,
              unsure);

  // Hair it has not seen: hair-synth's low tail at a seed outside the corpus's. Asked to be
  // surer than its least sure cluster, no cluster becomes surer, the same ones are decided
  // by the criteria, and the log lists the unsure ones.
  const fs::path data = directory() / "unseen";
  fs::create_directories(data);
  auto synth = run_command(kBin / "hair-synth",
                           {"--preset", "low_tail", "--vary", "--seed", "7101", "-o", data.string(),
                            "--body", (kSamples / "body.obj").string(), "--reproducible"});
  ASSERT_EQ(synth.exit_code, 0) << synth.err;
  const SampleOutputs unseen = hair::test::run_sample_pipeline(directory() / "unseen_low_tail",
                                                               data / "low_tail.obj", 10000);
  const auto [ruled_default, unsure_default] = check(styles(unseen), 0.6);
  // The least confidence of a cluster the classifier decided, on either mesh.
  double least = 1.0;
  const SampleOutputs* least_of = &unseen;
  for (const SampleOutputs* outputs : {&unseen, &ponytail}) {
    hair::h5::File file = hair::h5::File::open_read_only(styles(*outputs));
    const hair::StyleCertainty certainty = hair::read_style_certainty(file);
    const std::vector<int8_t> style = hair::read_cluster_styles(file);
    for (size_t c = 0; c < style.size(); ++c)
      if (style[c] >= 0 && !certainty.ruled[c] && certainty.confidence[c] < least) {
        least = certainty.confidence[c];
        least_of = outputs;
      }
  }
  ASSERT_LT(least, 1.0) << "every classified cluster of both meshes is sure to a full margin";
  std::printf("[ classify ] the least sure cluster: %.6f (%s)\n", least,
              least_of == &unseen ? "the unseen low tail" : "ponytail01");
  const double strict_below = std::nextafter(least, 2.0);
  const auto exact = [](double value) {  // reads back as the same double
    std::ostringstream text;
    text.precision(17);
    text << value;
    return text.str();
  };
  const fs::path strict = least_of->strands.parent_path() / "styles_strict.h5";
  std::vector<std::string> arguments = inputs(*least_of);
  arguments.insert(arguments.end(), {"--unsure_below", exact(strict_below), "-o", strict.string()});
  auto run = run_command(kBin / "classify", arguments);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto [ruled_strict, unsure_strict] = check(strict, strict_below);
  const auto [ruled_before, unsure_before] =
      least_of == &unseen ? std::pair{ruled_default, unsure_default} : std::pair{ruled, unsure};
  EXPECT_EQ(ruled_strict, ruled_before);
  EXPECT_GE(unsure_strict, unsure_before);
  EXPECT_GE(unsure_strict, 1);
  EXPECT_NE((run.out + run.err).find("unsure"), std::string::npos) << run.out << run.err;
}

TEST_F(ClassifyCli, APinnedClusterTakesTheUsersStyleAndTheFileSaysSo) {
  const SampleOutputs ponytail = sample("ponytail01");
  hair::h5::File classified = hair::h5::File::open_read_only(styles(ponytail));
  const std::vector<int8_t> before = hair::read_cluster_styles(classified);
  // The cluster with most strands, pinned to a style other than its own; and a second
  // cluster by a point of its grown strands.
  const std::vector<int64_t> strands =
      hair::h5::read_vector<int64_t>(classified, "/clusters/strand_count");
  const auto biggest =
      static_cast<size_t>(std::max_element(strands.begin(), strands.end()) - strands.begin());
  const int8_t other = before[biggest] == 1 ? 0 : 1;  // fixed, or normal if it was fixed
  const hair::GrownStrands grown =
      hair::read_grown_strands(hair::h5::File::open_read_only(ponytail.strands));
  const auto& point_cluster =
      std::get<std::vector<int32_t>>(grown.strands.point_attributes.at("cluster"));
  int64_t point = -1;
  for (int64_t p = 0; p < grown.strands.point_count(); ++p)
    if (point_cluster[static_cast<size_t>(p)] != static_cast<int32_t>(biggest) &&
        before[static_cast<size_t>(point_cluster[static_cast<size_t>(p)])] >= 0) {
      point = p;
      break;
    }
  ASSERT_GE(point, 0);
  const auto second = static_cast<size_t>(point_cluster[static_cast<size_t>(point)]);
  const Eigen::Vector3f at =
      grown.strands.points.row(point).transpose() + Eigen::Vector3f(0.001f, 0, 0);
  const fs::path overrides = directory() / "pins.toml";
  hair::test::write_text_file(
      overrides, "# pins\n[[pin]]\ncluster = " + std::to_string(biggest) + "\nstyle = \"" +
                     hair::hair_style_name(static_cast<hair::HairStyle>(other)) +
                     "\"\n\n[[pin]]\npoint_m = [" + std::to_string(at.x()) + ", " +
                     std::to_string(at.y()) + ", " + std::to_string(at.z()) +
                     "]\nstyle = \"short\"\n");
  const fs::path path = directory() / "pinned.h5";
  std::vector<std::string> arguments = inputs(ponytail);
  arguments.insert(arguments.end(), {"--overrides", overrides.string(), "-o", path.string()});
  arguments.push_back("--reproducible");
  const auto run = run_command(kBin / "classify", arguments);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("cluster " + std::to_string(biggest) + " pinned"), std::string::npos)
      << run.err;
  hair::h5::File file = hair::h5::File::open_read_only(path);
  const std::vector<int8_t> after = hair::read_cluster_styles(file);
  const hair::StyleCertainty certainty = hair::read_style_certainty(file);
  const std::vector<int8_t> forest =
      hair::h5::read_enum_dataset(file, "/clusters/forest_style", hair::style_members());
  for (size_t c = 0; c < after.size(); ++c) {
    SCOPED_TRACE("cluster " + std::to_string(c));
    if (c == biggest) {
      EXPECT_EQ(after[c], other);
      EXPECT_EQ(certainty.pinned[c], 1);
      EXPECT_EQ(certainty.unsure[c], 0);
      EXPECT_EQ(forest[c], before[c]);  // the classifier's own answer stays
    } else if (c == second) {
      EXPECT_EQ(after[c], 2);  // short
      EXPECT_EQ(certainty.pinned[c], 1);
    } else {
      EXPECT_EQ(after[c], before[c]);
      EXPECT_EQ(certainty.pinned[c], 0);
    }
  }
  // Provenance: the overrides file is an input, with its digest.
  const std::string provenance = hair::h5::read_string_attribute(file, "/", "inputs");
  EXPECT_NE(provenance.find("\"overrides\""), std::string::npos) << provenance;
  EXPECT_NE(provenance.find("pins.toml"), std::string::npos) << provenance;
  // The picture lists the pinned clusters.
  const fs::path png = directory() / "pinned.png";
  auto drawn = run_command(kBin / "hair-render",
                           {path.string(), "--strands", ponytail.strands.string(), "--extract",
                            ponytail.extract.string(), "--size", "128", "-o", png.string()});
  EXPECT_EQ(drawn.exit_code, 0) << drawn.err;
}

TEST_F(ClassifyCli, ThePipelineTakesAModelsPinsWhenItHasSomeAndRerunsOnlyClassify) {
  // A DATA folder with braid01's mesh and body, and its OUT folder up to date (the
  // fixture's files, each newer than what it is made from). `make -n` then has nothing to
  // do; a pins file in DATA/overrides makes it rerun classify alone, with --overrides.
  const SampleOutputs braid = sample("braid01");
  const fs::path root = directory() / "make";
  const fs::path data = root / "data", out = root / "out" / "braid01";
  fs::create_directories(data / "hair");
  fs::create_directories(out);
  fs::copy_file(kSamples / "hair" / "braid01.obj", data / "hair" / "braid01.obj");
  fs::copy_file(kSamples / "body.obj", data / "body.obj");
  const fs::path made[] = {braid.extract,  braid.types,   braid.middle,
                           braid.clusters, braid.strands, styles(braid)};
  auto when = fs::file_time_type::clock::now() + std::chrono::seconds(10);
  for (const fs::path& file : made) {
    fs::copy_file(file, out / file.filename());
    fs::last_write_time(out / file.filename(), when += std::chrono::seconds(1));
  }
  const std::vector<std::string> make = {
      "-n",
      "-f",
      (fs::path(HAIR_SOURCE_DIR) / "Makefile.pipeline").string(),
      "DATA=" + data.string(),
      "OUT=" + (root / "out").string(),
      "BIN=" + kBin.string(),
      "PARAMS=" + (fs::path(HAIR_SOURCE_DIR) / "pipelines" / "default").string(),
      "STYLE_MODEL=" + kModel.string(),
      (out / "styles.h5").string()};
  auto before = run_command("/usr/bin/make", make, HAIR_SOURCE_DIR);
  ASSERT_EQ(before.exit_code, 0) << before.err;
  EXPECT_NE(before.out.find("is up to date"), std::string::npos) << before.out;
  EXPECT_EQ(before.out.find("--model"), std::string::npos) << before.out;
  fs::create_directories(data / "overrides");
  hair::test::write_text_file(data / "overrides" / "braid01.toml",
                              "[[pin]]\ncluster = 0\nstyle = \"fixed\"\n");
  fs::last_write_time(data / "overrides" / "braid01.toml", when += std::chrono::seconds(1));
  auto after = run_command("/usr/bin/make", make, HAIR_SOURCE_DIR);
  ASSERT_EQ(after.exit_code, 0) << after.err;
  const std::vector<std::string> commands = text_lines(after.out);
  ASSERT_EQ(commands.size(), 1u) << after.out;
  EXPECT_NE(commands[0].find("/classify "), std::string::npos) << commands[0];
  EXPECT_NE(commands[0].find("--overrides " + (data / "overrides" / "braid01.toml").string()),
            std::string::npos)
      << commands[0];
}

/// A copy of the model file with its text changed by `edit`.
fs::path edited_model(const fs::path& copy, const std::string& from, const std::string& to) {
  std::ifstream stream(kModel);
  std::stringstream text;
  text << stream.rdbuf();
  std::string content = text.str();
  auto at = content.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) content.replace(at, from.size(), to);
  hair::test::write_text_file(copy, content);
  return copy;
}

/// Per true style (HairStyle value), the strands of a synthetic model's clusters of that
/// style (their majority, as hair-train-style labels them) and those classified so.
struct StrandsByTruth {
  std::map<int, int64_t> strands, right;
  double share_right(int style) const {
    auto found = strands.find(style);
    return found == strands.end() || found->second == 0
               ? -1
               : static_cast<double>(right.at(style)) / static_cast<double>(found->second);
  }
};

StrandsByTruth strands_by_truth(const SampleOutputs& out, const fs::path& truth_path,
                                const fs::path& styles_path) {
  hair::h5::File extract = hair::h5::File::open_read_only(out.extract);
  hair::h5::File truth = hair::h5::File::open_read_only(truth_path);
  hair::StyleFeatureInput input =
      hair::read_style_feature_input(extract, hair::h5::File::open_read_only(out.clusters),
                                     hair::h5::File::open_read_only(out.strands));
  auto group_count = static_cast<int32_t>(input.group_cluster.size());
  std::vector<int8_t> group_style = hair::group_styles_from_truth(
      hair::h5::read_vector<int64_t>(extract, "/mesh/face_offsets"),
      hair::h5::read_vector<int32_t>(extract, "/mesh/face_vertices"),
      hair::h5::read_vector<int32_t>(extract, "/mesh/face_group"), group_count,
      hair::h5::read_vector<int64_t>(truth, "/patches/first_vertex"),
      hair::h5::read_enum_values(truth, "/patches/style"));
  std::vector<int32_t> faces = hair::h5::read_vector<int32_t>(extract, "/groups/face_count");
  std::vector<int8_t> label = hair::cluster_styles_by_majority(
      input.group_cluster, group_style, std::vector<double>(faces.begin(), faces.end()),
      input.cluster_count);
  hair::h5::File styles = hair::h5::File::open_read_only(styles_path);
  std::vector<int8_t> style = hair::read_cluster_styles(styles);
  std::vector<int64_t> strands = hair::h5::read_vector<int64_t>(styles, "/clusters/strand_count");
  StrandsByTruth result;
  for (size_t c = 0; c < style.size(); ++c) {
    if (label[c] < 0 || strands[c] == 0) continue;
    result.strands[label[c]] += strands[c];
    result.right[label[c]] += style[c] == label[c] ? strands[c] : 0;
  }
  return result;
}

/// hair-synth's model of `spec` at seed 7101 (not one of the training corpus's, 1000-1089
/// and 2000-2089), written as `name`.obj beside its truth into `work`/`name`.data, then
/// through the pipeline to strands.h5 (in `work`/`name`): the outputs and the truth file.
/// Throws std::runtime_error with hair-synth's message when it fails.
std::pair<SampleOutputs, fs::path> unseen_model(const fs::path& work,
                                                const hair::synth::HairStyleSpec& spec,
                                                const std::string& name) {
  const fs::path data = work / (name + ".data");
  fs::create_directories(data);
  hair::test::write_text_file(data / "spec.json", hair::synth::spec_json(spec).dump(2));
  auto synth =
      run_command(kBin / "hair-synth",
                  {"--spec", (data / "spec.json").string(), "--seed", "7101", "--name", name, "-o",
                   data.string(), "--body", (kSamples / "body.obj").string(), "--reproducible"});
  if (synth.exit_code != 0) throw std::runtime_error("hair-synth: " + synth.err);
  return {hair::test::run_sample_pipeline(work / name, data / (name + ".obj"), 10000),
          data / (name + ".truth.h5")};
}

TEST_F(ClassifyCli, ThePaintedPresetsGetTheStylesTheirTruthSays) {
  // The kinds of community meshes (hair-synth's painted presets) with a seed the shipped
  // model was not trained on (the corpus's are 1000-1089 and 2000-2089): a bun and the
  // cap under a band are fixed, the low tail and the ringlet tubes normal, the mohawk's
  // spikes short (the check), each on at least 80% of its strands.
  const fs::path data = directory() / "painted";
  fs::create_directories(data);
  struct Expectation {
    std::string preset;
    std::vector<hair::HairStyle> styles;
  };
  const std::vector<Expectation> expectations = {
      {"bun", {hair::HairStyle::fixed}},
      {"low_tail", {hair::HairStyle::fixed, hair::HairStyle::normal}},
      {"ringlets", {hair::HairStyle::normal}},
      {"mohawk", {hair::HairStyle::short_hair}}};
  for (const Expectation& expectation : expectations) {
    auto synth =
        run_command(kBin / "hair-synth",
                    {"--preset", expectation.preset, "--vary", "--seed", "7101", "-o",
                     data.string(), "--body", (kSamples / "body.obj").string(), "--reproducible"});
    ASSERT_EQ(synth.exit_code, 0) << synth.err;
    SampleOutputs out = hair::test::run_sample_pipeline(
        directory() / expectation.preset, data / (expectation.preset + ".obj"), 10000);
    fs::path path = styles(out);
    StrandsByTruth found = strands_by_truth(out, data / (expectation.preset + ".truth.h5"), path);
    for (hair::HairStyle style : expectation.styles) {
      double share = found.share_right(static_cast<int>(style));
      std::printf("[ painted  ] %s: %s clusters %.1f%% right (%lld strands)\n",
                  expectation.preset.c_str(), hair::hair_style_name(style), 100 * share,
                  static_cast<long long>(found.strands[static_cast<int>(style)]));
      EXPECT_GE(share, 0.8) << expectation.preset << ": " << hair::hair_style_name(style);
    }
  }
}

TEST_F(ClassifyCli, ALooseLowTailsCapIsFixed) {
  // hair-synth's loose, low, full tail (cap_volume_m 3 cm, cap_drape: the family drawn into
  // the training corpus for braid01's cap) at a seed the shipped model was not trained on:
  // the cap stands off the head, falls over the ears and is still hair gathered into a
  // band, fixed, on at least 80% of its strands (96.7% at this seed with the models of
  // 2026-11-27, 100% with those before; 96-100% at seeds
  // 7101-7104). Its thin tail is not asked: grow ends most cap strands at the band.
  hair::synth::HairStyleSpec spec = hair::synth::varied_spec(hair::synth::preset("low_tail"), 7101);
  spec.components[0].cap_volume_m = 0.03;
  spec.components[0].cap_drape = true;
  spec.components[0].band_polar_deg = 100;
  const auto [out, truth] = unseen_model(directory().path(), spec, "loose_low_tail");
  StrandsByTruth found = strands_by_truth(out, truth, styles(out));
  const double share = found.share_right(static_cast<int>(hair::HairStyle::fixed));
  std::printf("[ loose    ] low_tail, loose: fixed clusters %.1f%% right (%lld strands)\n",
              100 * share,
              static_cast<long long>(found.strands[static_cast<int>(hair::HairStyle::fixed)]));
  EXPECT_GE(share, 0.8);
}

TEST_F(ClassifyCli, AWovenBraidFromALooseCapIsBraidedUnderAFixedCap) {
  // A braid as braid01's is made (hair-synth's braid knobs, drawn into the training corpus
  // for it): its lobes woven from four cards each, narrowing to half its width, its top
  // lifted off the head where a loose cap gathers, at a seed the shipped model was not
  // trained on. The braid is braided and the cap fixed, each on at least 80% of its
  // strands (both are classified so at seeds 7101-7103, loose or close).
  hair::synth::HairStyleSpec spec = hair::synth::varied_spec(hair::synth::preset("braid"), 7101);
  hair::synth::ComponentSpec& braid = spec.components[0];
  braid.braid_cards_per_lobe = 4;
  braid.braid_tip_width_share = 0.5;
  braid.cap_volume_m = 0.03;
  braid.cap_drape = true;
  braid.band_polar_deg = 100;
  braid.braid_lift_m = 0.02;
  const auto [out, truth] = unseen_model(directory().path(), spec, "woven_braid");
  StrandsByTruth found = strands_by_truth(out, truth, styles(out));
  for (hair::HairStyle style : {hair::HairStyle::braided, hair::HairStyle::fixed}) {
    const double share = found.share_right(static_cast<int>(style));
    std::printf("[ woven    ] braid from a loose cap: %s clusters %.1f%% right (%lld strands)\n",
                hair::hair_style_name(style), 100 * share,
                static_cast<long long>(found.strands[static_cast<int>(style)]));
    EXPECT_GE(share, 0.8) << hair::hair_style_name(style);
  }
}

TEST_F(ClassifyCli, WrongInputsFailCleanly) {
  const SampleOutputs braid = sample("braid01"), ponytail = sample("ponytail01");
  const TemporaryDirectory& directory = ClassifyCli::directory();
  hair::test::write_text_file(directory / "text.h5", "not HDF5\n");
  const std::string extract = braid.extract.string(), clusters = braid.clusters.string(),
                    strands = braid.strands.string(), model = kModel.string();
  const std::string version_3 =
      edited_model(directory / "v3.yml", "version: 2", "version: 3").string();
  const std::string other_format =
      edited_model(directory / "format.yml", "hairstyle.style_model", "something.else").string();
  auto pins = [&](const std::string& name, const std::string& text) {
    const fs::path path = directory / (name + ".toml");
    hair::test::write_text_file(path, text);
    return path.string();
  };
  const std::vector<hair::test::FailureCase> cases = {
      {{(directory / "missing.h5").string(), clusters, strands, "--model", model}, "missing.h5"},
      {{(directory / "text.h5").string(), clusters, strands, "--model", model}, "not an HDF5 file"},
      {{clusters, clusters, strands, "--model", model}, "expected hairstyle.extract"},
      {{extract, strands, strands, "--model", model}, "expected hairstyle.clusters"},
      {{extract, clusters, clusters, "--model", model}, "expected hairstyle.strands"},
      {{extract, ponytail.clusters.string(), strands, "--model", model}, "another model"},
      {{extract, clusters, ponytail.strands.string(), "--model", model}, "another model"},
      {{extract, clusters, strands, "--model", (directory / "none.yml").string()}, "none.yml"},
      {{extract, clusters, strands, "--model", version_3}, "version 3"},
      {{extract, clusters, strands, "--model", other_format}, "format"},
      {{extract, clusters, strands, "--model", model, "--classifier", "knn"}, "classifier"},
      {{extract, clusters, strands, "--model", model, "--short_tip_share", "2"}, "short_tip_share"},
      {{extract, clusters, strands, "--model", model, "--ungathered_gathering_ratio", "1.5"},
       "ungathered_gathering_ratio"},
      {{extract, clusters, strands, "--model", model, "--fixed_far_scalp_distance_h", "-0.1"},
       "fixed_far_scalp_distance_h"},
      {{extract, clusters, strands}, "--model"},
      {{extract, clusters, strands, "--model", model, "--overrides",
        (directory / "no.toml").string()},
       "no.toml"},
      {{extract, clusters, strands, "--model", model, "--overrides",
        pins("unknown_cluster", "[[pin]]\ncluster = 999\nstyle = \"fixed\"\n")},
       "no cluster 999"},
      {{extract, clusters, strands, "--model", model, "--overrides",
        pins("unknown_style", "[[pin]]\ncluster = 0\nstyle = \"curly\"\n")},
       "style must be one of"},
      {{extract, clusters, strands, "--model", model, "--overrides",
        pins("malformed", "[[pin]\ncluster = 0\n")},
       "not TOML"},
      {{extract, clusters, strands, "--model", model, "--overrides",
        pins("both", "[[pin]]\ncluster = 0\npoint_m = [0, 1.6, 0]\nstyle = \"fixed\"\n")},
       "either cluster or point_m"},
      {{extract, clusters, strands, "--model", model, "--overrides",
        pins("far_point", "[[pin]]\npoint_m = [5, 5, 5]\nstyle = \"fixed\"\n")},
       "no grown strand within"},
      {{extract, clusters, strands, "--model", model, "--overrides",
        pins("unknown_key", "[[pin]]\ncluster = 0\nstyle = \"fixed\"\ncolour = \"red\"\n")},
       "unknown key 'colour'"},
      {{extract, clusters, strands, "--model", model, "--overrides",
        pins("top_key", "style = \"fixed\"\n")},
       "unknown key 'style'"},
      {{extract, clusters, strands, "--model", model, "--overrides",
        pins(
            "disagree",
            "[[pin]]\ncluster = 1\nstyle = \"fixed\"\n[[pin]]\ncluster = 1\nstyle = \"normal\"\n")},
       "pinned already"},
  };
  hair::test::expect_clean_failures(kBin / "classify", "classify", cases, directory / "failures",
                                    braid.clusters);
}

}  // namespace
