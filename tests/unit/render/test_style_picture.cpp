// hair-render --style-labels: strands of the extract.h5 fixture (group 0: strands at
// x = 0 and 0.1, group 1: the strand at x = 0.2) coloured by a style per group.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "hair/core/error.h"
#include "hair/h5/file.h"
#include "hair/render/extract_picture.h"
#include "hair/style/style_labels.h"
#include "unit/test_h5_support.h"
#include "unit/test_schema_extract_fixture.h"

namespace hair {
namespace {

class StylePictureTest : public testing::TemporaryDirectoryTest {
 protected:
  void SetUp() override {
    TemporaryDirectoryTest::SetUp();
    testing::write_extract_file(path("extract.h5"));
  }
  h5::File extract() const { return h5::File::open_read_only(path("extract.h5"), "extract.h5"); }
};

/// The colour drawn at (x, y): the pixel furthest from white around it.
cv::Vec3b strand_colour(const cv::Mat& image, int x, int y) {
  cv::Vec3b best(255, 255, 255);
  for (int dy = -3; dy <= 3; ++dy)
    for (int dx = -3; dx <= 3; ++dx) {
      cv::Vec3b c = image.at<cv::Vec3b>(y + dy, x + dx);
      if (c[0] + c[1] + c[2] < best[0] + best[1] + best[2]) best = c;
    }
  return best;
}

TEST_F(StylePictureTest, ColoursGroupsByStyleAndUnlabelledGrey) {
  RenderOptions options;
  options.views = {ViewDirection::front};
  options.view_size_px = 400;
  options.line_width_px = 3;
  options.draw_body = false;
  // In that view (as in test_cluster_picture.cpp) group 0's strand at x = 0.1 crosses
  // y = 1.55 m at (200, 284), and group 1's at x = 0.2 crosses y = 1.65 m at (368, 116),
  // right of the legend.
  cv::Mat braided_fixed = style_picture(extract(), {kStyleBraided, kStyleFixed}, options);
  cv::Mat fixed_none = style_picture(extract(), {kStyleFixed, -1}, options);
  cv::Vec3b braided = strand_colour(braided_fixed, 200, 284);
  cv::Vec3b fixed = strand_colour(braided_fixed, 368, 116);
  EXPECT_GT(braided[0], braided[2]) << "braided is blue";
  EXPECT_GT(fixed[2], fixed[0]) << "fixed is brown";
  EXPECT_EQ(strand_colour(fixed_none, 200, 284), fixed);
  cv::Vec3b none = strand_colour(fixed_none, 368, 116);
  EXPECT_EQ(none[0], none[1]) << "no style is grey";
  EXPECT_EQ(none[1], none[2]) << "no style is grey";
}

TEST_F(StylePictureTest, TooFewStylesIsAnError) {
  EXPECT_THROW(style_picture(extract(), {kStyleNormal}, RenderOptions{}), Error);
}

}  // namespace
}  // namespace hair
