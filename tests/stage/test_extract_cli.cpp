// Stage tests of the extract binary, run as a subprocess the way make runs it: exit
// status, the one-line error, no partial or temporary output on failure (DESIGN.md,
// contract 1), valid and reproducible outputs on the sample and MakeHuman meshes, and
// glTF input. Each test works in its own temporary directory.
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <numbers>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "hair/h5/dataset.h"
#include "hair/h5/file.h"
#include "support/run_command.h"

namespace {

namespace fs = std::filesystem;
using hair::test::CommandResult;
using hair::test::run_command;
using hair::test::TemporaryDirectory;
using hair::test::text_lines;

const fs::path kExtract = fs::path(HAIR_BIN_DIR) / "extract";
const fs::path kInspect = fs::path(HAIR_BIN_DIR) / "hair-inspect";
const fs::path kSamples = fs::path(HAIR_SOURCE_DIR) / "data" / "samples";
const fs::path kSampleBody = kSamples / "body.obj";
const fs::path kMakeHuman = fs::path(HAIR_SHARED_DATA_DIR) / "makehuman";

/// The running test's name, for its temporary directory.
std::string current_test_name() {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return info != nullptr ? info->name() : "test";
}

/// For assertion messages: how a command ended and what it printed on stderr.
std::string describe(const CommandResult& result) {
  return "exit " + std::to_string(result.exit_code) + ", stderr:\n" + result.err;
}

/// Number of strand groups of an extract.h5 (/groups/first_strand has #groups + 1 entries).
int64_t group_count(const fs::path& extract_file) {
  const hair::h5::File file = hair::h5::File::open_read_only(extract_file);
  return static_cast<int64_t>(hair::h5::read_vector<int32_t>(file, "/groups/first_strand").size()) -
         1;
}

/// Two hair cards (one quad wide, eight long, 36 vertices) from the crown over the back
/// of the sample body's head and down, as OBJ text in decimetres: two patches, two groups.
std::string two_hair_cards_obj() {
  std::ostringstream obj;
  obj << "# two hair cards hanging off the back of the head (decimetres)\n";
  constexpr int kRows = 9;
  const double card_x[2][2] = {{-0.5, -0.1}, {0.1, 0.5}};
  for (const auto& xs : card_x) {
    for (int row = 0; row < kRows; ++row) {
      const double t = static_cast<double>(row) / (kRows - 1);
      double y = 0, z = 0;
      if (t < 0.4) {  // a quarter circle over the back of the head
        const double angle = t / 0.4 * std::numbers::pi / 2;
        y = 7.6 + std::cos(angle);
        z = 0.6 - 1.2 * std::sin(angle);
      } else {  // then straight down the back
        y = 7.6 - (t - 0.4) / 0.6 * 2.5;
        z = -0.6 - 0.1 * (t - 0.4);
      }
      for (const double x : xs) obj << "v " << x << " " << y << " " << z << "\n";
    }
  }
  for (int card = 0; card < 2; ++card) {
    for (int row = 0; row + 1 < kRows; ++row) {
      const int first = card * 2 * kRows + 2 * row + 1;  // OBJ indices start at 1
      obj << "f " << first << " " << first + 1 << " " << first + 3 << " " << first + 2 << "\n";
    }
  }
  return obj.str();
}

class ExtractCli : public ::testing::Test {
 protected:
  /// Runs extract in the test's directory.
  CommandResult extract(const std::vector<std::string>& arguments) const {
    return run_command(kExtract, arguments, directory_.path());
  }

  /// Writes an input file into the test's directory; returns its name.
  std::string input(const std::string& name, const std::string& text) const {
    hair::test::write_text_file(directory_ / name, text);
    return name;
  }

  /// Every file in the test's directory with its content.
  std::map<std::string, std::string> directory_content() const {
    std::map<std::string, std::string> content;
    for (const std::string& name : directory_.entries()) {
      content[name] = hair::test::read_file_bytes(directory_ / name);
    }
    return content;
  }

  /// Runs extract and expects a clean failure: exit status 2, exactly one line on
  /// stderr that contains every string of `named`, and the directory as it was (no
  /// output, no temporary file, an existing output untouched).
  void expect_clean_failure(const std::vector<std::string>& arguments,
                            const std::vector<std::string>& named) const {
    const std::map<std::string, std::string> before = directory_content();
    const CommandResult result = extract(arguments);
    EXPECT_EQ(result.exit_code, 2) << describe(result);
    const std::vector<std::string> lines = text_lines(result.err);
    ASSERT_EQ(lines.size(), 1u) << describe(result);
    EXPECT_EQ(result.err.back(), '\n');
    EXPECT_TRUE(lines[0].starts_with("extract: error: ")) << lines[0];
    for (const std::string& name : named) {
      EXPECT_NE(lines[0].find(name), std::string::npos) << "'" << name << "' not in: " << lines[0];
    }
    EXPECT_EQ(directory_content(), before) << "the directory changed";
  }

