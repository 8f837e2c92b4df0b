// hair-render's pictures of middle.h5 and clusters.h5: strands of the extract.h5
// fixture (group 0: strands at x = 0 and 0.1, group 1: the strand at x = 0.2) coloured
// by hand-made clusterings written with the stages' own writers.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "hair/cluster/clustering_io.h"
#include "hair/core/error.h"
#include "hair/h5/file.h"
#include "hair/h5/provenance.h"
#include "hair/render/cluster_picture.h"
#include "unit/test_h5_support.h"
#include "unit/test_schema_extract_fixture.h"

namespace hair {
namespace {

using h5::File;

/// One front view of 400 px, no title, lines thick enough to sample.
RenderOptions test_options() {
  RenderOptions options;
  options.views = {ViewDirection::front};
  options.view_size_px = 400;
  options.line_width_px = 3;
  options.draw_body = false;
  return options;
}

// Pixels on the fixture's strands in that view: the strands span x 0..0.2 and
// y 1.5..1.7, framed with a margin of 8% (1680 px per metre, centre (0.1, 1.6)); y = 1.65
// is at row 116, below the legend line.
const cv::Point kGroup0First(32, 116);    // strand 0, x = 0
const cv::Point kGroup0Second(200, 284);  // strand 1, x = 0.1, y = 1.55
const cv::Point kGroup1(368, 116);        // strand 2, x = 0.2

/// The colour drawn at `at`: the pixel furthest from white around it.
cv::Vec3b strand_colour(const cv::Mat& image, cv::Point at) {
  cv::Vec3b best(255, 255, 255);
  for (int dy = -3; dy <= 3; ++dy)
    for (int dx = -3; dx <= 3; ++dx) {
      cv::Vec3b c = image.at<cv::Vec3b>(at.y + dy, at.x + dx);
      if (c[0] + c[1] + c[2] < best[0] + best[1] + best[2]) best = c;
    }
  return best;
}

/// The colour colours_by_id() gives `id`: the palette the pictures must share.
cv::Vec3b palette(int32_t id) {
  StrandSet one;
  one.append_strand(Points3f::Zero(2, 3));
  return colours_by_id(one, {id}).at(0);
}

double distance(cv::Vec3b a, cv::Vec3b b) { return cv::norm(cv::Vec3d(a) - cv::Vec3d(b)); }

class ClusterPictureTest : public testing::TemporaryDirectoryTest {
 protected:
  void SetUp() override {
    TemporaryDirectoryTest::SetUp();
    testing::write_extract_file(path("extract.h5"));
  }

  File extract() const { return File::open_read_only(path("extract.h5"), "extract.h5"); }

  /// A middle.h5 with a middle cluster (or -1) per group, `name` in errors.
  File middle(const std::vector<int32_t>& middle_cluster, int32_t cluster_count,
              ClusterCountSource source, const std::string& name = "middle.h5") const {
    MiddleClustering clustering;
    clustering.middle_cluster = middle_cluster;
    clustering.cluster_count = cluster_count;
    clustering.count_source = source;
    clustering.graph.node_count = static_cast<int32_t>(middle_cluster.size());
    clustering.graph.add_edge(0, 1, 0.1, EdgeKind::connectivity, {0.1f, 0.5f, 0.1f});
    clustering.graph.set_affinities(0);
    clustering.eigenvalues = {1.0, 0.5};
    File file = File::create(path(name), name);
    write_middle_file(file, clustering, 0.25);
    write_provenance(file, {.stage = "cluster-middle",
                            .project_version = "test",
                            .parameters = "{}",
                            .inputs = {{"types", "types.h5", std::string(64, '0')}},
                            .wall_time_s = {},
                            .created_utc = {}});
    file.close();
    return File::open_read_only(path(name), name);
  }

