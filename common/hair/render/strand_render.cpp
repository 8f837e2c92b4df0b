#include "hair/render/strand_render.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <limits>
#include <map>
#include <numeric>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <tuple>

#include "hair/core/error.h"

namespace hair {
namespace {

/// Screen axes (right, up) and the direction towards the viewer for a view.
struct ViewAxes {
  Eigen::Vector3d right, up, towards_viewer;
};

ViewAxes view_axes(ViewDirection view) {
  switch (view) {
    case ViewDirection::front:
      return {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    case ViewDirection::side:
      return {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}};
    case ViewDirection::back:
      return {{-1, 0, 0}, {0, 1, 0}, {0, 0, -1}};
    case ViewDirection::top:
      return {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}};
  }
  return {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
}

/// Maps world points to pixels of one view: x right, y down, depth towards the viewer.
struct Projection {
  ViewAxes axes;
  Eigen::Vector2d centre;
  double pixels_per_unit = 1;
  int size_px = 512;

  Eigen::Vector3d operator()(const Eigen::Vector3d& p) const {
    double x = (p.dot(axes.right) - centre.x()) * pixels_per_unit + size_px / 2.0;
    double y = size_px / 2.0 - (p.dot(axes.up) - centre.y()) * pixels_per_unit;
    return {x, y, p.dot(axes.towards_viewer)};
  }
};

Projection framing(const Points3f& points, ViewDirection view, const RenderOptions& options) {
  Projection projection;
  projection.axes = view_axes(view);
  projection.size_px = options.view_size_px;
  Eigen::Vector2d low = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d high = -low;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    Eigen::Vector3d p = points.row(i).cast<double>().transpose();
    Eigen::Vector2d screen(p.dot(projection.axes.right), p.dot(projection.axes.up));
    low = low.cwiseMin(screen);
    high = high.cwiseMax(screen);
  }
  if (points.rows() == 0) low = high = Eigen::Vector2d::Zero();
  projection.centre = (low + high) / 2;
  double extent = std::max({(high - low).maxCoeff(), 1e-6});
  projection.pixels_per_unit = options.view_size_px * (1 - 2 * options.margin) / extent;
  return projection;
}

/// Draws the body with flat shading into `image` and its depth into `depth`.
void draw_body(const Points3f& vertices, const Triangles3i& triangles, const Projection& projection,
               cv::Mat& image, cv::Mat& depth) {
  std::vector<Eigen::Vector3d> screen(static_cast<size_t>(vertices.rows()));
  for (Eigen::Index v = 0; v < vertices.rows(); ++v)
    screen[v] = projection(vertices.row(v).cast<double>().transpose());
  std::vector<std::pair<double, Eigen::Index>> order;
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    double z =
        (screen[triangles(t, 0)].z() + screen[triangles(t, 1)].z() + screen[triangles(t, 2)].z()) /
        3;
    order.push_back({z, t});
  }
  std::sort(order.begin(), order.end());  // far to near: painter's order
  Eigen::Vector3d light = (projection.axes.towards_viewer + 0.5 * projection.axes.up).normalized();
  for (auto [z, t] : order) {
    Eigen::Vector3d a = vertices.row(triangles(t, 0)).cast<double>().transpose();
    Eigen::Vector3d b = vertices.row(triangles(t, 1)).cast<double>().transpose();
    Eigen::Vector3d c = vertices.row(triangles(t, 2)).cast<double>().transpose();
    Eigen::Vector3d normal = (b - a).cross(c - a);
    if (normal.norm() <= 0) continue;
    double shade = 0.35 + 0.55 * std::abs(normal.normalized().dot(light));
    auto grey = static_cast<uint8_t>(std::clamp(shade * 255, 0.0, 255.0));
    cv::Point corners[3];
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d& s = screen[triangles(t, k)];
      corners[k] = cv::Point(static_cast<int>(std::lround(s.x() * 16)),
                             static_cast<int>(std::lround(s.y() * 16)));
    }
    cv::fillConvexPoly(image, corners, 3, cv::Scalar(grey, grey, grey), cv::LINE_AA, 4);
    cv::fillConvexPoly(depth, corners, 3, cv::Scalar(z), cv::LINE_8, 4);
  }
}

}  // namespace

