#pragma once

#include <opencv2/core.hpp>
#include <string>

#include "hair/core/strand_set.h"
#include "hair/geom/triangle_mesh_distance.h"
#include "hair/h5/file.h"
#include "hair/render/strand_render.h"
#include "hair/sim/guides_io.h"

namespace hair {

/// What guides_picture() draws: a simulation read from guides.h5 and the body at rest.
struct GuidesPictureInput {
  SimulatedGuides guides;
  std::string motion;          ///< the head motion's name, for the title
  Points3f body_vertices;      ///< #V x 3, at rest (may have 0 rows)
  Triangles3i body_triangles;  ///< #T x 3
  std::string source;          ///< the guides file, named in errors
};

/// A contact sheet of a simulation: `panels` frames spread evenly over the animation
/// (the first and the last included; every frame once if there are fewer), in one row,
/// or in two if there are more than 4. Each panel shows the views of `options` of that
/// frame: the body moved by the frame's head transform (x_world = R x_rest + t) and the
/// guides in the paper's colours of their styles (style_colour()), wisp centres three
/// times as thick, with the frame number and its time as caption. Every panel has the
/// same camera, so the motion shows: framed on the guides and the head (the body
/// vertices within the head height of its top at rest) in every frame, not on the whole
/// body. A header has the title (options.title, then the motion, guide and frame counts)
/// and a legend of the guides' styles.
///
/// Throws Error::usage for fewer than 2 panels; bad_input or bad_dataset naming
/// input.source for guides without frames or whose arrays disagree in size.
cv::Mat guides_picture(const GuidesPictureInput& input, const RenderOptions& options,
                       int panels = 6);

/// The contact sheet of guides.h5 `guides` (the motion from its "motion" attribute) over
/// the body of `extract` (the extract.h5 of its model). Errors (bad_input) name the file
/// at fault: a file of another schema, a body of another head height (another model).
cv::Mat guides_picture(const h5::File& guides, const h5::File& extract,
                       const RenderOptions& options, int panels = 6);

}  // namespace hair
