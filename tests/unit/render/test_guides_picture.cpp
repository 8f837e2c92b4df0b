// hair-render's contact sheet of guides.h5: a hand-made simulation written with the
// simulate stage's own writer (a normal guide and a braided wisp centre in front of a
// spherical head) over an extract.h5 fixture whose body is that head.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <functional>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "hair/core/error.h"
#include "hair/h5/dataset.h"
#include "hair/h5/file.h"
#include "hair/h5/provenance.h"
#include "hair/render/guides_picture.h"
#include "hair/render/style_picture.h"
#include "hair/sim/guides_io.h"
#include "unit/icosphere.h"
#include "unit/test_h5_support.h"
#include "unit/test_schema_extract_fixture.h"

namespace hair {
namespace {

using h5::File;

constexpr int kViewPx = 200;    // one front view per panel
constexpr int kHeaderPx = 56;   // the sheet's title and legend
constexpr int kCaptionPx = 32;  // rows of a panel its caption may cover
constexpr double kHeadHeightM = 0.25;
const Eigen::Vector3d kHeadCentreM(0, 1.65, 0);
const Eigen::Vector3d kPivotM(0, 1.5, 0);

RenderOptions test_options() {
  RenderOptions options;
  options.views = {ViewDirection::front};
  options.view_size_px = kViewPx;
  options.line_width_px = 2;
  return options;
}

/// The head pitched forward by `degrees` about the pivot below it (a nod).
RigidTransform nod(double degrees) {
  RigidTransform head;
  head.rotation = Eigen::AngleAxisd(degrees * M_PI / 180, Eigen::Vector3d::UnitX());
  head.translation_m = kPivotM - head.rotation * kPivotM;
  return head;
}

/// The head moved along +x by `metres`.
RigidTransform shift(double metres) {
  RigidTransform head;
  head.translation_m = Eigen::Vector3d(metres, 0, 0);
  return head;
}

/// `frame_count` frames at 30 fps of two guides in front of the head, each 5 points from
/// y = 1.7 down to 1.5: a normal strand at x = 0.04 (cluster 0) and a braided wisp centre
/// at x = -0.04 (cluster 1). The guides move rigidly with the head of `head(frame)`.
SimulationResult two_guides(int32_t frame_count, const std::function<RigidTransform(int)>& head) {
  SimulationResult result;
  result.simulated_style = {0, 3};
  result.fps = 30;
  result.frame_count = frame_count;
  for (int g = 0; g < 2; ++g) {
    SimulatedGuide guide;
    guide.kind = g == 0 ? GuideKind::strand : GuideKind::wisp_centre;
    guide.strand = g == 0 ? 0 : -1;
    guide.cluster = g;
    guide.style = g == 0 ? HairStyle::normal : HairStyle::braided;
    guide.mass_scale = g == 0 ? 1 : 3;
    for (int k = 0; k < 5; ++k)
      guide.rest_m.emplace_back(g == 0 ? 0.04 : -0.04, 1.7 - 0.05 * k, 0.1);
    result.guides.push_back(guide);
  }
  result.plan.cluster_candidates = {1, 3};
  result.plan.cluster_guides = {1, 1};
  result.wisp_guide = {1};
  result.wisp_tetrahedron_offset = {0, 1};
  for (int f = 0; f < frame_count; ++f) {
    RigidTransform pose = head(f);
    result.head.push_back(pose);
    for (const SimulatedGuide& guide : result.guides)
      for (const Eigen::Vector3d& p : guide.rest_m)
        for (int axis = 0; axis < 3; ++axis)
          result.guide_points_m.push_back(static_cast<float>(pose.apply(p)[axis]));
    FrameStatistics stats;
    stats.time_s = f / result.fps;
    result.statistics.push_back(stats);
    for (float v : {0.f, 1.7f, 0.f, 1.f, 0.f, 0.f, 0.f}) result.wisp_frames.push_back(v);
  }
  return result;
}

/// The style of a pixel: how far it is from `colour`, channel by channel.
bool near(cv::Vec3b pixel, cv::Vec3b colour, int tolerance = 12) {
  for (int c = 0; c < 3; ++c)
    if (std::abs(pixel[c] - colour[c]) > tolerance) return false;
  return true;
}

/// Panel `index` of a sheet of one-view panels in one row, without its border and the
/// rows its caption may cover.
cv::Mat panel(const cv::Mat& sheet, int index) {
  return sheet(
      cv::Rect(index * kViewPx + 2, kHeaderPx + kCaptionPx, kViewPx - 4, kViewPx - kCaptionPx - 2));
}

/// The pixels of `image` that `select` picks: how many, and their mean column and row.
struct Pixels {
  int count = 0;
  double x = 0, y = 0;
};
Pixels pixels(const cv::Mat& image, const std::function<bool(cv::Vec3b)>& select) {
  Pixels found;
  for (int y = 0; y < image.rows; ++y)
    for (int x = 0; x < image.cols; ++x)
      if (select(image.at<cv::Vec3b>(y, x))) {
        ++found.count;
        found.x += x;
        found.y += y;
      }
  if (found.count > 0) {
    found.x /= found.count;
    found.y /= found.count;
  }
  return found;
}

/// The shaded body: grey, not the white background.
bool body_grey(cv::Vec3b c) { return c[0] == c[1] && c[1] == c[2] && c[0] > 60 && c[0] < 240; }

class GuidesPictureTest : public testing::TemporaryDirectoryTest {
 protected:
  void SetUp() override {
    TemporaryDirectoryTest::SetUp();
    // The fixture's body replaced by a head: a sphere of radius 0.08 m under the top
    // of the guides, all of it within the head height of its top.
    testing::write_extract_file(path("extract.h5"), [](File& file) {
      testing::SphereMesh head = testing::icosphere(2, 0.08, kHeadCentreM);
      for (const char* dataset : {"/body/vertices", "/body/triangles", "/body/scalp_triangle"})
        testing::remove_object(file, dataset);
      h5::write_dataset(
          file, "/body/vertices",
          std::vector<float>(head.vertices.data(), head.vertices.data() + head.vertices.size()),
          {head.vertices.rows(), 3});
      h5::write_dataset(file, "/body/triangles",
                        std::vector<int32_t>(head.triangles.data(),
                                             head.triangles.data() + head.triangles.size()),
                        {head.triangles.rows(), 3});
      h5::write_vector(file, "/body/scalp_triangle",
                       std::vector<uint8_t>(static_cast<size_t>(head.triangles.rows()), 0));
    });
  }

