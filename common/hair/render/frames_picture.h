#pragma once
// Pictures and preview videos of interpolate's frames.h5: every strand of a frame over the
// body moved by the head, coloured by style or by cluster.

#include <opencv2/core.hpp>
#include <string>

#include "hair/geom/triangle_mesh_distance.h"
#include "hair/h5/file.h"
#include "hair/interp/frames_io.h"
#include "hair/render/strand_render.h"

namespace hair {

/// How a frames picture colours the strands: every point in the paper's colour of the style
/// its cluster was simulated as (/clusters/simulated_style), or its cluster's colour.
enum class FramesColouring { style, cluster };

/// "style" or "cluster"; Error::usage for another word.
FramesColouring parse_frames_colouring(const std::string& word);

/// frames.h5 opened for pictures: its header, the body at rest.
struct FramesScene {
  FramesFile frames;
  Points3f body_vertices;      ///< #V x 3, at rest
  Triangles3i body_triangles;  ///< #T x 3
  std::string source;          ///< frames.h5, named in errors
};

/// Reads frames.h5 and the body of its model's extract.h5 (bad_input naming extract.h5 if
/// its head height is not the frames').
FramesScene read_frames_scene(const h5::File& frames, const h5::File& extract);

/// The camera box of the animation: the 8 corners of the box around every frame's points
/// (read from `file`) and the head (the body within H of its top) moved by each frame's
/// head transform, so that every frame of a video has one camera.
Points3f frames_camera_box(const FramesScene& scene, const h5::File& file);

/// A picture of row `row` of /frames/points (`points`, #points x 3): the views of
/// `options`, the body moved by the frame's head transform, a caption with the frame and its
/// time, and, by style, a legend with the strands per style.
cv::Mat frame_picture(const FramesScene& scene, const Points3f& points, int64_t row,
                      FramesColouring colouring, const RenderOptions& options);

/// Writes an MP4 video of every row of /frames/points at the simulation's fps, one
/// picture per frame with one camera (cv::VideoWriter, H.264 'avc1' if the OpenCV build
/// has an encoder for it, else MPEG-4 'mp4v'). Throws Error::runtime naming `path` if
/// neither can be opened.
void write_frames_video(const FramesScene& scene, const h5::File& file, const std::string& path,
                        FramesColouring colouring, RenderOptions options);

}  // namespace hair
