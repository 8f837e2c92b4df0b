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

#include "hair/core/atomic_file.h"
#include "hair/core/error.h"
#include "hair/h5/attribute.h"
#include "hair/h5/dataset.h"
#include "hair/h5/enum_dataset.h"
#include "hair/h5/file.h"
#include "hair/h5/schema_validation.h"
#include "hair/style/decisive_style_rules.h"
#include "hair/style/hair_style.h"
#include "hair/style/repeated_cross_validation.h"
#include "hair/style/repeated_model_holdout.h"
#include "hair/style/stratified_folds.h"
#include "hair/style/style_classifier.h"
#include "hair/style/style_cross_validation.h"
#include "hair/style/style_cross_validation_markdown.h"
#include "hair/style/style_features.h"
#include "hair/style/style_io.h"
#include "hair/style/style_labels.h"
#include "hair/style/style_model_holdout.h"
#include "hair/style/style_model_io.h"
#include "hair/style/style_table.h"
#include "hair/style/style_training.h"
#include "hair/synth/synth_io.h"

namespace fs = std::filesystem;

namespace {

/// The feature sets, in the order of the report: the paper's (section 5.1), ours (the
/// paper's and two more), the raw features (section 6.1).
const std::vector<std::string> kFeatureSets = {"paper", "extended", "raw"};

/// The feature tables of every labelled cluster of the models under the run folders, one
/// per feature set, with the same rows.
using Tables = std::map<std::string, hair::StyleTable>;

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

/// The truth file hair-synth wrote beside the hair mesh extract.h5 was made from (its
/// provenance names the mesh), or an empty path if there is none.
fs::path truth_beside_mesh(const hair::h5::File& extract) {
  if (!hair::h5::has_attribute(extract, "/", "inputs")) return {};
  nlohmann::json inputs = nlohmann::json::parse(
      hair::h5::read_string_attribute(extract, "/", "inputs"), nullptr, false);
  if (!inputs.is_array()) return {};
  for (const auto& input : inputs)
    if (input.value("role", "") == "hair_mesh") {
      fs::path truth = fs::path(input.value("path", "")).replace_extension(".truth.h5");
      if (fs::exists(truth)) return truth;
    }
  return {};
}

/// Where the labels of the models come from.
struct LabelSources {
  std::vector<fs::path> truth_folders;              ///< <model>.truth.h5 of synthetic models
  std::vector<hair::PatchStyleLabel> patch_labels;  ///< hand labels of real meshes
};

bool has_hand_labels(const LabelSources& sources, const std::string& model) {
  return std::any_of(sources.patch_labels.begin(), sources.patch_labels.end(),
                     [&](const hair::PatchStyleLabel& label) { return label.model == model; });
}

/// Adds the labelled clusters of the model in `folder` to both tables: labels from the
/// model's truth file if there is one, else from the hand labels.
void add_model(Tables& tables, const fs::path& folder, const LabelSources& sources,
               const hair::StyleFeatureParams& params) {
  std::string model = folder.filename().string();
  hair::h5::File extract = hair::h5::File::open_read_only((folder / "extract.h5").string());
  fs::path truth_path = truth_beside_mesh(extract);
  for (const fs::path& truth_folder : sources.truth_folders)
    if (truth_path.empty() && fs::exists(truth_folder / (model + ".truth.h5")))
      truth_path = truth_folder / (model + ".truth.h5");
  bool real = truth_path.empty();
  if (real && !has_hand_labels(sources, model)) {
    spdlog::warn(
        "{}: no labels (no {}.truth.h5 in the --truth folders, no rows in --labels); "
        "left out",
        model, model);
    return;
  }
  hair::h5::File clusters = hair::h5::File::open_read_only((folder / "clusters.h5").string());
  hair::h5::File strands = hair::h5::File::open_read_only((folder / "strands.h5").string());
  hair::StyleFeatureInput input = hair::read_style_feature_input(extract, clusters, strands);
  hair::StyleFeatures features = hair::style_features(input, params);
  auto group_count = static_cast<int32_t>(input.group_cluster.size());
  std::vector<int8_t> group_style =
      real ? hair::group_styles_from_patch_labels(
                 hair::h5::read_vector<int32_t>(extract, "/mesh/face_group"), group_count,
                 sources.patch_labels, model)
           : truth_group_styles(truth_path, extract, group_count);
  std::vector<int32_t> face_count = hair::h5::read_vector<int32_t>(extract, "/groups/face_count");
  std::vector<double> weight(face_count.begin(), face_count.end());
  std::vector<int8_t> label = hair::cluster_styles_by_majority(input.group_cluster, group_style,
                                                               weight, input.cluster_count);
  std::vector<double> purity =
      hair::cluster_label_purity(input.group_cluster, group_style, weight, input.cluster_count);
  for (int32_t c = 0; c < input.cluster_count; ++c) {
    auto i = static_cast<size_t>(c);
    if (label[i] < 0 || features.strand_count[i] == 0) continue;
    for (const std::string& set : kFeatureSets)
      tables[set].append(hair::feature_set_rows(features, set).row(c), label[i], folder.string(), c,
                         real, purity[i], features.strand_count[i]);
  }
}

/// Rows per class and source, as a Markdown table.
std::string data_summary(const hair::StyleTable& table) {
  std::map<int8_t, std::array<int, 2>> counts;
  std::map<std::string, int> models[2];
  for (int64_t r = 0; r < table.row_count(); ++r) {
    auto i = static_cast<size_t>(r);
    ++counts[table.label[i]][table.real_mesh[i]];
    ++models[table.real_mesh[i]][table.model[i]];
  }
  std::string text = "| style | synthetic clusters | real-mesh clusters |\n|---|---:|---:|\n";
  for (const auto& [style, count] : counts)
    text += "| " + std::string(hair::hair_style_name(static_cast<hair::HairStyle>(style))) + " | " +
            std::to_string(count[0]) + " | " + std::to_string(count[1]) + " |\n";
  text += "\n" + std::to_string(table.row_count()) + " clusters from " +
          std::to_string(models[0].size()) + " synthetic and " + std::to_string(models[1].size()) +
          " real meshes.\n";
  return text;
}

std::vector<int32_t> int_labels(const hair::StyleTable& table) {
  return std::vector<int32_t>(table.label.begin(), table.label.end());
}

void write_text(const fs::path& path, const std::string& text) {
  hair::AtomicFile output(path);
  {
    std::ofstream stream(output.temporary_path());
    stream << text;
    if (!stream.flush()) throw hair::Error::runtime(path.string(), "cannot write");
  }
  output.commit();
}

/// The spread of the SVM's and of the forest's accuracy over `repeats`; `accuracies` gives
/// a repeat's pair (SVM, forest).
template <class Repeat, class Accuracies>
std::pair<hair::AccuracySpread, hair::AccuracySpread> spreads(const std::vector<Repeat>& repeats,
                                                              Accuracies accuracies) {
  std::vector<double> svm, forest;
  for (const Repeat& repeat : repeats) {
    const auto [svm_accuracy, forest_accuracy] = accuracies(repeat);
    svm.push_back(svm_accuracy);
    forest.push_back(forest_accuracy);
  }
  return {hair::accuracy_spread(svm), hair::accuracy_spread(forest)};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app(
      "Train and cross-validate the hairstyle classifiers of classify: the SVM with the "
      "Pearson VII kernel and the random forest (paper section 5.1), on the paper's "
      "features and on the 190 raw features of section 6.1.",
      "hair-train-style");
  std::vector<std::string> runs, truth;
  std::string labels_path, tables_in, tables_folder, report_path, models_folder;
  hair::StyleClassifierParams params;
  app.add_option("--runs", runs,
                 "pipeline output folder (OUT of Makefile.pipeline): every subfolder with "
                 "extract.h5, clusters.h5 and strands.h5 is a model")
      ->check(CLI::ExistingDirectory);
  app.add_option("--truth", truth,
                 "folder of synthetic truth files <model>.truth.h5, for models whose extract.h5 "
                 "does not name a mesh with its truth beside it (hair-synth writes it there)")
      ->check(CLI::ExistingDirectory);
  app.add_option("--labels", labels_path,
                 "hand labels of real meshes per patch "
                 "(data/labels/makehuman_styles.tsv)")
      ->check(CLI::ExistingFile);
  app.add_option("--tables-in", tables_in,
                 "instead of --runs: the folder of an earlier --tables (features_paper.tsv, "
                 "features_extended.tsv, features_raw.tsv)")
      ->check(CLI::ExistingDirectory);
  app.add_option("--tables", tables_folder, "write the feature tables (TSV and ARFF) here");
  app.add_option("--report", report_path, "write the cross-validation report (Markdown) here");
  std::string holdout_path;
  hair::DecisiveStyleRules rules;
  app.add_flag("!--no-decisive-rules", rules.enabled,
               "leave-one-model-out: the classifiers alone, without the paper's criteria "
               "deciding where they hold (classify's decisive_rules = false)");
  app.add_option("--holdout-report", holdout_path,
                 "write the leave-one-model-out report on the real meshes (Markdown) here: each "
                 "real mesh classified by classifiers trained on every other model, scored by "
                 "strands");
  std::vector<std::string> report_sets = kFeatureSets;
  app.add_option("--feature-sets", report_sets, "the feature sets the reports evaluate")
      ->check(CLI::IsMember(kFeatureSets))
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--models", models_folder,
                 "write the models trained on all rows here: style_paper.yml (the paper's "
                 "features) and style_extended.yml (ours)");
  app.add_option("--folds", params.folds, "folds of the cross-validation")
      ->check(CLI::Range(2, 100));
  app.add_option("--seed", params.seed, "seed of the fold assignment");
  int repeats = 1;
  app.add_option("--repeats", repeats,
                 "--report: repeat the cross-validation with the fold seeds SEED, SEED + 1, ...; "
                 "--holdout-report: repeat the leave-one-model-out evaluation with those seeds "
                 "(the SVM's grid-search folds); each report gives the mean "
                 "accuracy, its spread and every repeat's, then the first repeat in full")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  bool linear_features = false;
  app.add_flag("--linear-features", linear_features,
               "give the classifiers every feature as it is, instead of the lengths in H and the "
               "node count on a log scale (feature_log_offsets; the models before 2026-11-27)");
  double length_log_offset_h = hair::kLengthLogOffsetH;
  app.add_option("--length-log-offset", length_log_offset_h,
                 "the offset c of the lengths' log scale, log(length + c), in H (0: lengths as "
                 "they are, the node count still on its log scale)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  std::string fold_by = "cluster";
  app.add_option("--fold-by", fold_by,
                 "cluster: stratified folds of clusters (the paper's cross-validation); model: "
                 "the clusters of a model stay in one fold, so every model, the real meshes "
                 "among them, is classified by classifiers trained without it")
      ->check(CLI::IsMember({"cluster", "model"}));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "hair-train-style: error: " << e.what() << "\n";
    return 2;
  }
  try {
    if (runs.empty() == tables_in.empty())
      throw hair::Error::usage("give either --runs (with --truth or --labels) or --tables-in");
    params.check();
    auto start = std::chrono::steady_clock::now();
    hair::StyleFeatureParams feature_params;
    Tables tables;
    if (!tables_in.empty()) {
      for (const std::string& set : kFeatureSets)
        tables[set] =
            hair::read_style_table_tsv(fs::path(tables_in) / ("features_" + set + ".tsv"));
    } else {
      for (const std::string& set : kFeatureSets)
        tables[set].feature_names = hair::feature_set_names(set, feature_params.raw_points);
      LabelSources sources;
      sources.truth_folders.assign(truth.begin(), truth.end());
      if (!labels_path.empty()) sources.patch_labels = hair::read_patch_style_labels(labels_path);
      for (const std::string& run : runs) {
        std::vector<fs::path> models;
        for (const auto& entry : fs::directory_iterator(run))
          if (entry.is_directory() && fs::exists(entry.path() / "strands.h5"))
            models.push_back(entry.path());
        std::sort(models.begin(), models.end());
        for (const fs::path& folder : models) add_model(tables, folder, sources, feature_params);
      }
    }
    const hair::StyleTable& first = tables.at("paper");
    spdlog::info("{} labelled clusters", first.row_count());
    if (first.row_count() < params.folds)
      throw hair::Error::usage("only " + std::to_string(first.row_count()) +
                               " labelled clusters, fewer than the " +
                               std::to_string(params.folds) + " folds");
    if (!tables_folder.empty()) {
      fs::path folder(tables_folder);
      fs::create_directories(folder);
      for (const std::string& set : kFeatureSets) {
        hair::write_style_table_tsv(folder / ("features_" + set + ".tsv"), tables.at(set));
        hair::write_style_table_arff(folder / ("features_" + set + ".arff"), tables.at(set),
                                     "hairstyle_" + set + "_features");
      }
    }
    // The classifiers' settings for a feature set: the log scale of its lengths and counts.
    const auto params_of = [&params, linear_features,
                            length_log_offset_h](const hair::StyleTable& table) {
      hair::StyleClassifierParams set_params = params;
      if (!linear_features)
        set_params.feature_log_offsets =
            hair::feature_log_offsets(table.feature_names, length_log_offset_h);
      return set_params;
    };
    const std::map<std::string, std::string> titles = {
        {"paper", "The paper's features"},
        {"extended", "Extended features (the paper's and eleven of ours)"},
        {"raw", "Raw features"}};
    if (!report_path.empty()) {
      std::vector<bool> real(first.real_mesh.begin(), first.real_mesh.end());
      hair::FoldsForSeed folds_for_seed;
      if (fold_by == "model")
        folds_for_seed = [&first, &params](uint64_t seed) {
          return hair::grouped_folds(first.model, params.folds, seed);
        };
      std::string command = "hair-train-style";
      for (int a = 1; a < argc; ++a) command += std::string(" ") + argv[a];
      std::string report = "# Style classifiers: cross-validation\n\nWritten by `" + command +
                           "`.\n\n## Data\n\n" + data_summary(first) + "\nFolds: " +
                           (fold_by == "model" ? "by model (a model's clusters in one fold)"
                                               : "stratified by style, cluster by cluster") +
                           ".\n";
      for (const std::string& set : report_sets) {
        const hair::StyleTable& table = tables.at(set);
        auto cv_start = std::chrono::steady_clock::now();
        hair::RepeatedCrossValidation repeated = hair::repeated_style_cross_validation(
            table.rows, int_labels(table), real, params_of(table), repeats, folds_for_seed);
        const hair::StyleCrossValidation& cv = repeated.repeats.front();
        double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - cv_start).count();
        report += "\n## " + titles.at(set) + " (" + std::to_string(table.rows.cols()) +
                  " dimensions)\n\n";
        if (repeats > 1)
          report += hair::repeated_cross_validation_markdown(repeated, "real meshes") +
                    fmt::format("\nThe first of them (seed {}):\n\n", repeated.seeds.front());
        report += hair::style_cross_validation_markdown(cv, "real meshes") + "\n" +
                  fmt::format(
                      "Cross-validation{} of both classifiers, grid search included: "
                      "{:.1f} s.\n",
                      repeats > 1 ? "s" : "", seconds);
        const auto [svm, forest] = spreads(repeated.repeats, [](const auto& each) {
          return std::pair{each.svm.accuracy(), each.forest.accuracy()};
        });
        spdlog::info(
            "{} features: SVM {:.1f}% (sd {:.1f} over {} repeats), random forest {:.1f}% (sd "
            "{:.1f}); first repeat's real meshes {:.1f}%, {:.1f}%",
            set, 100 * svm.mean, 100 * svm.standard_deviation, repeats, 100 * forest.mean,
            100 * forest.standard_deviation, 100 * cv.svm.subset_accuracy(),
            100 * cv.forest.subset_accuracy());
      }
      write_text(report_path, report);
    }
    if (!holdout_path.empty()) {
      std::vector<bool> real(first.real_mesh.begin(), first.real_mesh.end());
      if (std::find(real.begin(), real.end(), true) == real.end())
        throw hair::Error::usage("--holdout-report: no real mesh among the labelled clusters");
      std::vector<double> strands(first.strand_count.begin(), first.strand_count.end());
      std::string command = "hair-train-style";
      for (int a = 1; a < argc; ++a) command += std::string(" ") + argv[a];
      std::string report =
          "# Style classifiers on real meshes: leave one model out\n\nWritten by `" + command +
          "`.\n\n## Data\n\n" + data_summary(first) +
          "\nEach real mesh is classified by classifiers trained on every other "
          "model (synthetic and real); a cluster weighs its grown strands.\n";
      for (const std::string& set : report_sets) {
        const hair::StyleTable& table = tables.at(set);
        auto holdout_start = std::chrono::steady_clock::now();
        // The paper's criteria decide where they hold, as in classify (their features are in
        // the extended set; the paper's set lacks tip_share).
        std::vector<int32_t> decided;
        std::vector<uint8_t> fixed_ruled_out;
        if (rules.enabled && hair::has_decisive_rule_features(table.feature_names)) {
          decided = hair::decisive_styles_of_rows(table.rows, table.feature_names, rules);
          fixed_ruled_out = hair::fixed_ruled_out_of_rows(table.rows, table.feature_names, rules);
        }
        const hair::RepeatedModelHoldout repeated = hair::repeated_leave_one_model_out(
            table.rows, int_labels(table), table.model, real, strands, params_of(table), repeats,
            decided, fixed_ruled_out);
        const hair::ModelHoldout& holdout = repeated.repeats.front();
        double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - holdout_start).count();
        int ruled = static_cast<int>(std::count(holdout.ruled.begin(), holdout.ruled.end(), 1));
        report += "\n## " + titles.at(set) + " (" + std::to_string(table.rows.cols()) +
                  " dimensions)\n\n" +
                  (decided.empty()
                       ? std::string(rules.enabled ? "The paper's criteria do not decide here (the "
                                                     "set has no tip_share): the classifiers "
                                                     "alone.\n\n"
                                                   : "The classifiers alone "
                                                     "(--no-decisive-rules).\n\n")
                       : fmt::format("The paper's criteria decide {} of the {} held-out clusters "
                                     "(classify's decisive rules, default thresholds) and rule "
                                     "fixed out for {} more; the classifiers the rest.\n\n",
                                     ruled, holdout.truth.size(),
                                     std::count(holdout.fixed_ruled_out.begin(),
                                                holdout.fixed_ruled_out.end(), 1))) +
                  (repeats > 1 ? hair::repeated_model_holdout_markdown(repeated) +
                                     fmt::format("\nThe first of them (seed {}):\n\n",
                                                 repeated.seeds.front())
                               : std::string()) +
                  hair::model_holdout_markdown(holdout, table.cluster) + "\n" +
                  fmt::format("Both classifiers, grid search included{}: {:.1f} s.\n",
                              repeats > 1 ? ", every repeat" : "", seconds);
        const auto [svm, forest] = spreads(repeated.repeats, [](const auto& each) {
          return std::pair{each.svm_scores.accuracy(), each.forest_scores.accuracy()};
        });
        spdlog::info(
            "{} features, real meshes held out: SVM {:.1f}% (sd {:.1f} over {} repeats), random "
            "forest {:.1f}% (sd {:.1f}) of strands",
            set, 100 * svm.mean, 100 * svm.standard_deviation, repeats, 100 * forest.mean,
            100 * forest.standard_deviation);
      }
      write_text(holdout_path, report);
    }
    if (!models_folder.empty()) {
      fs::create_directories(models_folder);
      for (const char* set : {"paper", "extended"}) {
        const hair::StyleTable& table = tables.at(set);
        hair::StyleModel model = hair::trained_style_model(table.rows, int_labels(table), set,
                                                           table.feature_names, params_of(table));
        fs::path path = fs::path(models_folder) / ("style_" + std::string(set) + ".yml");
        hair::write_style_model(path, model);
        spdlog::info("wrote {}", path.string());
      }
    }
    spdlog::info("done in {:.1f} s",
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  } catch (const hair::Error& e) {
    std::cerr << "hair-train-style: error: " << e.what() << "\n";
    return e.exit_code();
  } catch (const std::exception& e) {
    std::cerr << "hair-train-style: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
