// interpolate: every grown strand per frame from the simulated guides (paper section 5.2,
// "Interpolation"), from guides.h5, strands.h5 and styles.h5 -> frames.h5.
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "hair/core/atomic_file.h"
#include "hair/core/error.h"
#include "hair/core/frame_range.h"
#include "hair/core/progress.h"
#include "hair/core/stage_app.h"
#include "hair/h5/frame_dataset.h"
#include "hair/h5/provenance.h"
#include "hair/h5/schema_validation.h"
#include "hair/interp/frames_io.h"
#include "hair/interp/interpolation_params.h"
#include "hair/interp/strand_interpolation.h"

namespace {

/// Throws a runtime error naming the frame and strand of the first non-finite value.
void require_finite(const std::vector<float>& points, const hair::StrandSet& strands, int64_t frame,
                    const std::string& source) {
  for (size_t i = 0; i < points.size(); ++i) {
    if (std::isfinite(points[i])) continue;
    auto row = static_cast<int64_t>(i / 3);
    auto strand = std::upper_bound(strands.offsets.begin(), strands.offsets.end(), row) -
                  strands.offsets.begin() - 1;
    throw hair::Error::runtime(source, "interpolation: frame " + std::to_string(frame) +
                                           ", strand " + std::to_string(strand) +
                                           ": a point is not finite");
  }
}

}  // namespace

int main(int argc, char** argv) {
  hair::StageApp app("interpolate",
                     "Every grown strand per frame from the simulated guides: barycentric "
                     "interpolation from three guides of a cluster, clump interpolation from "
                     "one, fixed hair with the head, braided hair from its wisp.");
  std::string guides_path, strands_path, styles_path, frames_text;
  app.cli().add_option("GUIDES_H5", guides_path, "guides.h5 from the simulate stage")->required();
  app.cli().add_option("STRANDS_H5", strands_path, "strands.h5 from the grow stage")->required();
  app.cli().add_option("STYLES_H5", styles_path, "styles.h5 from the classify stage")->required();
  app.cli().add_option("--frames", frames_text,
                       "frames of guides.h5 to compute: A:B (A to B-1), A:, :B or N; all by "
                       "default");
  hair::InterpolationParams params;
  hair::declare_interpolation_params(app.params(), params);

  return app.run(argc, argv, [&] {
    hair::h5::File guides_file = hair::h5::File::open_read_only(guides_path);
    hair::InterpolationInput input =
        hair::read_interpolation_input(guides_file, hair::h5::File::open_read_only(strands_path),
                                       hair::h5::File::open_read_only(styles_path));
    const hair::FrameRange range = hair::parse_frame_range(frames_text, input.frame_count);
    const hair::StrandSet& strands = input.strands;

    auto bind_start = std::chrono::steady_clock::now();
    hair::StrandBinding binding = hair::bind_strands(strands, input.guides, params);
    double bind_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - bind_start).count();
    int64_t by_method[4] = {0, 0, 0, 0};
    for (hair::InterpolationMethod method : binding.method) ++by_method[static_cast<int>(method)];

    // The error at rest: frame 0 against the grown strands carried by the head.
    std::vector<float> points;
    {
      hair::GuideFrameData data = hair::read_guide_frame(guides_file, 0);
      hair::GuideFrame frame{data.guide_points_m.data(), data.wisp_frames.data(), input.head[0]};
      hair::interpolate_frame(binding, strands, frame, points);
      require_finite(points, strands, 0, guides_path);
    }
    double rest_deviation_m = 0;
    for (int64_t row = 0; row < strands.point_count(); ++row) {
      Eigen::Vector3d expected = input.head[0].apply(hair::point_of(strands.points, row));
      Eigen::Vector3d found(points[3 * row], points[3 * row + 1], points[3 * row + 2]);
      rest_deviation_m = std::max(rest_deviation_m, (found - expected).norm());
    }
    spdlog::info(
        "{}: {} strands ({} points): {} barycentric, {} clump, {} fixed, {} braided; bound "
        "in {:.3f} s; at rest within {:.2e} m ({:.2e} H)",
        strands_path, strands.strand_count(), strands.point_count(), by_method[1], by_method[2],
        by_method[0], by_method[3], bind_s, rest_deviation_m,
        rest_deviation_m / input.head_height_m);

    hair::AtomicFile output(app.output_path());
    hair::h5::File file = hair::h5::File::create(output.temporary_path(), app.output_path());
    hair::FramesFileInfo info;
    info.head_height_m = input.head_height_m;
    info.fps = input.fps;
    info.motion = input.motion;
    info.first_frame = range.first;
    info.source_frame_count = input.frame_count;
    info.rest_max_deviation_m = rest_deviation_m;
    info.cluster_style = input.cluster_style;
    info.simulated_style = input.guides.cluster_simulated_style;
    info.guide_strand = input.guides.strand;

    // The frames, one chunk each.
    hair::h5::FrameDatasetWriter writer(file, "/frames/points", range.count(),
                                        strands.point_count(), 3);
    std::vector<int64_t> index;
    std::vector<double> time_s, frame_ms;
    std::vector<hair::RigidTransform> head;
    hair::Progress progress("interpolating frames", range.count());
    for (int64_t f = range.first; f < range.end; ++f) {
      hair::GuideFrameData data = hair::read_guide_frame(guides_file, f);
      hair::GuideFrame frame{data.guide_points_m.data(), data.wisp_frames.data(),
                             input.head[static_cast<size_t>(f)]};
      auto start = std::chrono::steady_clock::now();
      hair::interpolate_frame(binding, strands, frame, points);
      frame_ms.push_back(
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
              .count());
      require_finite(points, strands, f, guides_path);
      writer.write(f - range.first, points);
      index.push_back(f);
      time_s.push_back(input.time_s[static_cast<size_t>(f)]);
      head.push_back(input.head[static_cast<size_t>(f)]);
      progress.advance();
    }
    progress.finish();
    std::vector<double> sorted = frame_ms;
    std::nth_element(sorted.begin(),
                     sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
    const double median_ms = sorted[sorted.size() / 2];
    spdlog::info("{}: frames {} to {}: {:.3f} ms per frame of interpolation (median)", guides_path,
                 range.first, range.end - 1, median_ms);
    if (!app.reproducible()) info.interpolation_ms_per_frame = median_ms;
    hair::write_frames_bindings(file, strands, binding, info);
    hair::write_frames_timeline(file, index, time_s, head);
    hair::write_provenance(
        file, hair::stage_provenance(
                  "interpolate", app.params().effective_json().dump(),
                  {{"guides", guides_path}, {"strands", strands_path}, {"styles", styles_path}},
                  app.elapsed_s(), app.reproducible()));
    hair::h5::require_valid_output(file, hair::kFramesSchema);
    file.close();
    output.commit();
  });
}
