// classify as a subprocess with the model file kept in the repository (models/): on the
// braid and ponytail samples after extract to grow (10,000 strands, as the model was
// trained), a valid styles.h5 whose styles are the (braid01: braided and fixed;
// ponytail01: fixed and normal); byte-identical reruns whatever the thread count; bad
// input (exit 2, one line, no output, an existing output untouched); the picture.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "hair/h5/attribute.h"
#include "hair/h5/dataset.h"
#include "hair/h5/file.h"
#include "hair/style/hair_style.h"
#include "hair/style/style_io.h"
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
    EXPECT_EQ(report.back(), "valid: hairstyle.styles v2");
  }
  hair::h5::File file = hair::h5::File::open_read_only(path);
  EXPECT_EQ(hair::h5::read_string_attribute(file, "/", "stage"), "classify");
  EXPECT_EQ(hair::h5::read_string_attribute(file, "/", "classifier"), "random_forest");
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

TEST_F(ClassifyCli, WrongInputsFailCleanly) {
  const SampleOutputs braid = sample("braid01"), ponytail = sample("ponytail01");
  const TemporaryDirectory& directory = ClassifyCli::directory();
  hair::test::write_text_file(directory / "text.h5", "not HDF5\n");
  const std::string extract = braid.extract.string(), clusters = braid.clusters.string(),
                    strands = braid.strands.string(), model = kModel.string();
  const std::string version_2 =
      edited_model(directory / "v2.yml", "version: 1", "version: 2").string();
  const std::string other_format =
      edited_model(directory / "format.yml", "hairstyle.style_model", "something.else").string();
  const std::vector<hair::test::FailureCase> cases = {
      {{(directory / "missing.h5").string(), clusters, strands, "--model", model}, "missing.h5"},
      {{(directory / "text.h5").string(), clusters, strands, "--model", model}, "not an HDF5 file"},
      {{clusters, clusters, strands, "--model", model}, "expected hairstyle.extract"},
      {{extract, strands, strands, "--model", model}, "expected hairstyle.clusters"},
      {{extract, clusters, clusters, "--model", model}, "expected hairstyle.strands"},
      {{extract, ponytail.clusters.string(), strands, "--model", model}, "another model"},
      {{extract, clusters, ponytail.strands.string(), "--model", model}, "another model"},
      {{extract, clusters, strands, "--model", (directory / "none.yml").string()}, "none.yml"},
      {{extract, clusters, strands, "--model", version_2}, "version 2"},
      {{extract, clusters, strands, "--model", other_format}, "format"},
      {{extract, clusters, strands, "--model", model, "--classifier", "knn"}, "classifier"},
      {{extract, clusters, strands}, "--model"},
  };
  hair::test::expect_clean_failures(kBin / "classify", "classify", cases, directory / "failures",
                                    braid.clusters);
}

}  // namespace
