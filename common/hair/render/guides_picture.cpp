#include "hair/render/guides_picture.h"

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <variant>

#include "hair/core/error.h"
#include "hair/extract/extract_io.h"
#include "hair/h5/attribute.h"
#include "hair/render/style_picture.h"

namespace hair {
namespace {

constexpr int kHeaderPx = 56;             // title and legend above the panels
constexpr double kWispWidthFactor = 3.0;  // wisp centres are drawn this many times as thick

/// A per-strand attribute of the guides, checked to have one value per guide.
const std::vector<int32_t>& guide_column(const GuidesPictureInput& input, const std::string& name) {
  const StrandSet& rest = input.guides.rest;
  auto found = rest.strand_attributes.find(name);
  const auto* column = found == rest.strand_attributes.end()
                           ? nullptr
                           : std::get_if<std::vector<int32_t>>(&found->second);
  if (column == nullptr || static_cast<int64_t>(column->size()) != rest.strand_count())
    throw Error::bad_dataset(
        input.source, "/guides/" + name,
        "does not have one value per guide (" + std::to_string(rest.strand_count()) + ")");
  return *column;
}

/// Checks that the arrays of the guides agree with each other.
void check_guides(const GuidesPictureInput& input) {
  const SimulatedGuides& guides = input.guides;
  if (guides.frame_count < 1) throw Error::bad_input(input.source, "has no frames");
  if (!(guides.fps > 0)) throw Error::bad_input(input.source, "has no positive fps");
  const auto expected =
      static_cast<size_t>(guides.frame_count) * static_cast<size_t>(guides.rest.point_count()) * 3;
  if (guides.guide_points_m.size() != expected)
    throw Error::bad_dataset(
        input.source, "/frames/guide_points",
        "has " + std::to_string(guides.guide_points_m.size()) +
            " values, not frames x guide points x 3 = " + std::to_string(expected));
  if (guides.head.size() != static_cast<size_t>(guides.frame_count))
    throw Error::bad_dataset(input.source, "/frames/head_rotation",
                             "has " + std::to_string(guides.head.size()) + " frames, not " +
                                 std::to_string(guides.frame_count));
}

/// The frames shown: `panels` spread evenly from the first to the last, each once.
std::vector<int32_t> panel_frames(int32_t frame_count, int panels) {
  const int count = std::min(panels, frame_count);
  if (count == 1) return {0};
  std::vector<int32_t> frames;
  for (int i = 0; i < count; ++i)
    frames.push_back(static_cast<int32_t>(
        std::lround(static_cast<double>(i) * (frame_count - 1) / (count - 1))));
  return frames;
}

/// The guide points of frame `frame`, #points x 3.
Eigen::Map<const Points3f> frame_points(const SimulatedGuides& guides, int32_t frame) {
  const Eigen::Index points = guides.rest.point_count();
  return Eigen::Map<const Points3f>(guides.guide_points_m.data() + frame * points * 3, points, 3);
}

/// The body moved by `head`: x_world = R x_rest + t.
Points3f moved_body(const Points3f& vertices, const RigidTransform& head) {
  const Eigen::Matrix3f rotation = head.rotation.normalized().toRotationMatrix().cast<float>();
  const Eigen::RowVector3f translation = head.translation_m.transpose().cast<float>();
  Points3f moved = vertices * rotation.transpose();
  moved.rowwise() += translation;
  return moved;
}

/// The 8 corners of the box around the guides and the head (the body vertices within
/// the head height of the highest at rest) in every frame; no rows if there is nothing.
Points3f camera_box(const GuidesPictureInput& input) {
  const SimulatedGuides& guides = input.guides;
  Eigen::Array3f low = Eigen::Array3f::Constant(std::numeric_limits<float>::infinity());
  Eigen::Array3f high = -low;
  auto include = [&](const auto& points) {
    for (Eigen::Index i = 0; i < points.rows(); ++i) {
      low = low.min(points.row(i).transpose().array());
      high = high.max(points.row(i).transpose().array());
    }
  };
  Points3f head;
  const Points3f& body = input.body_vertices;
  if (body.rows() > 0) {
    const float neck_y_m = body.col(1).maxCoeff() - static_cast<float>(guides.head_height_m);
    std::vector<Eigen::Index> rows;
    for (Eigen::Index v = 0; v < body.rows(); ++v)
      if (body(v, 1) >= neck_y_m) rows.push_back(v);
    head = body(rows, Eigen::all);
  }
  for (int32_t f = 0; f < guides.frame_count; ++f) {
    include(frame_points(guides, f));
    include(moved_body(head, guides.head[static_cast<size_t>(f)]));
  }
  if (!(low <= high).all()) return {};
  Points3f corners(8, 3);
  for (int c = 0; c < 8; ++c)
    corners.row(c) << (c & 1 ? high : low).x(), (c & 2 ? high : low).y(), (c & 4 ? high : low).z();
  return corners;
}

}  // namespace

cv::Mat guides_picture(const GuidesPictureInput& input, const RenderOptions& options, int panels) {
  if (panels < 2)
    throw Error::usage(
        "a guides picture needs at least 2 panels (the first and the last "
        "frame), not " +
        std::to_string(panels));
  check_guides(input);
  const SimulatedGuides& guides = input.guides;
  const std::vector<int32_t>& style = guide_column(input, "style");
  const std::vector<int32_t>& kind = guide_column(input, "kind");

  // Colours and widths per guide, the same in every frame.
  StrandSet strands = guides.rest;
  PointColours colours(static_cast<size_t>(strands.point_count()));
  StrandWidths widths(static_cast<size_t>(strands.strand_count()), options.line_width_px);
  std::array<int, 4> style_count{};
  int wisp_centres = 0;
  for (int64_t s = 0; s < strands.strand_count(); ++s) {
    std::fill(colours.begin() + strands.offsets[s], colours.begin() + strands.offsets[s + 1],
              style_colour(static_cast<int8_t>(style[s])));
    if (style[s] >= 0 && style[s] < 4) ++style_count[static_cast<size_t>(style[s])];
    if (kind[s] == static_cast<int32_t>(GuideKind::wisp_centre)) {
      widths[s] = kWispWidthFactor * options.line_width_px;
      ++wisp_centres;
    }
  }

  RenderOptions panel_options = options;
  panel_options.frame_points = camera_box(input);
  const std::vector<int32_t> frames = panel_frames(guides.frame_count, panels);
  const int count = static_cast<int>(frames.size());
  const int columns = count <= 4 ? count : (count + 1) / 2;
  const int rows = (count + columns - 1) / columns;
  const int panel_width = options.view_size_px * static_cast<int>(options.views.size());
  const int panel_height = options.view_size_px;
  cv::Mat sheet(kHeaderPx + rows * panel_height, columns * panel_width, CV_8UC3,
                cv::Scalar(255, 255, 255));
  for (int p = 0; p < count; ++p) {
    const int32_t frame = frames[static_cast<size_t>(p)];
    strands.points = frame_points(guides, frame);
    panel_options.title = cv::format("frame %d   %.2f s", frame, frame / guides.fps);
    cv::Mat panel = render_strands(
        strands, colours, moved_body(input.body_vertices, guides.head[static_cast<size_t>(frame)]),
        input.body_triangles, panel_options, widths);
    cv::Rect where((p % columns) * panel_width, kHeaderPx + (p / columns) * panel_height,
                   panel_width, panel_height);
    panel.copyTo(sheet(where));
    cv::rectangle(sheet, where, cv::Scalar(190, 190, 190), 1);
  }

  std::string title = options.title.empty() ? "" : options.title + ": ";
  title += "motion " + input.motion + ", " + std::to_string(strands.strand_count()) + " guides, " +
           std::to_string(guides.frame_count) + " frames at " + cv::format("%g", guides.fps) +
           " fps";
  cv::putText(sheet, title, cv::Point(8, 22), cv::FONT_HERSHEY_SIMPLEX, 0.6, cv::Scalar(40, 40, 40),
              1, cv::LINE_AA);
  int x = draw_style_legend(sheet, cv::Point(10, 34), style_count);
  if (wisp_centres > 0)
    cv::putText(sheet, "(thick: wisp centres " + std::to_string(wisp_centres) + ")",
                cv::Point(x, 45), cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(40, 40, 40), 1,
                cv::LINE_AA);
  return sheet;
}

cv::Mat guides_picture(const h5::File& guides, const h5::File& extract,
                       const RenderOptions& options, int panels) {
  GuidesPictureInput input;
  input.guides = read_simulated_guides(guides);
  input.motion = h5::read_string_attribute(guides, "/", "motion");
  input.source = guides.name();
  ExtractedBody body = read_extracted_body(extract);
  const double body_head_height_m = h5::read_double_attribute(extract, "/", "head_height_m");
  if (std::abs(body_head_height_m - input.guides.head_height_m) >
      1e-6 * std::max(body_head_height_m, input.guides.head_height_m))
    throw Error::bad_input(
        extract.name(),
        cv::format("has head height %.4f m, %s %.4f m: made from another model", body_head_height_m,
                   guides.name().c_str(), input.guides.head_height_m));
  input.body_vertices = std::move(body.vertices);
  input.body_triangles = std::move(body.triangles);
  return guides_picture(input, options, panels);
}

}  // namespace hair
