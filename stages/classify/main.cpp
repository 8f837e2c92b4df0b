// classify: the hairstyle of every cluster of the grown strands (paper section 5.1),
// from extract.h5, clusters.h5, strands.h5 and a trained style model -> styles.h5.
#include <spdlog/spdlog.h>

#include "hair/core/atomic_file.h"
#include "hair/core/stage_app.h"
#include "hair/h5/provenance.h"
#include "hair/h5/schema_validation.h"
#include "hair/style/classify_params.h"
#include "hair/style/cluster_styles.h"
#include "hair/style/hair_style.h"
#include "hair/style/style_io.h"
#include "hair/style/style_model_io.h"
#include "hair/style/style_overrides.h"

int main(int argc, char** argv) {
  hair::StageApp app("classify",
                     "Classifies every cluster of the grown strands as normal, fixed, short or "
                     "braided by the paper's features, with a trained SVM and random forest.");
  std::string extract_path, clusters_path, strands_path, model_path;
  app.cli().add_option("EXTRACT_H5", extract_path, "extract.h5 from the extract stage")->required();
  app.cli()
      .add_option("CLUSTERS_H5", clusters_path, "clusters.h5 from the cluster-all stage")
      ->required();
  app.cli().add_option("STRANDS_H5", strands_path, "strands.h5 from the grow stage")->required();
  app.cli()
      .add_option("--model", model_path,
                  "style model file from hair-train-style: models/style_extended.yml (the "
                  "paper's features and ours) or models/style_paper.yml")
      ->required();
  std::string overrides_path;
  app.cli().add_option("--overrides", overrides_path,
                       "TOML file of [[pin]] tables that pin clusters' styles, each by "
                       "cluster = ID or point_m = [x, y, z] and style = \"fixed\" "
                       "(docs/classify.md)");
  hair::ClassifyStageParams params;
  hair::declare_classify_params(app.params(), params);

  return app.run(argc, argv, [&] {
    hair::StyleModel model = hair::read_style_model(model_path, {});
    hair::StyleFeatureInput input = hair::read_style_feature_input(
        hair::h5::File::open_read_only(extract_path), hair::h5::File::open_read_only(clusters_path),
        hair::h5::File::open_read_only(strands_path));
    hair::StyleFeatureParams feature_params;
    feature_params.raw_features = model.feature_set == "raw";  // slow; the default models
                                                               // take the paper's or ours
    hair::StyleFeatures features = hair::style_features(input, feature_params);
    hair::ClusterStyles styles =
        hair::cluster_styles(features, model, *hair::style_classifier_from_name(params.classifier), params.rules);
    // The user's pins, read and resolved before anything is written (a bad file: one
    // line, exit 2, no output).
    if (!overrides_path.empty()) {
      const std::vector<hair::ResolvedPin> pins =
          hair::resolve_style_pins(hair::read_style_pins(overrides_path), styles.style,
                                   input.strands, input.head_height_m, overrides_path);
      for (const hair::ResolvedPin& pin : pins)
        spdlog::info("{}: cluster {} pinned {} (it was {}, confidence {:.2f}){}", overrides_path,
                     pin.cluster, hair::hair_style_name(pin.style),
                     hair::hair_style_name(static_cast<hair::HairStyle>(
                         styles.style[static_cast<size_t>(pin.cluster)])),
                     styles.confidence[static_cast<size_t>(pin.cluster)],
                     pin.distance_m > 0 ? fmt::format(", by a point {:.1f} mm from its strands",
                                                      1000 * pin.distance_m)
                                        : std::string());
      hair::apply_style_pins(pins, styles);
    }
    int classified = 0;
    std::string summary;
    for (size_t c = 0; c < styles.style.size(); ++c) {
      if (styles.style[c] < 0) continue;
      ++classified;
      summary += (summary.empty() ? "" : ", ") + std::to_string(c) + " " +
                 hair::hair_style_name(static_cast<hair::HairStyle>(styles.style[c]));
    }
    spdlog::info("{}: {} clusters, {} classified ({})", strands_path, styles.style.size(),
                 classified, summary);
    std::string ruled_list;
    for (size_t c = 0; c < styles.ruled.size(); ++c)
      if (styles.ruled[c] && !styles.pinned[c])
        ruled_list +=
            fmt::format("{}{} {}", ruled_list.empty() ? "" : ", ", c,
                        hair::hair_style_name(static_cast<hair::HairStyle>(styles.style[c])));
    if (!ruled_list.empty())
      spdlog::info("{}: decided by the paper's criteria: {}", strands_path, ruled_list);
    std::string not_fixed_list;
    for (size_t c = 0; c < styles.fixed_ruled_out.size(); ++c) {
      const int8_t said = params.classifier == "svm" ? styles.svm_style[c] : styles.forest_style[c];
      if (styles.fixed_ruled_out[c] && !styles.pinned[c] && !styles.ruled[c] &&
          said == static_cast<int8_t>(hair::HairStyle::fixed))
        not_fixed_list +=
            fmt::format("{}{} {}", not_fixed_list.empty() ? "" : ", ", c,
                        hair::hair_style_name(static_cast<hair::HairStyle>(styles.style[c])));
    }
    if (!not_fixed_list.empty())
      spdlog::info(
          "{}: the {} said fixed, but the strands start at the roots and end in the "
          "cluster without gathering; its best other style: {}",
          strands_path, params.classifier == "svm" ? "SVM" : "random forest", not_fixed_list);
    const std::vector<uint8_t> unsure = hair::unsure_clusters(styles, params.unsure_below);
    std::string unsure_list;
    for (size_t c = 0; c < unsure.size(); ++c)
      if (unsure[c])
        unsure_list +=
            fmt::format("{}{} {} ({:.2f})", unsure_list.empty() ? "" : ", ", c,
                        hair::hair_style_name(static_cast<hair::HairStyle>(styles.style[c])),
                        styles.confidence[c]);
    if (!unsure_list.empty())
      spdlog::info("{}: unsure (confidence under {:.2f}; pin them with --overrides if wrong): {}",
                   strands_path, params.unsure_below, unsure_list);
    if (classified < static_cast<int>(styles.style.size()))
      spdlog::info("{}: {} clusters have no grown strands and are not classified", strands_path,
                   styles.style.size() - static_cast<size_t>(classified));

    hair::AtomicFile output(app.output_path());
    hair::h5::File file = hair::h5::File::create(output.temporary_path(), app.output_path());
    hair::write_styles_file(file, styles, features, model_path, model.feature_set,
                            input.head_height_m, params.unsure_below);
    std::vector<std::pair<std::string, std::filesystem::path>> inputs{{"extract", extract_path},
                                                                      {"clusters", clusters_path},
                                                                      {"strands", strands_path},
                                                                      {"model", model_path}};
    if (!overrides_path.empty()) inputs.emplace_back("overrides", overrides_path);
    hair::write_provenance(
        file, hair::stage_provenance("classify", app.params().effective_json().dump(), inputs,
                                     app.elapsed_s(), app.reproducible()));
    hair::h5::require_valid_output(file, hair::kStylesSchema);
    file.close();
    output.commit();
  });
}
