// cluster-all: every strand group of types.h5 in a hair cluster (paper section 4.3,
// Algorithm 2), with the middle clusters of middle.h5 as single nodes -> clusters.h5.
#include <spdlog/spdlog.h>

#include "hair/cluster/clustering_io.h"
#include "hair/cluster/clustering_params.h"
#include "hair/core/atomic_file.h"
#include "hair/core/stage_app.h"
#include "hair/h5/provenance.h"
#include "hair/h5/schema_validation.h"

int main(int argc, char** argv) {
  hair::StageApp app("cluster-all",
                     "Clusters every strand group: free-root groups by similarity (equations "
                     "4-5), the others and the middle clusters by connectivity (1-3), then "
                     "divides clusters where root-type groups meet the others.");
  std::string types_path, middle_path;
  app.cli().add_option("TYPES_H5", types_path, "types.h5 from the typeify stage")->required();
  app.cli()
      .add_option("MIDDLE_H5", middle_path, "middle.h5 from the cluster-middle stage")
      ->required();
  hair::HairClusteringParams params;
  hair::declare_cluster_all_params(app.params(), params);

  return app.run(argc, argv, [&] {
    hair::TypedGroups groups = hair::read_typed_groups(hair::h5::File::open_read_only(types_path));
    std::vector<int32_t> middle_cluster =
        hair::read_middle_clusters(hair::h5::File::open_read_only(middle_path), groups.type.size());
    hair::HairClustering clustering =
        hair::cluster_hair(groups.centre_strands, groups.type, middle_cluster, groups.head_height_m,
                           params, groups.start_scalp_distance_m);
    spdlog::info("{}: {} clusters from {} nodes ({}), {} divided at a type change: {} clusters",
                 types_path, clustering.clusters_before_split, clustering.graph.node_count,
                 hair::cluster_count_source_name(clustering.count_source), clustering.split_count,
                 clustering.cluster_origin.size());

    hair::AtomicFile output(app.output_path());
    hair::h5::File file = hair::h5::File::create(output.temporary_path(), app.output_path());
    hair::write_clusters_file(file, clustering, groups.head_height_m);
    hair::write_provenance(
        file, hair::stage_provenance("cluster-all", app.params().effective_json().dump(),
                                     {{"types", types_path}, {"middle", middle_path}},
                                     app.elapsed_s(), app.reproducible()));
    hair::h5::require_valid_output(file, hair::kClustersSchema);
    file.close();
    output.commit();
  });
}
