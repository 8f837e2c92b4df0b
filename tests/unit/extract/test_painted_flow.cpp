// The flow painted in a hair mesh's texture: strokes of a known direction on a textured
// quad come back as that direction in 3D, the alpha's fade gives the tips' side, and a
// missing or broken image is a warning and no flow, never a crash.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "hair/extract/extract.h"
#include "hair/extract/painted_flow.h"
#include "hair/mesh/mesh_io.h"
#include "unit/file_test.h"

namespace hair {
namespace {

class PaintedFlowTest : public hair::test::FileTest {
 protected:
  /// A 128 x 128 RGBA texture of stripes whose strokes run at `stroke_deg` in the image
  /// (0: along +x, 90: along -y, i.e. up the image), with alpha falling linearly from
  /// `alpha_top` at row 0 (v = 1) to `alpha_bottom` at the last row (v = 0).
  std::filesystem::path stripes(const std::string& name, double stroke_deg, double alpha_top,
                                double alpha_bottom) {
    const int size = 128;
    cv::Mat image(size, size, CV_8UC4);
    const double angle = stroke_deg * M_PI / 180;
    // Luminance varies across the strokes: along the normal (-sin, -cos) in (x, y down).
    const double nx = std::sin(angle), ny = std::cos(angle);
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        double across = nx * x + ny * y;
        auto level = static_cast<uint8_t>(127 + 100 * std::sin(2 * M_PI * across / 6));
        double alpha = alpha_top + (alpha_bottom - alpha_top) * y / (size - 1.0);
        image.at<cv::Vec4b>(y, x) = {level, level, level, static_cast<uint8_t>(255 * alpha)};
      }
    std::filesystem::path path = directory_ / name;
    cv::imwrite(path.string(), image);
    return path;
  }