  /// Runs extract on `hair_mesh` (decimetres) with `body`, expects success, a valid
  /// out.h5 with `expected_groups` groups and nothing else new in the directory.
  void expect_valid_extract(const fs::path& hair_mesh, const fs::path& body,
                            int64_t expected_groups) const {
    const std::vector<std::string> before = directory_.entries();
    const CommandResult result = extract({hair_mesh.string(), "--body", body.string(),
                                          "--unit_scale", "0.1", "--quiet", "-o", "out.h5"});
    ASSERT_EQ(result.exit_code, 0) << describe(result);

    std::vector<std::string> expected_entries = before;
    expected_entries.push_back("out.h5");
    std::sort(expected_entries.begin(), expected_entries.end());
    EXPECT_EQ(directory_.entries(), expected_entries);

    const CommandResult inspect = run_command(kInspect, {(directory_ / "out.h5").string()});
    EXPECT_EQ(inspect.exit_code, 0) << inspect.out << inspect.err;
    const std::vector<std::string> report = text_lines(inspect.out);
    ASSERT_FALSE(report.empty());
    EXPECT_EQ(report.back(), "valid: hairstyle.extract v3");
    EXPECT_EQ(group_count(directory_ / "out.h5"), expected_groups);
  }

  TemporaryDirectory directory_{"extract-" + current_test_name()};
  const std::string body_ = kSampleBody.string();
};

// A small quad mesh that extract accepts, to isolate one defect at a time.
constexpr const char* kQuadVertices = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

TEST_F(ExtractCli, MissingHairMeshFile) {
  expect_clean_failure({"nothere.obj", "--body", body_, "-o", "out.h5"}, {"nothere.obj"});
}

TEST_F(ExtractCli, NoHairMeshArgument) {
  expect_clean_failure({"--body", body_, "-o", "out.h5"}, {"HAIR_MESH"});
}

TEST_F(ExtractCli, MissingBodyOption) {
  const std::string hair = input("hair.obj", std::string(kQuadVertices) + "f 1 2 3 4\n");
  expect_clean_failure({hair, "-o", "out.h5"}, {"--body"});
}

TEST_F(ExtractCli, MissingBodyFile) {
  const std::string hair = input("hair.obj", std::string(kQuadVertices) + "f 1 2 3 4\n");
  expect_clean_failure({hair, "--body", "nobody.obj", "-o", "out.h5"}, {"nobody.obj"});
}

TEST_F(ExtractCli, UnsupportedFormat) {
  const std::string hair = input("hair.xyz", "0 0 0\n1 0 0\nnot a mesh\n");
  expect_clean_failure({hair, "--body", body_, "-o", "out.h5"}, {"hair.xyz"});
}

TEST_F(ExtractCli, EmptyFile) {
  const std::string hair = input("hair.obj", "");
  expect_clean_failure({hair, "--body", body_, "-o", "out.h5"}, {"hair.obj", "empty"});
}

TEST_F(ExtractCli, OnlyComments) {
  const std::string hair = input("hair.obj", "# a mesh\n# with nothing in it\n");
  expect_clean_failure({hair, "--body", body_, "-o", "out.h5"}, {"hair.obj", "empty"});
}

TEST_F(ExtractCli, NanVertex) {
  const std::string hair = input("hair.obj", "v nan 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  expect_clean_failure({hair, "--body", body_, "-o", "out.h5"}, {"hair.obj", "non-finite"});
}

TEST_F(ExtractCli, NanVertexInBody) {
  const std::string hair = input("hair.obj", std::string(kQuadVertices) + "f 1 2 3 4\n");
  const std::string body = input("body.obj", "v 0 0 0\nv 1 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3 4\n");
  expect_clean_failure({hair, "--body", body, "-o", "out.h5"}, {"body.obj", "non-finite"});
}

TEST_F(ExtractCli, VerticesWithoutFaces) {
  const std::string hair = input("hair.obj", kQuadVertices);
  expect_clean_failure({hair, "--body", body_, "-o", "out.h5"}, {"hair.obj", "no faces"});
}

TEST_F(ExtractCli, FaceIndexOutOfRange) {
  const std::string hair = input("hair.obj", std::string(kQuadVertices) + "f 1 2 3 9\n");
  expect_clean_failure({hair, "--body", body_, "-o", "out.h5"}, {"hair.obj", "9"});
}

TEST_F(ExtractCli, UnknownKeyInParameterFile) {
  const std::string hair = input("hair.obj", std::string(kQuadVertices) + "f 1 2 3 4\n");
  const std::string params = input("bad.toml", "unit_scale = 0.1\nunit_scal = 0.1\n");
  expect_clean_failure({hair, "--body", body_, "-o", "out.h5", "--params", params},
                       {"unit_scal'", "bad.toml"});
}

TEST_F(ExtractCli, ParameterOutOfRange) {
  const std::string hair = input("hair.obj", std::string(kQuadVertices) + "f 1 2 3 4\n");
  expect_clean_failure({hair, "--body", body_, "-o", "out.h5", "--unit_scale", "-1"},
                       {"unit_scale", "-1"});
  // The fade's fall along a whole rail, 0 to 1 from end to end, must be above 0.
  expect_clean_failure({hair, "--body", body_, "-o", "out.h5", "--alpha_fade_min_rail_fall", "0"},
                       {"alpha_fade_min_rail_fall"});
  expect_clean_failure({hair, "--body", body_, "-o", "out.h5", "--alpha_fade_min_rail_fall", "nan"},
                       {"alpha_fade_min_rail_fall"});
}

TEST_F(ExtractCli, AMeshOverTheTriangleLimitIsRefused) {
  // braid01 (about 5,000 triangles) under a limit of 1,000, and the body (far more) under
  // one that the hair passes: each refused naming its file and the setting.
  const std::string braid = (kSamples / "hair" / "braid01.obj").string();
  expect_clean_failure({braid, "--body", body_, "-o", "out.h5", "--max_mesh_triangles", "1000"},
                       {"braid01.obj", "more triangles than the limit of 1000 (max_mesh_triangles)"});
  expect_clean_failure({braid, "--body", body_, "-o", "out.h5", "--max_mesh_triangles", "6000"},
                       {"body.obj", "(max_mesh_triangles)"});
}

TEST_F(ExtractCli, FailureLeavesExistingOutputUntouched) {
  const std::string hair = input("hair.obj", "v nan 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  input("out.h5", "an earlier result that must survive\n");
  expect_clean_failure({hair, "--body", body_, "-o", "out.h5"}, {"hair.obj"});
}

TEST_F(ExtractCli, SampleBraid) {
  expect_valid_extract(kSamples / "hair" / "braid01.obj", kSampleBody, 87);
}

/// Faces of an extract.h5 with a painted flow (coherence above zero).
int64_t painted_faces(const fs::path& extract_file) {
  const hair::h5::File file = hair::h5::File::open_read_only(extract_file);
  const std::vector<float> coherence =
      hair::h5::read_vector<float>(file, "/mesh/face_flow_coherence");
  return std::count_if(coherence.begin(), coherence.end(), [](float c) { return c > 0; });
}

// The sample's OBJ names its MTL, and the MTL its painted texture: extract reads the flow.
TEST_F(ExtractCli, SampleHasAPaintedFlow) {
  expect_valid_extract(kSamples / "hair" / "long01.obj", kSampleBody, 18);
  EXPECT_GT(painted_faces(directory_ / "out.h5"), 1900);  // of 2054
}

// A texture that is missing, empty or not an image: one warning naming it, and the
// stage goes on as for a mesh without texture (exit 0, valid output, no flow).
TEST_F(ExtractCli, BrokenTextureIsAWarningNotAFailure) {
  const std::string cards = two_hair_cards_obj();
  std::string obj = "mtllib cards.mtl\nusemtl hair\n";
  // Texture coordinates: u across each card, v down it.
  for (int card = 0; card < 2; ++card)
    for (int row = 0; row < 9; ++row)
      for (int side = 0; side < 2; ++side)
        obj += "vt " + std::to_string(side) + " " + std::to_string(1 - row / 8.0) + "\n";
  std::istringstream lines(cards);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("f ", 0) == 0) {  // f a b c d -> f a/a b/b c/c d/d
      std::istringstream words(line.substr(2));
      line = "f";
      for (std::string index; words >> index;) line += " " + index + "/" + index;
    }
    obj += line + "\n";
  }
  input("cards.obj", obj);
  for (const char* texture : {"missing.png", "empty.png", "words.png"}) {
    input("cards.mtl", std::string("newmtl hair\nmap_Kd ") + texture + "\n");
    input("empty.png", "");
    input("words.png", "this is not a picture\n");
    const CommandResult result = extract(
        {"cards.obj", "--body", body_, "--unit_scale", "0.1", "-o", "out.h5", "--threads", "1"});
    ASSERT_EQ(result.exit_code, 0) << texture << ": " << describe(result);
    int warnings = 0;
    for (const std::string& line : text_lines(result.err))
      if (line.find("warning") != std::string::npos && line.find(texture) != std::string::npos)
        ++warnings;
    EXPECT_EQ(warnings, 1) << texture << ": " << result.err;
    EXPECT_EQ(painted_faces(directory_ / "out.h5"), 0) << texture;
    EXPECT_EQ(group_count(directory_ / "out.h5"), 2) << texture;
  }
}

// --reproducible: same inputs and parameters give byte-identical files, whatever the
// thread count (DESIGN.md, contract 4); this is stronger than equal datasets.
TEST_F(ExtractCli, ReproducibleRunsAreByteIdentical) {
  const std::string hair = (kSamples / "hair" / "braid01.obj").string();
  for (const char* threads : {"1", "2"}) {
    const CommandResult result =
        extract({hair, "--body", body_, "--unit_scale", "0.1", "--quiet", "--reproducible",
                 "--threads", threads, "-o", "run" + std::string(threads) + ".h5"});
    ASSERT_EQ(result.exit_code, 0) << describe(result);
  }
  const std::string first = hair::test::read_file_bytes(directory_ / "run1.h5");
  EXPECT_FALSE(first.empty());
  EXPECT_TRUE(first == hair::test::read_file_bytes(directory_ / "run2.h5"))
      << "run1.h5 and run2.h5 differ";
}

// glTF 2 input (through assimp): two quad cards converted with assimp's exporter, as
// triangles, which extract pairs back into quads.
class ExtractGltf : public ExtractCli, public ::testing::WithParamInterface<const char*> {};

TEST_P(ExtractGltf, TwoCards) {
  const std::string format = GetParam();
  const std::string obj = input("cards.obj", two_hair_cards_obj());
  const std::string converted = format == "glb2" ? "cards.glb" : "cards.gltf";

  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile((directory_ / obj).string(),
                                           aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
  ASSERT_NE(scene, nullptr) << importer.GetErrorString();
  Assimp::Exporter exporter;
  ASSERT_EQ(exporter.Export(scene, format, (directory_ / converted).string()), AI_SUCCESS)
      << exporter.GetErrorString();
  fs::remove(directory_ / obj);

  expect_valid_extract(directory_ / converted, kSampleBody, 2);
}

INSTANTIATE_TEST_SUITE_P(Formats, ExtractGltf, ::testing::Values("gltf2", "glb2"),
                         [](const ::testing::TestParamInfo<const char*>& param_info) {
                           return std::string(param_info.param);
                         });

// The ten MakeHuman meshes in ../shared/data (not shipped with the project).
struct MakeHumanCase {
  const char* model;
  int64_t groups;
};

void PrintTo(const MakeHumanCase& makehuman_case, std::ostream* stream) {
  *stream << makehuman_case.model;
}

class ExtractMakeHuman : public ExtractCli, public ::testing::WithParamInterface<MakeHumanCase> {};

TEST_P(ExtractMakeHuman, ValidWithExpectedGroups) {
  if (!fs::is_directory(kMakeHuman)) GTEST_SKIP() << kMakeHuman << " is absent";
  const fs::path hair = kMakeHuman / "hair" / (std::string(GetParam().model) + ".obj");
  expect_valid_extract(hair, kMakeHuman / "body.obj", GetParam().groups);
}

INSTANTIATE_TEST_SUITE_P(Meshes, ExtractMakeHuman,
                         ::testing::Values(MakeHumanCase{"afro01", 342}, MakeHumanCase{"bob01", 22},
                                           MakeHumanCase{"bob02", 25}, MakeHumanCase{"braid01", 87},
                                           MakeHumanCase{"long01", 18},
                                           MakeHumanCase{"ponytail01", 48},
                                           MakeHumanCase{"short01", 200},
                                           MakeHumanCase{"short02", 1}, MakeHumanCase{"short03", 1},
                                           MakeHumanCase{"short04", 22}),
                         [](const ::testing::TestParamInfo<MakeHumanCase>& param_info) {
                           return param_info.param.model;
                         });

}  // namespace
