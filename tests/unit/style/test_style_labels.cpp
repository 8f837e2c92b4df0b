// Hand labels of hairstyles per patch (data/labels/makehuman_styles.tsv): reading the
// table, its errors with line numbers, matching labels to extract groups, and the
// shipped labels against the ten MakeHuman meshes.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <map>
#include <set>

#include "unit/file_test.h"
#include "hair/core/error.h"
#include "hair/extract/extract.h"
#include "hair/mesh/mesh_io.h"
#include "hair/style/style_labels.h"
#include "hair/synth/synth_model.h"

namespace hair {
namespace {

using test::FileTest;

const std::string kHeader = "model\tfirst_face\tstyle\n";

TEST(StyleCodes, MatchTheSyntheticTruth) {
  EXPECT_EQ(kStyleNormal, static_cast<int8_t>(synth::HairStyle::normal));
  EXPECT_EQ(kStyleFixed, static_cast<int8_t>(synth::HairStyle::fixed));
  EXPECT_EQ(kStyleShort, static_cast<int8_t>(synth::HairStyle::short_hair));
  EXPECT_EQ(kStyleBraided, static_cast<int8_t>(synth::HairStyle::braided));
  for (size_t code = 0; code < kStyleWords.size(); ++code)
    EXPECT_EQ(style_code(kStyleWords[code]), static_cast<int8_t>(code));
  EXPECT_FALSE(style_code("braid").has_value());
  EXPECT_FALSE(style_code("Normal").has_value());
}

class StyleLabelTable : public FileTest {};

TEST_F(StyleLabelTable, ReadsRowsAfterCommentsAndHeader) {
  auto path = write_file("labels.tsv", "# hand labels\n\n# more\n" + kHeader +
                                           "braid01\t0\tfixed\n"
                                           "# a comment between rows\n"
                                           "braid01\t224\tbraided\r\n"
                                           "short02\t0\tshort\n"
                                           "long01\t7\tnormal\n");
  std::vector<PatchStyleLabel> labels = read_patch_style_labels(path);
  ASSERT_EQ(labels.size(), 4u);
  EXPECT_EQ(labels[0].model, "braid01");
  EXPECT_EQ(labels[0].first_face, 0);
  EXPECT_EQ(labels[0].style, kStyleFixed);
  EXPECT_EQ(labels[0].line, 5);
  EXPECT_EQ(labels[1].first_face, 224);
  EXPECT_EQ(labels[1].style, kStyleBraided);
  EXPECT_EQ(labels[1].line, 7);
  EXPECT_EQ(labels[2].model, "short02");
  EXPECT_EQ(labels[2].style, kStyleShort);
  EXPECT_EQ(labels[3].style, kStyleNormal);
  EXPECT_EQ(labels[3].line, 9);
}

TEST_F(StyleLabelTable, HeaderOnlyIsEmpty) {
  EXPECT_TRUE(read_patch_style_labels(write_file("empty.tsv", "# none yet\n" + kHeader)).empty());
}

/// The one-line message of the error reading `text` throws (empty if none).
std::string error_of(const std::filesystem::path& path) {
  try {
    read_patch_style_labels(path);
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::bad_input);
    std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos);
    return message;
  }
  return {};
}

TEST_F(StyleLabelTable, RejectsBadRowsNamingFileAndLine) {
  struct Case {
    std::string body;  ///< after the comment line and the header (lines 1 and 2)
    std::string line;  ///< the line named
    std::string reason;
  };
  const std::vector<Case> cases = {
      {"bob01\t0\tnormal\nbob01\t5\tbraid\n", "line 4", "style 'braid' is not one of"},
      {"bob01\t0\tNormal\n", "line 3", "style 'Normal'"},
      {"bob01\t12a\tnormal\n", "line 3", "first_face '12a' is not a non-negative integer"},
      {"bob01\t-3\tnormal\n", "line 3", "first_face '-3'"},
      {"bob01\t\tnormal\n", "line 3", "first_face ''"},
      {"bob01\t1e3\tnormal\n", "line 3", "first_face '1e3'"},
      {"bob01 0 normal\n", "line 3", "expected 3 tab-separated fields"},
      {"bob01\t0\tnormal\textra\n", "line 3", "found 4"},
      {"\t0\tnormal\n", "line 3", "empty model name"},
      {"bob01\t0\tnormal\n\nbob01\t1\tnormal\nbob01\t0\tshort\n", "line 6",
       "bob01 first face 0 is labelled again (first on line 3)"},
  };
  for (const Case& c : cases) {
    auto path = write_file("bad.tsv", "# labels\n" + kHeader + c.body);
    std::string message = error_of(path);
    EXPECT_NE(message.find(path.string() + ":" + c.line + ": "), std::string::npos)
        << message << "\n for: " << c.body;
    EXPECT_NE(message.find(c.reason), std::string::npos) << message << "\n for: " << c.body;
  }
}