cv::Mat render_strands(const StrandSet& strands, const PointColours& colours,
                       const Points3f& body_vertices, const Triangles3i& body_triangles,
                       const RenderOptions& options, const StrandWidths& widths) {
  if (!widths.empty() && static_cast<int64_t>(widths.size()) != strands.strand_count())
    throw Error::usage("render_strands: " + std::to_string(widths.size()) + " line widths for " +
                       std::to_string(strands.strand_count()) + " strands");
  int size = options.view_size_px;
  cv::Mat canvas(size, size * static_cast<int>(options.views.size()), CV_8UC3,
                 cv::Scalar(255, 255, 255));
  const Points3f& drawn_points =
      options.frame_on_strands && strands.point_count() > 0 ? strands.points : body_vertices;
  const Points3f& frame_points =
      options.frame_points.rows() > 0 ? options.frame_points : drawn_points;
  for (size_t view_index = 0; view_index < options.views.size(); ++view_index) {
    Projection projection = framing(frame_points, options.views[view_index], options);
    cv::Mat view = canvas(cv::Rect(static_cast<int>(view_index) * size, 0, size, size));
    cv::Mat depth(size, size, CV_64F, cv::Scalar(-std::numeric_limits<double>::infinity()));
    if (body_triangles.rows() > 0) {
      cv::Mat body_image = options.draw_body ? view : view.clone();
      draw_body(body_vertices, body_triangles, projection, body_image, depth);
    }

    // Strand segments far to near, each drawn unless the body is in front of it.
    // Each segment: its depth, its first point and its strand.
    struct Segment {
      double z;
      int64_t i, strand;
      bool operator<(const Segment& other) const {
        return std::tie(z, i) < std::tie(other.z, other.i);
      }
    };
    std::vector<Segment> segments;
    std::vector<Eigen::Vector3d> screen(static_cast<size_t>(strands.point_count()));
    for (int64_t i = 0; i < strands.point_count(); ++i)
      screen[i] = projection(strands.points.row(i).cast<double>().transpose());
    for (int64_t s = 0; s < strands.strand_count(); ++s)
      for (int64_t i = strands.offsets[s]; i + 1 < strands.offsets[s + 1]; ++i)
        segments.push_back({(screen[i].z() + screen[i + 1].z()) / 2, i, s});
    std::sort(segments.begin(), segments.end());
    constexpr double depth_tolerance_m = 0.004;  // hair lies on the body
    auto thickness_px = [](double width_px) {
      return std::max(1, static_cast<int>(std::lround(width_px)));
    };
    const int thickness = thickness_px(options.line_width_px);
    for (auto [z, i, strand] : segments) {
      Eigen::Vector3d middle = (screen[i] + screen[i + 1]) / 2;
      int px = static_cast<int>(middle.x()), py = static_cast<int>(middle.y());
      if (px >= 0 && py >= 0 && px < size && py < size &&
          depth.at<double>(py, px) > z + depth_tolerance_m)
        continue;
      // Long segments are drawn in pieces so that colours blend along them.
      Eigen::Vector2d from = screen[i].head<2>(), to = screen[i + 1].head<2>();
      int pieces = std::clamp(static_cast<int>((to - from).norm() / 6.0), 1, 16);
      for (int k = 0; k < pieces; ++k) {
        double t0 = static_cast<double>(k) / pieces, t1 = static_cast<double>(k + 1) / pieces;
        cv::Vec3d blended = cv::Vec3d(colours[i]) * (1 - (t0 + t1) / 2) +
                            cv::Vec3d(colours[i + 1]) * ((t0 + t1) / 2);
        Eigen::Vector2d a = from + t0 * (to - from), b = from + t1 * (to - from);
        cv::line(view,
                 cv::Point(static_cast<int>(std::lround(a.x() * 16)),
                           static_cast<int>(std::lround(a.y() * 16))),
                 cv::Point(static_cast<int>(std::lround(b.x() * 16)),
                           static_cast<int>(std::lround(b.y() * 16))),
                 cv::Scalar(blended[0], blended[1], blended[2]),
                 widths.empty() ? thickness : thickness_px(widths[strand]), cv::LINE_AA, 4);
      }
    }
  }
  if (!options.title.empty())
    cv::putText(canvas, options.title, cv::Point(8, 22), cv::FONT_HERSHEY_SIMPLEX, 0.6,
                cv::Scalar(40, 40, 40), 1, cv::LINE_AA);
  return canvas;
}

