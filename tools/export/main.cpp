// hair-export: the strands of interpolate's frames.h5 in formats that hair tools read:
// ASCII USD (.usda): the rest groom as BasisCurves with the Alembic groom attributes as
// primvars, and on request a layer of the animation over it; OBJ polylines (one file per
// frame) and cyHair .hair (one frame).
// docs/interpolate.md describes the formats and the mapping to the groom conventions.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <numbers>

#include "hair/core/error.h"
#include "hair/core/frame_range.h"
#include "hair/export/strand_export.h"
#include "hair/geom/strand_simplify.h"
#include "hair/h5/file.h"
#include "hair/interp/frames_io.h"

namespace {

namespace fs = std::filesystem;

/// Rows of frames.h5 for guides.h5 frames `range` (which must lie within the file's).
std::vector<int64_t> rows_of(const hair::FramesFile& frames, const hair::FrameRange& range,
                             const std::string& source) {
  const int64_t first = frames.first_frame, end = first + frames.frame_count();
  if (range.first < first || range.end > end)
    throw hair::Error::usage(source + " holds frames " + std::to_string(first) + " to " +
                             std::to_string(end - 1) + " only, not " + std::to_string(range.first) +
                             " to " + std::to_string(range.end - 1));
  std::vector<int64_t> rows;
  for (int64_t f = range.first; f < range.end; ++f) rows.push_back(f - first);
  return rows;
}

/// Width per point: `root_m` at the root tapering linearly to a third of it at the tip.
std::vector<float> tapered_widths(const hair::StrandSet& strands, double root_m) {
  std::vector<float> widths(static_cast<size_t>(strands.point_count()));
  for (int64_t s = 0; s < strands.strand_count(); ++s) {
    const int64_t begin = strands.offsets[static_cast<size_t>(s)];
    const int64_t size = strands.strand_size(s);
    for (int64_t i = 0; i < size; ++i)
      widths[static_cast<size_t>(begin + i)] = static_cast<float>(
          root_m * (1.0 - 2.0 / 3.0 * static_cast<double>(i) /
                              static_cast<double>(std::max<int64_t>(1, size - 1))));
  }
  return widths;
}

/// Root UVs: a spherical projection of the roots about their centroid, u the angle about
/// +Y from +Z (0.5 at the face), v the height from the lowest root (0) to the highest (1).
std::vector<Eigen::Vector2f> root_uvs(const hair::StrandSet& strands) {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double low = INFINITY, high = -INFINITY;
  for (int64_t s = 0; s < strands.strand_count(); ++s) {
    Eigen::Vector3d root = hair::point_of(strands.points, strands.offsets[static_cast<size_t>(s)]);
    centre += root;
    low = std::min(low, root.y());
    high = std::max(high, root.y());
  }
  centre /= static_cast<double>(std::max<int64_t>(1, strands.strand_count()));
  std::vector<Eigen::Vector2f> uv;
  for (int64_t s = 0; s < strands.strand_count(); ++s) {
    Eigen::Vector3d root =
        hair::point_of(strands.points, strands.offsets[static_cast<size_t>(s)]) - centre;
    double u = 0.5 + std::atan2(root.x(), root.z()) / (2 * std::numbers::pi);
    double v = high > low ? (root.y() + centre.y() - low) / (high - low) : 0.0;
    uv.emplace_back(static_cast<float>(u), static_cast<float>(v));
  }
  return uv;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("Export the strands of frames.h5 (interpolate) to USD, OBJ and cyHair.",
               "hair-export");
  std::string input_path, usda_path, animation_path, over_path, obj_dir, hair_path, frames_text;
  int64_t frame = -1;
  double width_m = 8e-5;
  app.add_option("FRAMES_H5", input_path, "frames.h5 from the interpolate stage")->required();
  app.add_option("--usda", usda_path,
                 "ASCII USD file of the rest groom: BasisCurves with the groom attributes, "
                 "no animation");
  app.add_option("--usda-animation", animation_path,
                 "ASCII USD layer of the points of every frame of --frames as time samples, "
                 "over the groom layer (which it names in subLayers): the --usda one, or "
                 "--over");
  app.add_option("--over", over_path,
                 "--usda-animation: an existing groom layer (--usda of an earlier run) to "
                 "animate, instead of writing one now");
  app.add_option("--obj", obj_dir,
                 "folder for OBJ polylines, one file per frame of --frames "
                 "(frame_NNNN.obj, NNNN the simulation's frame)");
  app.add_option("--hair", hair_path, "cyHair .hair file of the frame --frame");
  app.add_option("--frames", frames_text,
                 "frames of the simulation to export (A:B is A to B-1, A:, :B or N); all the "
                 "file holds by default");
  app.add_option("--frame", frame, "the frame of --hair (default: the file's first)");
  app.add_option("--width_m", width_m,
                 "strand width at the root, metres (a third of it at the tip)")
      ->check(CLI::PositiveNumber);
  double tolerance_m = 0;
  CLI::Option* tolerance = app.add_option(
      "--tolerance_m", tolerance_m,
      "keep only the points each strand needs to stay within this distance of its shape at "
      "rest and in every frame of FRAMES_H5, metres (Douglas-Peucker on each; the same points "
      "in every frame and every export of the file; default: every point)");
  tolerance->check(CLI::NonNegativeNumber);
  try {
    app.parse(argc, argv);
    if (!animation_path.empty() && usda_path.empty() == over_path.empty())
      throw CLI::ValidationError(
          "--usda-animation needs the groom layer it animates: --usda (written now) or --over "
          "(an existing one), one of them");
    if (!over_path.empty() && animation_path.empty())
      throw CLI::ValidationError("--over names the groom layer of --usda-animation");
    if (usda_path.empty() && obj_dir.empty() && hair_path.empty() && animation_path.empty())
      throw CLI::ValidationError("nothing to do: give --usda, --obj or --hair");
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "hair-export: error: " << e.what() << "\n";
    return 2;
  }
  try {
    hair::h5::File file = hair::h5::File::open_read_only(input_path);
    hair::FramesFile frames = hair::read_frames_file(file);
    const int64_t last = frames.first_frame + frames.frame_count();
    hair::FrameRange range = frames_text.empty() ? hair::FrameRange{frames.first_frame, last}
                                                 : hair::parse_frame_range(frames_text, last);
    std::vector<int64_t> rows = rows_of(frames, range, input_path);
    // The points written: every one, or those the tolerance keeps (chosen on the rest
    // shape, the same in every frame).
    std::vector<int64_t> kept;
    hair::StrandSet strands = frames.rest;
    double largest_deviation_m = 0;
    if (tolerance->count() > 0) {
      // The points the rest shape needs and those every frame of the file needs (motion
      // bends hair where it lay straight): they depend on the file and the tolerance
      // only, so a groom layer and an animation over it exported apart fit each other.
      kept = hair::rows_within_tolerance(frames.rest, tolerance_m);
      hair::StrandSet shape;
      shape.offsets = frames.rest.offsets;
      for (int64_t row = 0; row < frames.frame_count(); ++row) {
        shape.points = hair::read_frame_points(file, row);
        std::vector<int64_t> needed = hair::rows_within_tolerance(shape, tolerance_m), both;
        std::set_union(kept.begin(), kept.end(), needed.begin(), needed.end(),
                       std::back_inserter(both));
        kept = std::move(both);
      }
      strands = hair::select_points(frames.rest, kept);
      largest_deviation_m = hair::largest_deviation(frames.rest.points, kept);
    }
    const auto frame_points = [&](int64_t row) {
      hair::Points3f points = hair::read_frame_points(file, row);
      if (kept.empty()) return points;
      largest_deviation_m = std::max(largest_deviation_m, hair::largest_deviation(points, kept));
      return hair::select_rows(points, kept);
    };
    const std::string note = "from " + input_path + ", motion " + frames.motion;
    std::vector<float> widths = tapered_widths(strands, width_m);

    if (!usda_path.empty()) {
      hair::UsdaCurves curves;
      curves.offsets = strands.offsets;
      const auto& cluster = std::get<std::vector<int32_t>>(strands.strand_attributes.at("cluster"));
      const auto& point_cluster =
          std::get<std::vector<int32_t>>(strands.point_attributes.at("cluster"));
      curves.cluster = cluster;
      curves.groom_guide = std::get<std::vector<int32_t>>(strands.strand_attributes.at("is_guide"));
      for (int64_t s = 0; s < strands.strand_count(); ++s) {
        curves.groom_id.push_back(static_cast<int32_t>(s));
        int32_t tip_cluster =
            point_cluster[static_cast<size_t>(strands.offsets[static_cast<size_t>(s) + 1] - 1)];
        curves.style.push_back(frames.cluster_style[static_cast<size_t>(tip_cluster)]);
      }
      curves.root_uv = root_uvs(strands);
      curves.width_m = widths;
      curves.fps = frames.fps;
      curves.comment = note;
      if (fs::path parent = fs::path(usda_path).parent_path(); !parent.empty())
        fs::create_directories(parent);
      hair::write_usda_groom(usda_path, curves, strands.points);
    }
    if (!animation_path.empty()) {
      const fs::path groom = usda_path.empty() ? fs::path(over_path) : fs::path(usda_path);
      if (!fs::is_regular_file(groom))
        throw hair::Error::bad_input(groom.string(), "no such groom layer to animate");
      if (fs::path parent = fs::path(animation_path).parent_path(); !parent.empty())
        fs::create_directories(parent);
      std::vector<int64_t> codes;
      for (int64_t row : rows) codes.push_back(frames.index[static_cast<size_t>(row)]);
      const std::string groom_layer =
          fs::relative(fs::absolute(groom), fs::absolute(animation_path).parent_path())
              .generic_string();
      hair::write_usda_animation(animation_path, groom_layer, frames.fps, note, codes,
                                 [&](size_t k) { return frame_points(rows[k]); });
    }
    if (!obj_dir.empty()) {
      fs::create_directories(obj_dir);
      for (int64_t row : rows) {
        strands.points = frame_points(row);
        char name[32];
        std::snprintf(name, sizeof name, "frame_%04lld.obj",
                      static_cast<long long>(frames.index[static_cast<size_t>(row)]));
        hair::write_obj_polylines(
            fs::path(obj_dir) / name, strands,
            note + ", frame " + std::to_string(frames.index[static_cast<size_t>(row)]));
      }
    }
    if (!hair_path.empty()) {
      int64_t which = frame < 0 ? frames.first_frame : frame;
      std::vector<int64_t> one = rows_of(frames, {which, which + 1}, input_path);
      strands.points = frame_points(one.front());
      hair::write_cyhair(hair_path, strands, widths,
                         "hairstyle frame " + std::to_string(which) + ", metres");
    }
    if (tolerance->count() > 0)
      std::cerr << "hair-export: " << kept.size() << " of " << frames.rest.point_count()
                << " points kept (" << (100.0 * static_cast<double>(kept.size()) /
                                        static_cast<double>(std::max<int64_t>(
                                            1, frames.rest.point_count())))
                << "%) within " << tolerance_m
                << " m of the rest shape and each frame; the dropped ones lie at most "
                << largest_deviation_m << " m from the kept strands in the rest shape and the "
                << "frames written\n";
  } catch (const hair::Error& e) {
    std::cerr << "hair-export: error: " << e.what() << "\n";
    return e.exit_code();
  } catch (const std::exception& e) {
    std::cerr << "hair-export: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
