// classify: the hairstyle of every cluster of the grown strands (paper section 5.1),
// from extract.h5, clusters.h5, strands.h5 and a trained style model -> styles.h5.
#include <spdlog/spdlog.h>

#include "hair/core/atomic_file.h"
#include "hair/core/stage_app.h"
#include "hair/h5/provenance.h"
#include "hair/h5/schema_validation.h"
#include "hair/style/cluster_styles.h"
#include "hair/style/hair_style.h"
#include "hair/style/style_io.h"
#include "hair/style/style_model_io.h"

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
  std::string classifier = "random_forest";
  app.params().add("classifier", classifier,
                   "whose class is the style: random_forest (the paper's better one) or svm",
                   {"random_forest", "svm"});

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
        hair::cluster_styles(features, model, *hair::style_classifier_from_name(classifier));
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
    if (classified < static_cast<int>(styles.style.size()))
      spdlog::info("{}: {} clusters have no grown strands and are not classified", strands_path,
                   styles.style.size() - static_cast<size_t>(classified));

    hair::AtomicFile output(app.output_path());
    hair::h5::File file = hair::h5::File::create(output.temporary_path(), app.output_path());
    hair::write_styles_file(file, styles, features, model_path, model.feature_set,
                            input.head_height_m);
    hair::write_provenance(file,
                           hair::stage_provenance("classify", app.params().effective_json().dump(),
                                                  {{"extract", extract_path},
                                                   {"clusters", clusters_path},
                                                   {"strands", strands_path},
                                                   {"model", model_path}},
                                                  app.elapsed_s(), app.reproducible()));
    hair::h5::require_valid_output(file, hair::kStylesSchema);
    file.close();
    output.commit();
  });
}