cv::Vec3b id_colour(int32_t id) {
  // Golden-angle hues give neighbouring ids distinct colours; -1 (none) is dark.
  double hue = std::fmod(std::max(0, id) * 137.508, 360.0);
  cv::Mat hsv(1, 1, CV_8UC3, cv::Scalar(hue / 2, 200, id < 0 ? 60 : 220)), bgr;
  cv::cvtColor(hsv, bgr, cv::COLOR_HSV2BGR);
  return bgr.at<cv::Vec3b>(0, 0);
}

PointColours colours_by_id(const StrandSet& strands, const std::vector<int32_t>& strand_ids) {
  PointColours colours(static_cast<size_t>(strands.point_count()));
  for (int64_t s = 0; s < strands.strand_count(); ++s)
    std::fill(colours.begin() + strands.offsets[s], colours.begin() + strands.offsets[s + 1],
              id_colour(strand_ids[s]));
  return colours;
}

PointColours colours_by_point_id(const std::vector<int32_t>& point_ids) {
  std::map<int32_t, cv::Vec3b> cache;
  PointColours colours;
  colours.reserve(point_ids.size());
  for (int32_t id : point_ids) {
    auto found = cache.find(id);
    if (found == cache.end()) found = cache.emplace(id, id_colour(id)).first;
    colours.push_back(found->second);
  }
  return colours;
}

PointColours colours_root_to_tip(const StrandSet& strands) {
  PointColours colours(static_cast<size_t>(strands.point_count()));
  const cv::Vec3d root(140, 40, 20), tip(0, 220, 255);  // BGR: dark blue to yellow
  for (int64_t s = 0; s < strands.strand_count(); ++s) {
    int64_t n = strands.strand_size(s);
    for (int64_t i = 0; i < n; ++i) {
      double t = n > 1 ? static_cast<double>(i) / static_cast<double>(n - 1) : 0.0;
      cv::Vec3d c = root * (1 - t) + tip * t;
      colours[strands.offsets[s] + i] = cv::Vec3b(
          static_cast<uint8_t>(c[0]), static_cast<uint8_t>(c[1]), static_cast<uint8_t>(c[2]));
    }
  }
  return colours;
}

PointColours colours_by_table(const StrandSet& strands, const std::vector<int32_t>& strand_values,
                              const std::vector<cv::Vec3b>& table) {
  PointColours colours(static_cast<size_t>(strands.point_count()), cv::Vec3b(128, 128, 128));
  for (int64_t s = 0; s < strands.strand_count(); ++s) {
    int32_t value = strand_values[s];
    if (value < 0 || value >= static_cast<int32_t>(table.size())) continue;
    std::fill(colours.begin() + strands.offsets[s], colours.begin() + strands.offsets[s + 1],
              table[value]);
  }
  return colours;
}

void write_png(const cv::Mat& image, const std::string& path) {
  bool written = false;
  try {
    written = cv::imwrite(path, image, {cv::IMWRITE_PNG_COMPRESSION, 9});
  } catch (const cv::Exception& e) {
    throw Error::runtime(path, std::string("cannot write PNG: ") + e.what());
  }
  if (!written) throw Error::runtime(path, "cannot write PNG");
}

}  // namespace hair