TEST_F(StyleLabelTable, SameFaceOfAnotherModelIsNoDuplicate) {
  auto path = write_file("two.tsv", kHeader + "bob01\t0\tnormal\nbob02\t0\tnormal\n");
  EXPECT_EQ(read_patch_style_labels(path).size(), 2u);
}

TEST_F(StyleLabelTable, RejectsMissingOrWrongHeader) {
  auto no_header = write_file("no_header.tsv", "# labels\nbob01\t0\tnormal\n");
  EXPECT_NE(error_of(no_header).find(no_header.string() + ":line 2: expected the header"),
            std::string::npos)
      << error_of(no_header);
  auto spaces = write_file("spaces.tsv", "model first_face style\n");
  EXPECT_NE(error_of(spaces).find(":line 1: expected the header"), std::string::npos);
  auto comments_only = write_file("comments.tsv", "# nothing\n");
  EXPECT_NE(error_of(comments_only).find(comments_only.string() + ": no header"), std::string::npos)
      << error_of(comments_only);
  auto missing = directory_.path() / "missing.tsv";
  EXPECT_NE(error_of(missing).find(missing.string() + ": cannot open"), std::string::npos);
}

// Groups: 0 = faces {2, 4}, 1 = faces {0, 1}, 2 = face {3}, 3 = faces {5}.
const std::vector<int32_t> kFaceGroup = {1, 1, 0, 2, 0, 3};

TEST(GroupStyles, TheLabelOfEachGroupsFirstFace) {
  std::vector<PatchStyleLabel> labels = {{"m", 2, kStyleBraided, 3},
                                         {"m", 0, kStyleFixed, 4},
                                         {"other", 3, kStyleShort, 5},
                                         {"m", 5, kStyleNormal, 6}};
  std::vector<int8_t> styles = group_styles_from_patch_labels(kFaceGroup, 4, labels, "m");
  EXPECT_EQ(styles, (std::vector<int8_t>{kStyleBraided, kStyleFixed, -1, kStyleNormal}));
  EXPECT_EQ(group_styles_from_patch_labels(kFaceGroup, 4, labels, "other"),
            (std::vector<int8_t>{-1, -1, kStyleShort, -1}));
  EXPECT_EQ(group_styles_from_patch_labels(kFaceGroup, 4, labels, "none"),
            (std::vector<int8_t>(4, -1)));
  // A group without faces has no first face and no label.
  EXPECT_EQ(group_styles_from_patch_labels(kFaceGroup, 5, labels, "m").back(), -1);
}

TEST(GroupStyles, ALabelMatchingNoFirstFaceIsAnError) {
  // Face 4 is in group 0, whose first face is 2: the mesh must have changed.
  std::vector<PatchStyleLabel> labels = {{"m", 2, kStyleBraided, 3}, {"m", 4, kStyleFixed, 9}};
  try {
    group_styles_from_patch_labels(kFaceGroup, 4, labels, "m");
    FAIL() << "no error";
  } catch (const Error& e) {
    std::string message = e.what();
    EXPECT_NE(message.find("m: the style label on line 9 names first face 4"), std::string::npos)
        << message;
  }
  labels = {{"m", 6, kStyleBraided, 3}};  // past the last face
  EXPECT_THROW(group_styles_from_patch_labels(kFaceGroup, 4, labels, "m"), Error);
}

