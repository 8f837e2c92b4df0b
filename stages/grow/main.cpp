// grow: strands grown from the scalp through the clusters of clusters.h5 (paper
// section 4.4, Figure 7), from extract.h5, types.h5 and clusters.h5 -> strands.h5.
#include <spdlog/spdlog.h>

#include "hair/core/atomic_file.h"
#include "hair/core/stage_app.h"
#include "hair/grow/grow_io.h"
#include "hair/grow/grow_params.h"
#include "hair/h5/provenance.h"
#include "hair/h5/schema_validation.h"

int main(int argc, char** argv) {
  hair::StageApp app("grow",
                     "Grows strands from roots sampled on the scalp: along one orientation field "
                     "per cluster, then along the input strands of the groups they reach.");
  std::string extract_path, types_path, clusters_path;
  app.cli().add_option("EXTRACT_H5", extract_path, "extract.h5 from the extract stage")->required();
  app.cli().add_option("TYPES_H5", types_path, "types.h5 from the typeify stage")->required();
  app.cli()
      .add_option("CLUSTERS_H5", clusters_path, "clusters.h5 from the cluster-all stage")
      ->required();
  hair::GrowParams params;
  hair::declare_grow_params(app.params(), params);

  return app.run(argc, argv, [&] {
    hair::GrowInput input = hair::read_grow_input(hair::h5::File::open_read_only(extract_path),
                                                  hair::h5::File::open_read_only(types_path),
                                                  hair::h5::File::open_read_only(clusters_path));
    hair::GrowResult result = hair::grow_strands(input, params);
    spdlog::info(
        "{}: {} strands, {} points, {} pushed out of the body, {} continuations ({} "
        "into another cluster); {} strands joined the cards feeding a continued cluster; {} "
        "ended where the card they followed dives into the body, {} where the next step would "
        "fold them back; {} left the field where it ran into air; roots from {} (root-type "
        "strands cover {:.0f}% of the scalp under the hair)",
        extract_path, result.strands.strand_count(), result.strands.point_count(),
        result.points_pushed_out,
        result.continuations_same_cluster + result.continuations_other_cluster,
        result.continuations_other_cluster, result.strands_joining_continued_flow,
        result.strands_ended_at_body, result.strands_ended_at_fold, result.strands_stopped_at_air,
        result.roots_from_any_type ? "strands of any type" : "root-type strands",
        100 * result.typed_root_scalp_share);

    hair::AtomicFile output(app.output_path());
    hair::h5::File file = hair::h5::File::create(output.temporary_path(), app.output_path());
    hair::write_strands_file(file, result, params, input.head_height_m);
    hair::write_provenance(
        file, hair::stage_provenance(
                  "grow", app.params().effective_json().dump(),
                  {{"extract", extract_path}, {"types", types_path}, {"clusters", clusters_path}},
                  app.elapsed_s(), app.reproducible()));
    hair::h5::require_valid_output(file, hair::kStrandsSchema);
    file.close();
    output.commit();
  });
}
