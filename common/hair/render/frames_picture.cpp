#include "hair/render/frames_picture.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "hair/core/error.h"
#include "hair/extract/extract_io.h"
#include "hair/h5/attribute.h"
#include "hair/render/style_picture.h"

namespace hair {
namespace {

constexpr int kHeaderPx = 34;  // title and legend above the views

/// The body moved by `head`: x_world = R x_rest + t.
Points3f moved(const Points3f& vertices, const RigidTransform& head) {
  const Eigen::Matrix3f rotation = head.rotation.normalized().toRotationMatrix().cast<float>();
  Points3f out = vertices * rotation.transpose();
  out.rowwise() += head.translation_m.transpose().cast<float>();
  return out;
}

}  // namespace

FramesColouring parse_frames_colouring(const std::string& word) {
  if (word == "style") return FramesColouring::style;
  if (word == "cluster") return FramesColouring::cluster;
  throw Error::usage("--color-by for frames.h5 is style or cluster, not '" + word + "'");
}

FramesScene read_frames_scene(const h5::File& frames, const h5::File& extract) {
  FramesScene scene;
  scene.frames = read_frames_file(frames);
  scene.source = frames.name();
  ExtractedBody body = read_extracted_body(extract);
  const double body_h = h5::read_double_attribute(extract, "/", "head_height_m");
  if (std::abs(body_h - scene.frames.head_height_m) >
      1e-6 * std::max(body_h, scene.frames.head_height_m))
    throw Error::bad_input(extract.name(),
                           cv::format("has head height %.4f m, %s %.4f m: made from another model",
                                      body_h, frames.name().c_str(), scene.frames.head_height_m));
  scene.body_vertices = std::move(body.vertices);
  scene.body_triangles = std::move(body.triangles);
  return scene;
}

Points3f frames_camera_box(const FramesScene& scene, const h5::File& file) {
  Eigen::Array3f low = Eigen::Array3f::Constant(std::numeric_limits<float>::infinity());
  Eigen::Array3f high = -low;
  auto include = [&](const Points3f& points) {
    if (points.rows() == 0) return;
    low = low.min(points.colwise().minCoeff().transpose().array());
    high = high.max(points.colwise().maxCoeff().transpose().array());
  };
  Points3f head;
  const Points3f& body = scene.body_vertices;
  if (body.rows() > 0) {
    const float neck_y_m = body.col(1).maxCoeff() - static_cast<float>(scene.frames.head_height_m);
    std::vector<Eigen::Index> rows;
    for (Eigen::Index v = 0; v < body.rows(); ++v)
      if (body(v, 1) >= neck_y_m) rows.push_back(v);
    head = body(rows, Eigen::all);
  }
  for (int64_t row = 0; row < scene.frames.frame_count(); ++row) {
    include(read_frame_points(file, row));
    include(moved(head, scene.frames.head[static_cast<size_t>(row)]));
  }
  if (!(low <= high).all()) return {};
  Points3f corners(8, 3);
  for (int c = 0; c < 8; ++c)
    corners.row(c) << (c & 1 ? high : low).x(), (c & 2 ? high : low).y(), (c & 4 ? high : low).z();
  return corners;
}

cv::Mat frame_picture(const FramesScene& scene, const Points3f& points, int64_t row,
                      FramesColouring colouring, const RenderOptions& options) {
  const FramesFile& frames = scene.frames;
  if (row < 0 || row >= frames.frame_count())
    throw Error::usage(scene.source + " has no frame row " + std::to_string(row));
  if (points.rows() != frames.rest.point_count())
    throw Error::bad_dataset(scene.source, "/frames/points",
                             "has " + std::to_string(points.rows()) + " points in a frame, not " +
                                 std::to_string(frames.rest.point_count()));
  StrandSet strands;
  strands.offsets = frames.rest.offsets;
  strands.points = points;
  const auto& point_cluster =
      std::get<std::vector<int32_t>>(frames.rest.point_attributes.at("cluster"));
  PointColours colours;
  std::array<int, 4> style_count{};
  if (colouring == FramesColouring::cluster) {
    colours = colours_by_point_id(point_cluster);
  } else {
    colours.resize(point_cluster.size());
    for (size_t i = 0; i < point_cluster.size(); ++i)
      colours[i] = style_colour(frames.simulated_style[static_cast<size_t>(point_cluster[i])]);
    for (int64_t s = 0; s < strands.strand_count(); ++s) {
      // A strand counts for the style of its last point: a ponytail's for its tail.
      int8_t style = frames.simulated_style[static_cast<size_t>(
          point_cluster[static_cast<size_t>(strands.offsets[static_cast<size_t>(s) + 1] - 1)])];
      if (style >= 0 && style < 4) ++style_count[static_cast<size_t>(style)];
    }
  }
  const RigidTransform& head = frames.head[static_cast<size_t>(row)];
  RenderOptions view_options = options;
  view_options.title = cv::format("frame %lld   %.2f s",
                                  static_cast<long long>(frames.index[static_cast<size_t>(row)]),
                                  frames.time_s[static_cast<size_t>(row)]);
  cv::Mat views = render_strands(strands, colours, moved(scene.body_vertices, head),
                                 scene.body_triangles, view_options);
  cv::Mat picture(kHeaderPx + views.rows, views.cols, CV_8UC3, cv::Scalar(255, 255, 255));
  views.copyTo(picture(cv::Rect(0, kHeaderPx, views.cols, views.rows)));
  std::string title = options.title.empty() ? scene.source : options.title;
  title += cv::format(": %lld strands, motion %s", static_cast<long long>(strands.strand_count()),
                      frames.motion.c_str());
  cv::putText(picture, title, cv::Point(8, 14), cv::FONT_HERSHEY_SIMPLEX, 0.45,
              cv::Scalar(40, 40, 40), 1, cv::LINE_AA);
  if (colouring == FramesColouring::style)
    draw_style_legend(picture, cv::Point(10, 19), style_count);
  return picture;
}

void write_frames_video(const FramesScene& scene, const h5::File& file, const std::string& path,
                        FramesColouring colouring, RenderOptions options) {
  options.frame_points = frames_camera_box(scene, file);
  cv::VideoWriter writer;
  cv::Mat first = frame_picture(scene, read_frame_points(file, 0), 0, colouring, options);
  // Even sizes: encoders want whole macroblock pairs.
  cv::Size size(first.cols & ~1, first.rows & ~1);
  const double fps = scene.frames.fps;
  for (int fourcc :
       {cv::VideoWriter::fourcc('a', 'v', 'c', '1'), cv::VideoWriter::fourcc('m', 'p', '4', 'v')}) {
    if (writer.open(path, cv::CAP_FFMPEG, fourcc, fps, size)) break;
  }
  if (!writer.isOpened())
    throw Error::runtime(path,
                         "cannot open an MP4 video writer (OpenCV has neither an H.264 nor an "
                         "MPEG-4 encoder through FFmpeg; install libopencv-videoio-dev with "
                         "FFmpeg)");
  for (int64_t row = 0; row < scene.frames.frame_count(); ++row) {
    cv::Mat picture =
        row == 0 ? first
                 : frame_picture(scene, read_frame_points(file, row), row, colouring, options);
    writer.write(picture(cv::Rect(0, 0, size.width, size.height)));
  }
  writer.release();
}

}  // namespace hair