  /// A unit quad standing in the x-y plane (x right, y up), its texture spanning [0, 1]^2
  /// with u along x and v along y, of material `texture`.
  PolyMesh textured_quad(const std::string& texture) {
    write_file("quad.mtl", "newmtl hair\nmap_Kd " + texture + "\nmap_d " + texture + "\n");
    return read_mesh(write_file("quad.obj",
                                "mtllib quad.mtl\nusemtl hair\n"
                                "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                "f 1/1 2/2 3/3 4/4\n"));
  }
};

TEST_F(PaintedFlowTest, VerticalStrokesFadingDownPointDownTheQuad) {
  stripes("down.png", 90, 1.0, 0.3);
  PaintedFlow flow = painted_flow(textured_quad("down.png"), PaintedFlowParams{}, "quad");
  ASSERT_EQ(flow.painted_face_count(), 1);
  EXPECT_TRUE(flow.unreadable_images.empty());
  EXPECT_GT(flow.coherence[0], 0.9);
  // The alpha falls from the top of the image (v = 1, y = 1) to its bottom: tips down.
  EXPECT_NEAR(flow.direction[0].y(), -1.0, 0.02);
  EXPECT_NEAR(flow.alpha_fall[0], 0.7, 0.1);
}

TEST_F(PaintedFlowTest, TheFadeDecidesTheSenseAndTheStrokesTheAxis) {
  stripes("up.png", 90, 0.3, 1.0);  // fading upwards: tips up
  PaintedFlow up = painted_flow(textured_quad("up.png"), PaintedFlowParams{}, "quad");
  EXPECT_NEAR(up.direction[0].y(), 1.0, 0.02);
  stripes("diagonal.png", 45, 1.0, 1.0);  // no fade: the axis only
  PaintedFlow diagonal = painted_flow(textured_quad("diagonal.png"), PaintedFlowParams{}, "quad");
  ASSERT_EQ(diagonal.painted_face_count(), 1);
  const Eigen::Vector3f expected = Eigen::Vector3f(1, 1, 0).normalized();
  EXPECT_GT(std::abs(diagonal.direction[0].dot(expected)), std::cos(5 * M_PI / 180));
  EXPECT_LT(diagonal.alpha_fall[0], 0.05);
}

TEST_F(PaintedFlowTest, AHighlightBandPaintedAcrossTheStrokesIsNotReadAsTheirFlow) {
  // Faint fine vertical strokes under broad bright bands across them, as artists paint
  // the shine on hair: the bands' edges run across the hair, are steeper on average than
  // the strokes, and must not win.
  const int size = 128;
  cv::Mat image(size, size, CV_8UC4);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const double band = 110 * std::pow(std::sin(M_PI * y / 32), 2);
      const double strokes = 6 * std::sin(2 * M_PI * x / 5);
      auto level = static_cast<uint8_t>(std::clamp(70 + band + strokes, 0.0, 255.0));
      image.at<cv::Vec4b>(y, x) = {level, level, level, 255};
    }
  cv::imwrite((directory_ / "band.png").string(), image);
  PaintedFlow flow = painted_flow(textured_quad("band.png"), PaintedFlowParams{}, "quad");
  ASSERT_EQ(flow.painted_face_count(), 1);
  EXPECT_GT(std::abs(flow.direction[0].y()), std::cos(10 * M_PI / 180)) << flow.direction[0];
  EXPECT_GT(flow.coherence[0], kClearFlowCoherence);
  // Without the high pass (a blur far wider than the image) the bands win.
  PaintedFlowParams no_high_pass;
  no_high_pass.stroke_scale_px = 1000;
  PaintedFlow banded = painted_flow(textured_quad("band.png"), no_high_pass, "quad");
  EXPECT_GT(std::abs(banded.direction[0].x()), std::cos(10 * M_PI / 180)) << banded.direction[0];
}

TEST_F(PaintedFlowTest, UniformPaintHasNoClearFlow) {
  cv::Mat flat(64, 64, CV_8UC4, cv::Scalar(90, 60, 40, 255));
  cv::randn(flat, cv::Scalar(90, 60, 40, 255), cv::Scalar(20, 20, 20, 0));  // noise, no strokes
  cv::imwrite((directory_ / "flat.png").string(), flat);
  PaintedFlow flow = painted_flow(textured_quad("flat.png"), PaintedFlowParams{}, "quad");
  EXPECT_LT(flow.coherence[0], kClearFlowCoherence);
}

TEST_F(PaintedFlowTest, BrokenImagesAreAWarningAndNoFlow) {
  write_file("empty.png", "");
  write_file("text.png", "not an image at all\n");
  std::string png_start = "\x89PNG\r\n\x1a\n";
  write_file("cut.png", png_start + "IHDR and then nothing");
  for (const char* texture : {"missing.png", "empty.png", "text.png", "cut.png"}) {
    PaintedFlow flow;
    ASSERT_NO_THROW(flow = painted_flow(textured_quad(texture), PaintedFlowParams{}, "quad"))
        << texture;
    EXPECT_EQ(flow.painted_face_count(), 0) << texture;
    ASSERT_EQ(flow.unreadable_images.size(), 1u) << texture;  // map_Kd and map_d: one image
    EXPECT_NE(flow.unreadable_images[0].find(texture), std::string::npos);
    EXPECT_EQ(flow.direction[0], Eigen::Vector3f::Zero());
  }
}

TEST_F(PaintedFlowTest, AMeshWithoutTextureCoordinatesOrMaterialsHasNoFlow) {
  stripes("down.png", 90, 1, 0.3);
  write_file("bare.mtl", "newmtl hair\nmap_Kd down.png\n");
  PolyMesh no_uv = read_mesh(write_file(
      "bare.obj", "mtllib bare.mtl\nusemtl hair\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n"));
  EXPECT_EQ(painted_flow(no_uv, PaintedFlowParams{}, "bare").painted_face_count(), 0);
  PolyMesh no_material = read_mesh(write_file(
      "plain.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                   "f 1/1 2/2 3/3 4/4\n"));
  PaintedFlow flow = painted_flow(no_material, PaintedFlowParams{}, "plain");
  EXPECT_EQ(flow.painted_face_count(), 0);
  EXPECT_EQ(flow.direction.size(), 1u);
}

/// Extract's input strands against the paint of a MakeHuman mesh, with or without its
/// textures given to extract (without, extract chooses rails as if it had none).
double input_strands_along_paint(const std::string& model, bool textured, int64_t& segments) {
  const std::filesystem::path data = std::filesystem::path(HAIR_SHARED_DATA_DIR) / "makehuman";
  ExtractParams params;
  params.unit_scale = 0.1;
  PolyMesh mesh = read_mesh(data / "hair" / (model + ".obj"));
  PaintedTextures textures = load_painted_textures(mesh.materials, params.painted_flow, model);
  ExtractResult result = extract_strands(std::move(mesh), read_mesh(data / "body.obj"), params,
                                         model, "body", textured ? textures : PaintedTextures{});
  PaintedFlow flow = painted_flow(result.hair_mesh, textures, params.painted_flow);
  EXPECT_GT(flow.painted_face_count(), result.hair_mesh.face_count() * 3 / 4) << model;
  return painted_flow_agreement(result.hair_mesh, flow, result.strands, kClearFlowCoherence,
                                kFlowAgreementAngleDeg, 0.1 * result.head.head_height, segments);
}

TEST(PaintedFlowMakeHuman, ACapReadAsRingsWithoutItsTextureIsTracedAlongThePaintWithIt) {
  // short03 is a one-piece cap whose quads run in rings around the head while its paint
  // runs down it: without the texture extract's rails cross the paint; with it the cap is
  // cut into strands along the paint.
  if (!std::filesystem::exists(std::filesystem::path(HAIR_SHARED_DATA_DIR) / "makehuman"))
    GTEST_SKIP();
  int64_t segments = 0;
  EXPECT_LT(input_strands_along_paint("short03", false, segments), 0.2);
  EXPECT_GT(segments, 500);
  EXPECT_GT(input_strands_along_paint("short03", true, segments), 0.9);
  EXPECT_GT(segments, 500);
}

class PaintedFlowEveryMakeHuman : public ::testing::TestWithParam<std::string> {};

// Where the paint is not clear a face is judged against its rails: its own group's input
// strands, not those of a card that crosses it closer (short01's spikes stacked on its
// cap). Two strips of two quads 1 cm wide and 4 cm long: A along x in z = 0, rails along its
// two long edges; B along y, 1 mm above A, crossing it over x in [1, 2] cm, a rail along
// its edge x = 1 cm. A face of a group with no strands takes the nearest rail of any.
TEST(PaintedFlowRails, AFaceWithoutClearPaintIsJudgedAgainstItsOwnRails) {
  PolyMesh mesh;
  mesh.vertices.resize(12, 3);
  mesh.vertices << 0, 0, 0, 0.02f, 0, 0, 0.04f, 0, 0,  // A's edge y = 0
      0, 0.01f, 0, 0.02f, 0.01f, 0, 0.04f, 0.01f, 0,   // A's edge y = 1 cm
      0.01f, -0.015f, 0.001f, 0.02f, -0.015f, 0.001f,  // B's start, y = -1.5 cm
      0.01f, 0.005f, 0.001f, 0.02f, 0.005f, 0.001f,    // B's middle, over A
      0.01f, 0.025f, 0.001f, 0.02f, 0.025f, 0.001f;    // B's end
  for (const std::vector<int32_t>& quad :
       std::vector<std::vector<int32_t>>{{0, 1, 4, 3}, {1, 2, 5, 4}, {6, 7, 9, 8}, {8, 9, 11, 10}})
    mesh.append_face(quad);
  PaintedFlow unpainted;
  unpainted.direction.assign(4, Eigen::Vector3f::Zero());
  unpainted.coherence.assign(4, 0.0f);
  unpainted.alpha_fall.assign(4, 0.0f);
  StrandSet rails;
  auto add_rail = [&rails](const std::vector<Eigen::Vector3f>& points) {
    Points3f rows(static_cast<Eigen::Index>(points.size()), 3);
    for (size_t i = 0; i < points.size(); ++i)
      rows.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
    rails.append_strand(rows);
  };
  for (float y : {0.0f, 0.01f})
    add_rail({{0, y, 0}, {0.01f, y, 0}, {0.02f, y, 0}, {0.03f, y, 0}, {0.04f, y, 0}});
  add_rail({{0.01f, -0.015f, 0.001f},
            {0.01f, -0.005f, 0.001f},
            {0.01f, 0, 0.001f},
            {0.01f, 0.01f, 0.001f},
            {0.01f, 0.025f, 0.001f}});
  rails.strand_attributes["group"] = std::vector<int32_t>{0, 0, 1};
  const std::vector<int32_t> face_group = {0, 0, 1, 1};
  const PaintedFlow flow = flow_with_rails(mesh, unpainted, rails, face_group, 0.05);
  // A's first face (centroid (1, 0.5) cm) lies 1 mm under a segment of B's rail, 7 mm from
  // its own rails' nearest.
  for (size_t face : {0u, 1u}) {
    EXPECT_EQ(flow.coherence[face], 1.0f);
    EXPECT_GT(std::abs(flow.direction[face].x()), 0.99f) << "face " << face;
  }
  for (size_t face : {2u, 3u}) EXPECT_GT(std::abs(flow.direction[face].y()), 0.99f);
  // By the nearest rail of any group, A's first face takes B's.
  const PaintedFlow any = flow_with_rails(mesh, unpainted, rails, {}, 0.05);
  EXPECT_GT(std::abs(any.direction[0].y()), 0.99f);
  // Clear paint stays; a group without rails takes the nearest of any.
  PaintedFlow painted = unpainted;
  painted.direction[1] = Eigen::Vector3f(0, 0, 1);
  painted.coherence[1] = 0.8f;
  const PaintedFlow kept = flow_with_rails(mesh, painted, rails, {0, 0, 2, 2}, 0.05);
  EXPECT_EQ(kept.direction[1], Eigen::Vector3f(0, 0, 1));
  EXPECT_EQ(kept.coherence[1], 0.8f);
  for (size_t face : {2u, 3u}) {
    EXPECT_EQ(kept.coherence[face], 1.0f);
    EXPECT_EQ(kept.direction[face], any.direction[face]);
  }
  // Beyond max_distance no flow.
  const PaintedFlow near = flow_with_rails(mesh, unpainted, rails, face_group, 0.0005);
  EXPECT_EQ(near.coherence[0], 0.0f);
}

TEST_P(PaintedFlowEveryMakeHuman, InputStrandsRunAlongThePaint) {
  // The real-meshes issue's target: at least 90% of the judged segments within 30 degrees
  // of the painted flow on every mesh whose texture decides it. afro01's tiny curl cards
  // are left out: their paint is curls smaller than a face (see docs/extract.md).
  if (!std::filesystem::exists(std::filesystem::path(HAIR_SHARED_DATA_DIR) / "makehuman"))
    GTEST_SKIP();
  int64_t segments = 0;
  const double along = input_strands_along_paint(GetParam(), true, segments);
  std::printf("[ paint    ] %s: %.1f%% of %lld input segments along the paint\n",
              GetParam().c_str(), 100 * along, static_cast<long long>(segments));
  EXPECT_GE(along, 0.9);
  EXPECT_GT(segments, 400);
}

INSTANTIATE_TEST_SUITE_P(Models, PaintedFlowEveryMakeHuman,
                         ::testing::Values("bob01", "bob02", "braid01", "long01", "ponytail01",
                                           "short01", "short02", "short03", "short04"));

}  // namespace
}  // namespace hair
