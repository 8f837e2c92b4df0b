// hair-grow-report: how well the strands of strands.h5 reproduce the hair mesh of the
// extract.h5 they were grown from: coverage, fidelity, points inside the body, roots
// off the scalp (docs/grow.md). Prints one Markdown table row, or the header with --header.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>

#include "hair/core/error.h"
#include "hair/extract/extract_io.h"
#include "hair/grow/grow_io.h"
#include "hair/grow/grow_measures.h"
#include "hair/h5/dataset.h"
#include "hair/h5/schema_validation.h"

int main(int argc, char** argv) {
  CLI::App app("Measure grown strands against the hair mesh and the body.", "hair-grow-report");
  std::string extract_path, strands_path, name;
  int samples = 20000;
  bool header = false;
  app.add_flag("--header", header, "print the table's header and exit");
  app.add_option("EXTRACT_H5", extract_path, "extract.h5 the strands were grown from");
  app.add_option("STRANDS_H5", strands_path, "strands.h5 from the grow stage");
  app.add_option("--name", name, "first column (default: the strands file)");
  app.add_option("--samples", samples, "points sampled on the hair mesh")
      ->check(CLI::Range(100, 10'000'000));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "hair-grow-report: error: " << e.what() << "\n";
    return 2;
  }
  if (header) {
    std::printf(
        "| model | strands | points | coverage mean / p95 (H) | fidelity mean / p95 (H) | "
        "points inside body | root to scalp mean / max (H) |\n|---|---:|---:|---|---|---:|---|\n");
    return 0;
  }
  try {
    if (extract_path.empty() || strands_path.empty())
      throw hair::Error::usage("EXTRACT_H5 and STRANDS_H5 are required");
    hair::h5::File extract = hair::h5::File::open_read_only(extract_path);
    hair::h5::require_schema(extract, hair::kExtractSchema);
    hair::GrownStrands grown =
        hair::read_grown_strands(hair::h5::File::open_read_only(strands_path));
    hair::Points3f hair_vertices = hair::h5::read_matrix<float, 3>(extract, "/mesh/vertices");
    hair::Triangles3i hair_triangles =
        hair::fan_triangulation(hair::h5::read_vector<int64_t>(extract, "/mesh/face_offsets"),
                                hair::h5::read_vector<int32_t>(extract, "/mesh/face_vertices"));
    hair::ExtractedBody body = hair::read_extracted_body(extract);
    hair::GrowMeasures m = hair::measure_grown_strands(
        grown.strands, hair_vertices, hair_triangles, body.vertices, body.triangles,
        body.scalp_triangle, grown.head_height_m, samples);
    std::printf("| %s | %lld | %lld | %.4f / %.4f | %.4f / %.4f | %.2f%% | %.4f / %.4f |\n",
                (name.empty() ? strands_path : name).c_str(),
                static_cast<long long>(grown.strands.strand_count()),
                static_cast<long long>(grown.strands.point_count()), m.coverage_mean_h,
                m.coverage_p95_h, m.fidelity_mean_h, m.fidelity_p95_h, 100 * m.inside_body_share,
                m.root_distance_mean_h, m.root_distance_max_h);
  } catch (const hair::Error& e) {
    std::cerr << "hair-grow-report: error: " << e.what() << "\n";
    return e.exit_code();
  } catch (const std::exception& e) {
    std::cerr << "hair-grow-report: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
