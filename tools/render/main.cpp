// hair-render: a picture of what a stage produced: the input strands of extract.h5
// coloured by group, root-to-tip direction, orientation rule or patch kind; with
// --extract, the same strands coloured by the group types of types.h5, the middle
// clusters of middle.h5 or the hair clusters of clusters.h5, or by hand-labelled styles
// (--style-labels, data/labels); the grown strands of strands.h5, or, with --strands,
// in the paper's colours of the styles of styles.h5; a contact sheet of frames of the
// simulated guides of guides.h5; a frame of every strand of interpolate's frames.h5 by
// style or cluster (a PNG), or all its frames as an MP4 video. The file's `schema`
// attribute says which it is.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <iostream>

#include "hair/cluster/clustering_io.h"
#include "hair/cluster/typeify_io.h"
#include "hair/core/error.h"
#include "hair/extract/extract_io.h"
#include "hair/grow/grow_io.h"
#include "hair/h5/attribute.h"
#include "hair/h5/dataset.h"
#include "hair/h5/file.h"
#include "hair/h5/schema_validation.h"
#include "hair/interp/frames_io.h"
#include "hair/render/cluster_picture.h"
#include "hair/render/extract_picture.h"
#include "hair/render/frames_picture.h"
#include "hair/render/grow_picture.h"
#include "hair/render/guides_picture.h"
#include "hair/render/style_picture.h"
#include "hair/sim/guides_io.h"
#include "hair/style/style_io.h"
#include "hair/style/style_labels.h"

