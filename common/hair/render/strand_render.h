#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "hair/core/strand_set.h"
#include "hair/geom/triangle_mesh_distance.h"

namespace hair {

/// An orthographic view: the camera looks along -forward with +Y up.
enum class ViewDirection { front, side, back, top };

/// What to draw and how big.
struct RenderOptions {
  std::vector<ViewDirection> views{ViewDirection::front, ViewDirection::side, ViewDirection::back};
  int view_size_px = 512;  ///< each view is square
  double margin = 0.08;    ///< empty border, as a share of the view
  double line_width_px = 1.0;
  bool frame_on_strands = true;  ///< frame the views on the strands (else on the body)
  bool draw_body = true;         ///< draw the body (it still hides the strands behind it)
  std::string title;             ///< drawn at the top left, may be empty
  /// When not empty, every view is framed on these points instead of the strands or the
  /// body: e.g. the 8 corners of a box around every frame of an animation (exact, the
  /// views being along the axes), so that pictures of its frames share one camera.
  Points3f frame_points;
};

/// Line widths per strand (#strands, pixels); empty: RenderOptions::line_width_px for all.
using StrandWidths = std::vector<double>;

/// Per-point colours (#points, BGR 0-255) for a strand set.
using PointColours = std::vector<cv::Vec3b>;

/// Renders strands over a shaded body in orthographic views placed side by side.
/// Strand segments hidden behind the body are not drawn. The body may be empty.
///
/// @param strands          the strands to draw
/// @param colours          #points colours
/// @param body_vertices    #V x 3 body positions (may have 0 rows)
/// @param body_triangles   #T x 3 body triangles
/// @param widths           #strands line widths, or empty for options.line_width_px
/// @return a BGR image, #views * view_size_px wide
cv::Mat render_strands(const StrandSet& strands, const PointColours& colours,
                       const Points3f& body_vertices, const Triangles3i& body_triangles,
                       const RenderOptions& options, const StrandWidths& widths = {});

/// A colour per strand, cycling through a palette of distinguishable hues keyed by
/// `ids` (e.g. group or cluster ids): #points colours.
PointColours colours_by_id(const StrandSet& strands, const std::vector<int32_t>& strand_ids);

/// One colour per id (golden-angle hues, so neighbouring ids differ; -1, none, dark).
cv::Vec3b id_colour(int32_t id);

/// Every point in the colour of its own id (#points ids).
PointColours colours_by_point_id(const std::vector<int32_t>& point_ids);

/// A gradient from root (dark blue) to tip (yellow) along every strand.
PointColours colours_root_to_tip(const StrandSet& strands);

/// A fixed colour per strand from a table indexed by `strand_values` (enum values).
PointColours colours_by_table(const StrandSet& strands, const std::vector<int32_t>& strand_values,
                              const std::vector<cv::Vec3b>& table);

/// Writes an image as PNG; throws hair::Error (runtime) naming the file on failure.
void write_png(const cv::Mat& image, const std::string& path);

}  // namespace hair