TEST(GroupStyles, AFaceOutsideTheGroupsIsAnError) {
  EXPECT_THROW(group_styles_from_patch_labels(kFaceGroup, 3, {}, "m"), Error);
  EXPECT_THROW(group_styles_from_patch_labels({0, -1}, 1, {}, "m"), Error);
}

// The shipped labels against the meshes they label.

std::filesystem::path makehuman_dir() {
  return std::filesystem::path(HAIR_SHARED_DATA_DIR) / "makehuman";
}

std::filesystem::path shipped_labels() {
  return std::filesystem::path(HAIR_SOURCE_DIR) / "data/labels/makehuman_styles.tsv";
}

const std::vector<std::string> kModels = {"afro01",     "bob01",   "bob02",   "braid01", "long01",
                                          "ponytail01", "short01", "short02", "short03", "short04"};

TEST(MakeHumanStyleLabelTable, LabelsTheTenModels) {
  std::set<std::string> models;
  for (const PatchStyleLabel& label : read_patch_style_labels(shipped_labels()))
    models.insert(label.model);
  EXPECT_EQ(models, std::set<std::string>(kModels.begin(), kModels.end()));
}

class MakeHumanStyleLabels : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(makehuman_dir())) GTEST_SKIP() << "no " << makehuman_dir();
  }
};

TEST_P(MakeHumanStyleLabels, EveryGroupHasTheExpectedStyles) {
  const std::string& model = GetParam();
  static const std::vector<PatchStyleLabel> labels = read_patch_style_labels(shipped_labels());
  static const PolyMesh body = read_mesh(makehuman_dir() / "body.obj");
  ExtractParams params;
  params.unit_scale = 0.1;  // as pipelines/default/extract.toml
  std::filesystem::path hair_path = makehuman_dir() / "hair" / (model + ".obj");
  ExtractResult result =
      extract_strands(read_mesh(hair_path), body, params, hair_path.string(), "body.obj");

  // Throws if a label of the model names no group's first face.
  std::vector<int8_t> styles =
      group_styles_from_patch_labels(result.face_group, result.group_count(), labels, model);
  for (int32_t group = 0; group < result.group_count(); ++group)
    EXPECT_GE(styles[group], 0) << model << " group " << group << " has no label";
  auto own = std::count_if(labels.begin(), labels.end(),
                           [&](const PatchStyleLabel& label) { return label.model == model; });
  EXPECT_EQ(own, result.group_count()) << "one label per patch";

  std::set<int8_t> present(styles.begin(), styles.end());
  std::map<std::string, std::set<int8_t>> expected = {
      {"afro01", {kStyleShort}},
      {"bob01", {kStyleNormal}},
      {"bob02", {kStyleNormal}},
      {"braid01", {kStyleFixed, kStyleBraided, kStyleNormal}},  // normal: the tuft
      {"long01", {kStyleNormal}},
      {"ponytail01", {kStyleFixed, kStyleNormal}},
      {"short01", {kStyleShort}},
      {"short02", {kStyleShort}},
      {"short03", {kStyleShort}},
      {"short04", {kStyleShort}}};
  EXPECT_EQ(present, expected.at(model));

  // The rule the fixed labels were drawn by: a fixed patch lies wholly above the
  // neck, and every patch above the neck of braid01 and ponytail01 is fixed.
  std::vector<float> lowest(static_cast<size_t>(result.group_count()),
                            std::numeric_limits<float>::infinity());
  for (int64_t face = 0; face < result.hair_mesh.face_count(); ++face)
    for (int32_t vertex : result.hair_mesh.face(face))
      lowest[result.face_group[face]] =
          std::min(lowest[result.face_group[face]], result.hair_mesh.vertices(vertex, 1));
  for (int32_t group = 0; group < result.group_count(); ++group) {
    bool above_neck = lowest[group] >= result.head.neck_y;
    if (styles[group] == kStyleFixed) {
      EXPECT_TRUE(above_neck) << model << " group " << group;
    }
    if (model == "braid01" || model == "ponytail01") {
      EXPECT_EQ(above_neck, styles[group] == kStyleFixed) << model << " group " << group;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Models, MakeHumanStyleLabels, ::testing::ValuesIn(kModels),
                         [](const auto& test_info) { return test_info.param; });

}  // namespace
}  // namespace hair
