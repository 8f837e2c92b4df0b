#pragma once
// Reading the interpolate stage's inputs (guides.h5, strands.h5, styles.h5) and writing
// and reading its output, frames.h5 (schemas/frames.json).

#include <cstdint>
#include <string>
#include <vector>

#include "hair/core/strand_set.h"
#include "hair/h5/enum_dataset.h"
#include "hair/h5/file.h"
#include "hair/interp/strand_interpolation.h"
#include "hair/sim/head_motion.h"

namespace hair {

/// Schema name of the interpolate stage's output (schemas/frames.json).
inline constexpr const char* kFramesSchema = "hairstyle.frames";

/// Members of the enum dataset /strands/method.
const h5::EnumMembers& interpolation_method_members();

/// What interpolation reads: the grown strands (point attribute "cluster"), the guides
/// and wisps, and the simulation's frames but for their points.
struct InterpolationInput {
  StrandSet strands;
  InterpolationGuides guides;
  std::vector<int8_t> cluster_style;  ///< styles.h5
  double head_height_m = 0;
  double fps = 0;
  std::string motion;
  int64_t frame_count = 0;
  int64_t wisp_tetrahedron_count = 0;
  std::vector<double> time_s;        ///< per frame
  std::vector<RigidTransform> head;  ///< per frame
};

/// Reads guides.h5, strands.h5 and styles.h5 after checking their schemas and that they
/// come from one model (cluster counts; every guide's first particle on its grown strand;
/// the wisps' bound points among the strands' points): bad_input naming the file at fault.
InterpolationInput read_interpolation_input(const h5::File& guides, const h5::File& strands,
                                            const h5::File& styles);

/// The guides' points (#guide points x 3) and wisp frames (#tetrahedra x 7) of frame
/// `frame` of guides.h5.
struct GuideFrameData {
  std::vector<float> guide_points_m;
  std::vector<float> wisp_frames;
};
GuideFrameData read_guide_frame(const h5::File& guides, int64_t frame);

/// What frames.h5 records besides the bindings and the points.
struct FramesFileInfo {
  double head_height_m = 0;
  double fps = 0;
  std::string motion;
  int64_t first_frame = 0;
  int64_t source_frame_count = 0;
  double rest_max_deviation_m = 0;
  std::vector<int8_t> cluster_style, simulated_style;
  std::vector<int64_t> guide_strand;       ///< grown strand of every guide (-1 for wisp centres)
  double interpolation_ms_per_frame = -1;  ///< left out when negative (reproducible runs)
};

/// Writes frames.h5's attributes, /strands and /clusters (schemas/frames.json) but for
/// provenance and the frames.
void write_frames_bindings(h5::File& file, const StrandSet& strands, const StrandBinding& binding,
                           const FramesFileInfo& info);

/// Writes /frames/index, time_s, head_rotation and head_translation_m of the frames in
/// the file (the points go through h5::FrameDatasetWriter on "/frames/points").
void write_frames_timeline(h5::File& file, const std::vector<int64_t>& index,
                           const std::vector<double>& time_s,
                           const std::vector<RigidTransform>& head);

/// What exporters and pictures read of frames.h5 (not the points of the frames).
struct FramesFile {
  /// The grown strands at rest, with the strand attributes "cluster", "method" and
  /// "is_guide" (1 for a strand simulated as a guide) and the
  /// point attribute "cluster".
  StrandSet rest;
  std::vector<int8_t> cluster_style, simulated_style;
  double head_height_m = 0, fps = 0;
  std::string motion;
  int64_t first_frame = 0;
  std::vector<int64_t> index;  ///< guides.h5 frame of each row
  std::vector<double> time_s;
  std::vector<RigidTransform> head;
  int64_t frame_count() const { return static_cast<int64_t>(index.size()); }
};

/// Reads frames.h5 after checking its schema.
FramesFile read_frames_file(const h5::File& file);

/// The points of row `row` of /frames/points: #points x 3.
Points3f read_frame_points(const h5::File& file, int64_t row);

}  // namespace hair
