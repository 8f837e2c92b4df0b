// cluster-middle: spectral clustering of the middle-type strand groups of types.h5
// over a graph weighted by connectivity (paper section 4.2) -> middle.h5.
#include <spdlog/spdlog.h>

#include "hair/cluster/clustering_io.h"
#include "hair/cluster/clustering_params.h"
#include "hair/core/atomic_file.h"
#include "hair/core/stage_app.h"
#include "hair/h5/provenance.h"
#include "hair/h5/schema_validation.h"

int main(int argc, char** argv) {
  hair::StageApp app("cluster-middle",
                     "Clusters the middle-type strand groups by how well they connect "
                     "(equations 1-3; Ng-Jordan-Weiss spectral clustering).");
  std::string types_path;
  app.cli().add_option("TYPES_H5", types_path, "types.h5 from the typeify stage")->required();
  hair::GraphClusteringParams params;
  hair::declare_cluster_middle_params(app.params(), params);

  return app.run(argc, argv, [&] {
    hair::TypedGroups groups = hair::read_typed_groups(hair::h5::File::open_read_only(types_path));
    hair::MiddleClustering clustering = hair::cluster_middle_groups(
        groups.centre_strands, groups.type, groups.head_height_m, params);
    if (clustering.count_source == hair::ClusterCountSource::skipped)
      spdlog::info("{}: no middle groups; skipped (an empty clustering)", types_path);
    else
      spdlog::info("{}: {} middle clusters ({}), {} edges, affinity scale {:.4f}", types_path,
                   clustering.cluster_count,
                   hair::cluster_count_source_name(clustering.count_source),
                   clustering.graph.edges.size(), clustering.graph.affinity_scale);

    hair::AtomicFile output(app.output_path());
    hair::h5::File file = hair::h5::File::create(output.temporary_path(), app.output_path());
    hair::write_middle_file(file, clustering, groups.head_height_m);
    hair::write_provenance(
        file, hair::stage_provenance("cluster-middle", app.params().effective_json().dump(),
                                     {{"types", types_path}}, app.elapsed_s(), app.reproducible()));
    hair::h5::require_valid_output(file, hair::kMiddleSchema);
    file.close();
    output.commit();
  });
}
