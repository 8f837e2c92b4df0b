// hair-train-style: trains the hairstyle classifiers of the classify stage (paper section
// 5.1) on labelled clusters, reports their 10-fold cross-validation, and writes the
// model files classify reads (docs/classify.md).
//
//   hair-train-style --runs out/synth --truth out/synth_data/hair --runs out/makehuman
//                    --labels data/labels/makehuman_styles.tsv --tables out/tables
//                    --report docs/measured/classify_cv.md --models models
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>

#include "hair/error.h"
#include "hair/h5/dataset.h"
#include "hair/h5/enum_dataset.h"
#include "hair/h5/file.h"
#include "hair/h5/schema_validation.h"
#include "hair/style_features.h"
#include "hair/style_io.h"
#include "hair/style_table.h"
#include "hair/style_training.h"
#include "hair/synth/synth_io.h"

namespace fs = std::filesystem;

namespace {

/// The two feature tables of every labelled cluster of the models under the run folders.
struct Tables {
  hair::StyleTable paper, raw;
};

/// Per group of a synthetic model, its true style (truth file beside the mesh).
std::vector<int8_t> truth_group_styles(const fs::path& truth_path, const hair::h5::File& extract,
                                       int32_t group_count) {
  hair::h5::File truth = hair::h5::File::open_read_only(truth_path.string());
  hair::h5::require_schema(truth, hair::synth::kSynthTruthSchema);
  return hair::group_styles_from_truth(
      hair::h5::read_vector<int64_t>(extract, "/mesh/face_offsets"),
      hair::h5::read_vector<int32_t>(extract, "/mesh/face_vertices"),
      hair::h5::read_vector<int32_t>(extract, "/mesh/face_group"), group_count,
      hair::h5::read_vector<int64_t>(truth, "/patches/first_vertex"),
      hair::h5::read_enum_values(truth, "/patches/style"));
}

void add_model(Tables& tables, const fs::path& folder, const std::vector<fs::path>& truth_folders,
               const hair::StyleFeatureParams& params) {
  std::string model = folder.filename().string();
  fs::path truth_path;
  for (const fs::path& truth_folder : truth_folders)
    if (fs::exists(truth_folder / (model + ".truth.h5")))
      truth_path = truth_folder / (model + ".truth.h5");
  if (truth_path.empty()) {
    spdlog::warn("{}: no labels (no {}.truth.h5 in the --truth folders); left out", model, model);
    return;
  }
  hair::h5::File extract = hair::h5::File::open_read_only((folder / "extract.h5").string());
  hair::h5::File clusters = hair::h5::File::open_read_only((folder / "clusters.h5").string());
  hair::h5::File strands = hair::h5::File::open_read_only((folder / "strands.h5").string());
  hair::StyleFeatureInput input = hair::read_style_feature_input(extract, clusters, strands);
  hair::StyleFeatures features = hair::style_features(input, params);
  auto group_count = static_cast<int32_t>(input.group_cluster.size());
  std::vector<int8_t> group_style = truth_group_styles(truth_path, extract, group_count);
  std::vector<int32_t> face_count = hair::h5::read_vector<int32_t>(extract, "/groups/face_count");
  std::vector<double> weight(face_count.begin(), face_count.end());
  std::vector<int8_t> label = hair::cluster_styles_by_majority(input.group_cluster, group_style,
                                                               weight, input.cluster_count);
  std::vector<double> purity =
      hair::cluster_label_purity(input.group_cluster, group_style, weight, input.cluster_count);
  for (int32_t c = 0; c < input.cluster_count; ++c) {
    auto i = static_cast<size_t>(c);
    if (label[i] < 0 || features.strand_count[i] == 0) continue;
    tables.paper.append(features.paper_rows.row(c), label[i], model, c, false, purity[i]);
    tables.raw.append(features.raw_rows.row(c), label[i], model, c, false, purity[i]);
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("Train and cross-validate the hairstyle classifiers of classify.",
               "hair-train-style");
  std::vector<std::string> runs, truth;
  std::string tables_folder;
  app.add_option("--runs", runs,
                 "pipeline output folder (OUT of Makefile.pipeline): every "
                 "subfolder with extract.h5, clusters.h5 and strands.h5 is a model")
      ->required()
      ->check(CLI::ExistingDirectory);
  app.add_option("--truth", truth, "folder of synthetic truth files <model>.truth.h5")
      ->check(CLI::ExistingDirectory);
  app.add_option("--tables", tables_folder, "write the feature tables (TSV and ARFF) here");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "hair-train-style: error: " << e.what() << "\n";
    return 2;
  }
  try {
    hair::StyleFeatureParams params;
    Tables tables;
    tables.paper.feature_names = hair::paper_feature_names();
    tables.raw.feature_names = hair::raw_feature_names(params.raw_points);
    std::vector<fs::path> truth_folders(truth.begin(), truth.end());
    for (const std::string& run : runs) {
      std::vector<fs::path> models;
      for (const auto& entry : fs::directory_iterator(run))
        if (entry.is_directory() && fs::exists(entry.path() / "strands.h5"))
          models.push_back(entry.path());
      std::sort(models.begin(), models.end());
      for (const fs::path& folder : models) add_model(tables, folder, truth_folders, params);
    }
    if (!tables_folder.empty()) {
      fs::create_directories(tables_folder);
      fs::path folder(tables_folder);
      hair::write_style_table_tsv(folder / "features_paper.tsv", tables.paper);
      hair::write_style_table_tsv(folder / "features_raw.tsv", tables.raw);
      hair::write_style_table_arff(folder / "features_paper.arff", tables.paper,
                                   "hairstyle_paper_features");
      hair::write_style_table_arff(folder / "features_raw.arff", tables.raw,
                                   "hairstyle_raw_features");
    }
    std::cout << tables.paper.row_count() << " labelled clusters\n";
  } catch (const hair::Error& e) {
    std::cerr << "hair-train-style: error: " << e.what() << "\n";
    return e.exit_code();
  } catch (const std::exception& e) {
    std::cerr << "hair-train-style: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