  File extract() const { return File::open_read_only(path("extract.h5"), "extract.h5"); }

  /// guides.h5 of `result`, written as the simulate stage writes it.
  File guides(const SimulationResult& result, double head_height_m = kHeadHeightM) const {
    File file = File::create(path("guides.h5"), "guides.h5");
    GuidesFileInfo info;
    info.head_height_m = head_height_m;
    info.motion = "nod";
    info.cluster_style = {0, 3};
    write_guides_file(file, result, info);
    write_provenance(file, {.stage = "simulate",
                            .project_version = "test",
                            .parameters = "{}",
                            .inputs = {{"extract", "extract.h5", std::string(64, '0')},
                                       {"strands", "strands.h5", std::string(64, '0')},
                                       {"styles", "styles.h5", std::string(64, '0')}},
                            .wall_time_s = {},
                            .created_utc = {}});
    file.close();
    return File::open_read_only(path("guides.h5"), "guides.h5");
  }
};

TEST_F(GuidesPictureTest, APanelPerFrameWithTheStylesAndTheMovedHead) {
  // Frames 0 and 1 at rest, the head nodded 60 degrees in frame 2.
  File file = guides(two_guides(3, [](int f) { return f < 2 ? RigidTransform{} : nod(60); }));
  cv::Mat sheet = guides_picture(file, extract(), test_options());
  // 6 panels asked, 3 frames: each frame once, in one row.
  ASSERT_EQ(sheet.type(), CV_8UC3);
  ASSERT_EQ(sheet.size(), cv::Size(3 * kViewPx, kHeaderPx + kViewPx));

  std::vector<Pixels> normal, braided, body;
  for (int p = 0; p < 3; ++p) {
    cv::Mat image = panel(sheet, p);
    normal.push_back(pixels(image, [](cv::Vec3b c) { return near(c, style_colour(0)); }));
    braided.push_back(pixels(image, [](cv::Vec3b c) { return near(c, style_colour(3)); }));
    body.push_back(pixels(image, body_grey));
    EXPECT_GT(normal[p].count, 20) << "panel " << p << ": the normal guide in yellow";
    EXPECT_GT(braided[p].count, 20) << "panel " << p << ": the braided wisp centre in blue";
    EXPECT_GT(body[p].count, 1000) << "panel " << p << ": the head";
    EXPECT_GT(normal[p].x, braided[p].x) << "panel " << p << ": normal at +x, braided at -x";
  }
  EXPECT_GT(braided[0].count, 2 * normal[0].count) << "the wisp centre is drawn thicker";

  // The same camera and the same pose: frames 0 and 1 look the same.
  EXPECT_EQ(cv::norm(panel(sheet, 0), panel(sheet, 1), cv::NORM_INF), 0);
  // The nod brings the head and the guides down in the front view: the head's centre
  // 0.075 m, about 40 px at the scale of the box around every frame (0.32 m high).
  EXPECT_GT(body[2].y - body[0].y, 20);
  EXPECT_GT(normal[2].y - normal[0].y, 20);
  EXPECT_GT(braided[2].y - braided[0].y, 20);
  EXPECT_NEAR(body[2].x, body[0].x, 2) << "a nod does not move the head sideways";
}

TEST_F(GuidesPictureTest, PanelsSpreadEvenlyFromTheFirstToTheLastFrameInTwoRowsAboveFour) {
  // The head moves 0.02 m along +x each frame.
  File file = guides(two_guides(9, [](int f) { return shift(0.02 * f); }));
  RenderOptions options = test_options();
  cv::Mat every = guides_picture(file, extract(), options, 9);  // frames 0..8
  cv::Mat three = guides_picture(file, extract(), options, 3);  // frames 0, 4, 8
  ASSERT_EQ(every.size(), cv::Size(5 * kViewPx, kHeaderPx + 2 * kViewPx));
  ASSERT_EQ(three.size(), cv::Size(3 * kViewPx, kHeaderPx + kViewPx));
  std::vector<double> head_x;
  for (int p = 0; p < 3; ++p) head_x.push_back(pixels(panel(three, p), body_grey).x);
  // 0.08 m in 4 frames; the camera fits all of them (0.32 m wide): about 42 px a step.
  EXPECT_NEAR(head_x[1] - head_x[0], head_x[2] - head_x[1], 2) << "evenly spread";
  double step = pixels(panel(every, 1), body_grey).x - pixels(panel(every, 0), body_grey).x;
  EXPECT_GT(step, 5);
  EXPECT_NEAR(head_x[1] - head_x[0], 4 * step, 4) << "frames 0, 4 and 8: the last included";
  // Panel 5 is the first of the second row: frame 5.
  cv::Mat second_row =
      every(cv::Rect(2, kHeaderPx + kViewPx + kCaptionPx, kViewPx - 4, kViewPx - kCaptionPx - 2));
  EXPECT_NEAR(pixels(second_row, body_grey).x - head_x[0], 5 * step, 4);
}

TEST_F(GuidesPictureTest, AFileOfAnotherSchemaIsRefused) {
  try {
    guides_picture(extract(), extract(), test_options());
    FAIL() << "extract.h5 drawn as guides.h5";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::bad_input);
    EXPECT_EQ(e.file(), "extract.h5");
    EXPECT_NE(std::string(e.what()).find("expected hairstyle.guides"), std::string::npos)
        << e.what();
  }
}

TEST_F(GuidesPictureTest, ABodyOfAnotherHeadHeightIsAnotherModel) {
  File file = guides(two_guides(2, [](int) { return RigidTransform{}; }), 0.3);
  try {
    guides_picture(file, extract(), test_options());
    FAIL() << "a body of another model drawn";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::bad_input);
    EXPECT_EQ(e.file(), "extract.h5");
    EXPECT_NE(std::string(e.what()).find("another model"), std::string::npos) << e.what();
  }
}

TEST_F(GuidesPictureTest, FewerThanTwoPanelsOrMismatchedFramesAreErrors) {
  File file = guides(two_guides(3, [](int) { return RigidTransform{}; }));
  try {
    guides_picture(file, extract(), test_options(), 1);
    FAIL() << "one panel";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::usage);
  }
  GuidesPictureInput input;
  input.guides = read_simulated_guides(file);
  input.source = "guides.h5";
  input.guides.head.pop_back();
  try {
    guides_picture(input, test_options());
    FAIL() << "a frame without a head";
  } catch (const Error& e) {
    EXPECT_EQ(e.dataset(), "/frames/head_rotation");
  }
}

}  // namespace
}  // namespace hair