  /// A clusters.h5 of the fixture's two groups: spectral clustering put both in cluster
  /// 0, which the division at the type change split into 0 (root) and 1.
  File clusters() const {
    HairClustering clustering;
    clustering.node_of_group = {0, 1};
    clustering.cluster_before_split = {0, 0};
    clustering.cluster = {0, 1};
    clustering.node_in_s1 = {0, 0};
    clustering.node_middle_cluster = {-1, -1};
    clustering.cluster_origin = {0, 0};
    clustering.cluster_starts_at_root = {1, 0};
    clustering.cluster_group_count = {1, 1};
    clustering.clusters_before_split = 1;
    clustering.split_count = 1;
    clustering.count_source = ClusterCountSource::eigengap;
    clustering.graph.node_count = 2;
    clustering.graph.add_edge(0, 1, 0.2, EdgeKind::connectivity, {0.1f, 0.5f, 0.1f});
    clustering.graph.set_affinities(0);
    clustering.eigenvalues = {1.0, -0.5};
    File file = File::create(path("clusters.h5"), "clusters.h5");
    write_clusters_file(file, clustering, 0.25);
    write_provenance(file, {.stage = "cluster-all",
                            .project_version = "test",
                            .parameters = "{}",
                            .inputs = {{"types", "types.h5", std::string(64, '0')},
                                       {"middle", "middle.h5", std::string(64, '0')}},
                            .wall_time_s = {},
                            .created_utc = {}});
    file.close();
    return File::open_read_only(path("clusters.h5"), "clusters.h5");
  }
};

/// Pixels of the top left, where the legend line is, that are dark text.
int dark_legend_pixels(const cv::Mat& image) {
  int dark = 0;
  for (int y = 30; y < 50; ++y)
    for (int x = 10; x < 200; ++x) {
      cv::Vec3b c = image.at<cv::Vec3b>(y, x);
      if (c[0] < 100 && c[1] < 100 && c[2] < 100) ++dark;
    }
  return dark;
}

TEST_F(ClusterPictureTest, MiddleGroupsInTheirClusterColourTheOthersGrey) {
  cv::Mat image =
      middle_picture(middle({0, -1}, 1, ClusterCountSource::parameter), extract(), test_options());
  ASSERT_EQ(image.type(), CV_8UC3);
  ASSERT_EQ(image.size(), cv::Size(400, 400));
  EXPECT_LT(distance(strand_colour(image, kGroup0First), palette(0)), 8);
  EXPECT_LT(distance(strand_colour(image, kGroup0Second), palette(0)), 8);
  EXPECT_EQ(strand_colour(image, kGroup1), kNonMiddleGrey);
  EXPECT_EQ(kNonMiddleGrey[0], kNonMiddleGrey[1]);
  EXPECT_EQ(kNonMiddleGrey[1], kNonMiddleGrey[2]);
  EXPECT_GT(distance(palette(0), kNonMiddleGrey), 100);
  EXPECT_GT(dark_legend_pixels(image), 20) << "no legend line";
}

TEST_F(ClusterPictureTest, TwoMiddleClustersGetDifferentColours) {
  cv::Mat image =
      middle_picture(middle({1, 0}, 2, ClusterCountSource::eigengap), extract(), test_options());
  cv::Vec3b first = strand_colour(image, kGroup0First), second = strand_colour(image, kGroup1);
  EXPECT_LT(distance(first, palette(1)), 8);
  EXPECT_LT(distance(second, palette(0)), 8);
  EXPECT_GT(distance(first, second), 100);
}

TEST_F(ClusterPictureTest, FinalClustersAndClustersBeforeTheSplit) {
  File file = clusters();
  cv::Mat final_clusters = clusters_picture(file, extract(), test_options(), false);
  EXPECT_LT(distance(strand_colour(final_clusters, kGroup0First), palette(0)), 8);
  EXPECT_LT(distance(strand_colour(final_clusters, kGroup0Second), palette(0)), 8);
  EXPECT_LT(distance(strand_colour(final_clusters, kGroup1), palette(1)), 8);
  EXPECT_GT(
      distance(strand_colour(final_clusters, kGroup0First), strand_colour(final_clusters, kGroup1)),
      100);
  EXPECT_GT(dark_legend_pixels(final_clusters), 20) << "no legend line";

  cv::Mat before_split = clusters_picture(file, extract(), test_options(), true);
  EXPECT_LT(distance(strand_colour(before_split, kGroup0First), palette(0)), 8);
  EXPECT_LT(distance(strand_colour(before_split, kGroup1), palette(0)), 8);
}

TEST_F(ClusterPictureTest, ColouringWords) {
  EXPECT_FALSE(parse_cluster_colouring("cluster"));
  EXPECT_TRUE(parse_cluster_colouring("before_split"));
  try {
    parse_cluster_colouring("group");
    FAIL() << "expected a usage error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::usage);
    EXPECT_NE(std::string(error.what()).find("before_split"), std::string::npos);
  }
}

/// Runs `draw` and expects a bad_input error naming `file_name`.
template <typename Draw>
void expect_bad_input_naming(const std::string& file_name, Draw draw) {
  try {
    draw();
    ADD_FAILURE() << "expected an error naming " << file_name;
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::bad_input) << error.what();
    EXPECT_EQ(error.file(), file_name) << error.what();
    EXPECT_NE(std::string(error.what()).find(file_name), std::string::npos) << error.what();
  }
}

TEST_F(ClusterPictureTest, WrongSchemaOrAnotherModelNamesTheFile) {
  File middle_file = middle({0, -1}, 1, ClusterCountSource::parameter);
  File clusters_file = clusters();
  expect_bad_input_naming("clusters.h5",
                          [&] { middle_picture(clusters_file, extract(), test_options()); });
  expect_bad_input_naming("middle.h5",
                          [&] { clusters_picture(middle_file, extract(), test_options(), false); });
  expect_bad_input_naming("extract.h5",
                          [&] { middle_picture(extract(), extract(), test_options()); });
  expect_bad_input_naming(
      "middle.h5", [&] { clusters_picture(clusters_file, middle_file, test_options(), false); });

  // A middle.h5 of three groups does not go with the fixture's two.
  File other_model = middle({0, -1, 0}, 1, ClusterCountSource::parameter, "other.h5");
  expect_bad_input_naming("other.h5",
                          [&] { middle_picture(other_model, extract(), test_options()); });
}

}  // namespace
}  // namespace hair
