// hair-render: a picture of what a stage produced, e.g. the input strands of
// extract.h5 coloured by group, root-to-tip direction, orientation rule or patch kind.
#include <CLI/CLI.hpp>
#include <iostream>

#include "hair/error.h"
#include "hair/h5/file.h"
#include "hair/render/extract_picture.h"

int main(int argc, char** argv) {
  CLI::App app("Render a hairstyle HDF5 file as a PNG (front, side and back views).",
               "hair-render");
  std::string input_path, output_path, colouring = "group", title, extract_path;
  int size_px = 512;
  bool no_body = false;
  app.add_option("FILE", input_path, "extract.h5, or types.h5 with --extract")->required();
  app.add_option("--extract", extract_path, "the extract.h5 a types.h5 was made from");
  app.add_option("-o,--output", output_path, "PNG to write")->required();
  app.add_option("--color-by", colouring, "group, direction, rule or kind");
  app.add_option("--size", size_px, "pixels per view")->check(CLI::Range(64, 4096));
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
    options.title = title.empty() ? input_path + " (" + colouring + ")" : title;
    hair::h5::File file = hair::h5::File::open_read_only(input_path);
    cv::Mat image;
    if (extract_path.empty()) {
      image = hair::extract_picture(file, hair::parse_extract_colouring(colouring), options);
    } else {
      if (title.empty()) options.title = input_path + " (type)";
      image = hair::types_picture(file, hair::h5::File::open_read_only(extract_path), options);
    }
    hair::write_png(image, output_path);
  } catch (const hair::Error& e) {
    std::cerr << "hair-render: error: " << e.what() << "\n";
    return e.exit_code();
  } catch (const std::exception& e) {
    std::cerr << "hair-render: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