namespace {

/// The picture of `file` by the schema it names; an empty `colouring` is the file's
/// default, an empty title in `options` names the file and the colouring; `panels` is
/// for guides.h5 only (0: not given).
cv::Mat picture(const hair::h5::File& file, const std::string& extract_path,
                const std::string& strands_path, const std::string& colouring, int panels,
                hair::RenderOptions options) {
  if (!hair::h5::has_attribute(file, "/", "schema"))
    throw hair::Error::bad_input(file.name(), "has no schema attribute: not a hairstyle file");
  std::string schema = hair::h5::read_string_attribute(file, "/", "schema");
  if (panels != 0 && schema != hair::kGuidesSchema)
    throw hair::Error::usage("--panels is for guides.h5, not " + file.name() + " (" + schema + ")");
  // The colouring asked for or `fallback`, named in the default title.
  auto colour_word = [&](const std::string& fallback) {
    std::string word = colouring.empty() ? fallback : colouring;
    if (options.title.empty()) options.title = file.name() + " (" + word + ")";
    return word;
  };
  if (schema == hair::kExtractSchema) {
    if (!extract_path.empty())
      throw hair::Error::usage(
          "--extract is for types.h5, middle.h5, clusters.h5, strands.h5, styles.h5 and "
          "guides.h5, not " +
          file.name() + " (" + schema + ")");
    hair::ExtractColouring how = hair::parse_extract_colouring(colour_word("group"));
    return hair::extract_picture(file, how, options);
  }
  if (schema != hair::kTypesSchema && schema != hair::kMiddleSchema &&
      schema != hair::kClustersSchema && schema != hair::kStrandsSchema &&
      schema != hair::kStylesSchema && schema != hair::kGuidesSchema)
    throw hair::Error::bad_input(file.name(),
                                 "schema '" + schema +
                                     "' is not one hair-render draws (extract, types, middle, "
                                     "clusters, strands, styles or guides)");
  if (!strands_path.empty() != (schema == hair::kStylesSchema))
    throw hair::Error::usage(schema == hair::kStylesSchema
                                 ? file.name() +
                                       " (styles) needs --strands: the strands.h5 it classified"
                                 : "--strands is for styles.h5, not " + file.name());
  if (extract_path.empty())
    throw hair::Error::usage(file.name() + " (" + schema +
                             ") needs --extract: the extract.h5 it was made from");
  if (!colouring.empty() && schema != hair::kClustersSchema && schema != hair::kStrandsSchema)
    throw hair::Error::usage("--color-by is for extract.h5, clusters.h5 and strands.h5, not " +
                             file.name() + " (" + schema + ")");
  hair::h5::File extract = hair::h5::File::open_read_only(extract_path);
  if (schema == hair::kGuidesSchema) {
    // A panel per frame: the front and side views show turns, nods and walks.
    options.views = {hair::ViewDirection::front, hair::ViewDirection::side};
    if (options.title.empty()) options.title = file.name();
    return hair::guides_picture(file, extract, options, panels == 0 ? 6 : panels);
  }
  if (schema == hair::kStylesSchema) {
    colour_word("style");
    return hair::styles_picture(file, hair::h5::File::open_read_only(strands_path), extract,
                                options);
  }
  if (schema == hair::kStrandsSchema) {
    hair::GrownColouring how = hair::parse_grown_colouring(colour_word("cluster"));
    return hair::grown_picture(file, extract, options, how);
  }
  if (schema == hair::kTypesSchema) {
    colour_word("type");
    return hair::types_picture(file, extract, options);
  }
  if (schema == hair::kMiddleSchema) {
    colour_word("middle cluster");
    return hair::middle_picture(file, extract, options);
  }
  bool before_split = hair::parse_cluster_colouring(colour_word("cluster"));
  return hair::clusters_picture(file, extract, options, before_split);
}

/// Whether `path` names an MP4 file.
bool is_video(const std::string& path) {
  return path.size() > 4 && path.compare(path.size() - 4, 4, ".mp4") == 0;
}

/// frames.h5: a PNG of frame `frame` (of the simulation; -1 the file's middle one), or an MP4
/// of every frame.
void render_frames(const hair::h5::File& file, const std::string& extract_path,
                   const std::string& colouring, int64_t frame, const std::string& output_path,
                   hair::RenderOptions options) {
  if (extract_path.empty())
    throw hair::Error::usage(file.name() +
                             " (frames) needs --extract: the extract.h5 of its model");
  hair::FramesScene scene =
      hair::read_frames_scene(file, hair::h5::File::open_read_only(extract_path));
  hair::FramesColouring how = hair::parse_frames_colouring(colouring.empty() ? "style" : colouring);
  options.views = {hair::ViewDirection::front, hair::ViewDirection::side,
                   hair::ViewDirection::back};
  if (is_video(output_path)) {
    options.views = {hair::ViewDirection::front, hair::ViewDirection::side};
    if (frame >= 0) throw hair::Error::usage("--frame is for a PNG, not a video of every frame");
    hair::write_frames_video(scene, file, output_path, how, options);
    return;
  }
  const int64_t first = scene.frames.first_frame;
  const int64_t row = frame < 0 ? scene.frames.frame_count() / 2 : frame - first;
  if (row < 0 || row >= scene.frames.frame_count())
    throw hair::Error::usage(file.name() + " holds frames " + std::to_string(first) + " to " +
                             std::to_string(first + scene.frames.frame_count() - 1) + ", not " +
                             std::to_string(frame));
  hair::write_png(hair::frame_picture(scene, hair::read_frame_points(file, row), row, how, options),
                  output_path);
}

/// The picture of extract.h5 `file` coloured by the styles that the table
/// `labels_path` gives the patches of `model`.
cv::Mat style_label_picture(const hair::h5::File& file, const std::string& labels_path,
                            const std::string& model, hair::RenderOptions options) {
  hair::h5::require_schema(file, hair::kExtractSchema);
  std::vector<hair::PatchStyleLabel> labels = hair::read_patch_style_labels(labels_path);
  auto group_count =
      static_cast<int32_t>(hair::h5::read_vector<int32_t>(file, "/groups/face_count").size());
  std::vector<int8_t> styles;
  try {
    styles = hair::group_styles_from_patch_labels(
        hair::h5::read_vector<int32_t>(file, "/mesh/face_group"), group_count, labels, model);
  } catch (const hair::Error& e) {
    throw hair::Error::bad_input(labels_path, file.name() + ": " + e.what());
  }
  if (std::count(styles.begin(), styles.end(), -1) == group_count)
    throw hair::Error::bad_input(labels_path, "labels no patch of model '" + model + "'");
  if (options.title.empty()) options.title = model + ": hand-labelled styles";
  return hair::style_picture(file, styles, options);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("Render a hairstyle HDF5 file as a PNG (front, side and back views).",
               "hair-render");
  std::string input_path, output_path, colouring, title, extract_path, strands_path, labels_path,
      model;
  int size_px = 512, panels = 0;
  int64_t frame = -1;
  bool no_body = false;
  app.add_option("FILE", input_path,
                 "extract.h5; or, with --extract, types.h5, middle.h5, clusters.h5, strands.h5, "
                 "guides.h5 or frames.h5; or, with --extract and --strands, styles.h5")
      ->required();
  app.add_option("--extract", extract_path,
                 "the extract.h5 that types.h5, middle.h5, clusters.h5, strands.h5 or guides.h5 "
                 "was made from");
  app.add_option("--strands", strands_path,
                 "the strands.h5 that styles.h5 classified (its strands are drawn in the paper's "
                 "colours of their clusters' styles)");
  app.add_option("-o,--output", output_path,
                 "PNG to write; for frames.h5 also an MP4 video of every frame (*.mp4)")
      ->required();
  app.add_option("--frame", frame,
                 "frames.h5: the frame of the simulation to draw (default: the file's middle one)");
  app.add_option("--color-by", colouring,
                 "extract.h5: group (default), direction, rule, kind or flow (along the painted flow); clusters.h5: cluster "
                 "(default, the final clusters) or before_split (as spectral clustering found "
                 "them); strands.h5: cluster (default: the cluster each point runs through), "
                 "root_cluster (each strand whole by its root's), rule (how each segment was "
                 "grown) or direction; frames.h5: style (default) or cluster. types.h5 is coloured by type, "
                 "middle.h5 by middle cluster (other "
                 "groups grey)");
  auto* labels_option = app.add_option(
      "--style-labels", labels_path,
      "extract.h5: colour the groups by the hand-labelled styles of --model in this table "
      "(data/labels/makehuman_styles.tsv) instead of --color-by");
  auto* model_option =
      app.add_option("--model", model, "the model whose --style-labels to use (e.g. braid01)")
          ->needs(labels_option);
  labels_option->needs(model_option)->excludes("--color-by")->excludes("--extract");
  app.add_option("--size", size_px, "pixels per view")->check(CLI::Range(64, 4096));
  app.add_option("--panels", panels,
                 "guides.h5: frames shown, spread evenly from the first to the last, each a "
                 "front and a side view (default 6; two rows if more than 4)")
      ->check(CLI::Range(2, 16))
      ->excludes(labels_option);
  app.add_option("--title", title, "text at the top left (default: the file and colouring)");
  app.add_flag("--no-body", no_body, "do not draw the body (it still hides what is behind it)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "hair-render: error: " << e.what() << "\n";
    return 2;
  }
  try {
    hair::RenderOptions options;
    options.view_size_px = size_px;
    options.draw_body = !no_body;
    options.title = title;
    hair::h5::File file = hair::h5::File::open_read_only(input_path);
    const bool frames_file =
        hair::h5::has_attribute(file, "/", "schema") &&
        hair::h5::read_string_attribute(file, "/", "schema") == hair::kFramesSchema;
    if (frames_file) {
      render_frames(file, extract_path, colouring, frame, output_path, options);
    } else if (frame >= 0 || is_video(output_path)) {
      throw hair::Error::usage("--frame and MP4 output are for frames.h5, not " + input_path);
    } else if (!labels_path.empty()) {
      hair::write_png(style_label_picture(file, labels_path, model, options), output_path);
    } else {
      hair::write_png(picture(file, extract_path, strands_path, colouring, panels, options),
                      output_path);
    }
  } catch (const hair::Error& e) {
    std::cerr << "hair-render: error: " << e.what() << "\n";
    return e.exit_code();
  } catch (const std::exception& e) {
    std::cerr << "hair-render: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
