// typeify: the type of every strand group of extract.h5 (paper section 4.1,
// Algorithm 1): root_free, root_connected, middle or tip -> types.h5.
#include <spdlog/spdlog.h>

#include "hair/cluster/group_scalp_distance.h"
#include "hair/cluster/typeify.h"
#include "hair/cluster/typeify_io.h"
#include "hair/cluster/typeify_params.h"
#include "hair/core/atomic_file.h"
#include "hair/core/stage_app.h"
#include "hair/extract/extract_io.h"
#include "hair/h5/provenance.h"
#include "hair/h5/schema_validation.h"

int main(int argc, char** argv) {
  hair::StageApp app("typeify",
                     "Types every strand group (root_free, root_connected, middle, tip) from "
                     "the groups close to its beginning and end (Algorithm 1).");
  std::string extract_path;
  app.cli().add_option("EXTRACT_H5", extract_path, "extract.h5 from the extract stage")->required();
  hair::TypeifyParams params;
  hair::declare_typeify_params(app.params(), params);

  return app.run(argc, argv, [&] {
    hair::h5::File extract = hair::h5::File::open_read_only(extract_path);
    hair::ExtractedStrands extracted = hair::read_extracted_strands(extract);
    hair::ExtractedBody body = hair::read_extracted_body(extract);
    hair::StrandSet centres =
        hair::centre_strands(extracted.strands, extracted.group_first_strand, params.centre_points);
    std::vector<double> start_scalp_distance_m =
        hair::start_scalp_distances(centres, body.vertices, body.triangles, body.scalp_triangle);
    hair::GroupTypes types = hair::group_types_from_centres(
        std::move(centres), std::move(start_scalp_distance_m), extracted.head_height_m, params);
    std::array<int, 4> counts{};
    for (hair::GroupType type : types.type) ++counts[static_cast<size_t>(type)];
    spdlog::info(
        "{}: root_free {}, root_connected {}, middle {}, tip {}; connect angle {:.1f} "
        "degrees ({})",
        extract_path, counts[0], counts[1], counts[2], counts[3],
        types.connect_angle_threshold_rad * 180 / 3.14159265358979,
        types.threshold_from_distribution ? "from the distribution" : "parameter");

    hair::AtomicFile output(app.output_path());
    hair::h5::File file = hair::h5::File::create(output.temporary_path(), app.output_path());
    hair::write_types_file(file, types, extracted.head_height_m,
                           params.neighbour_distance_h * extracted.head_height_m);
    hair::write_provenance(
        file,
        hair::stage_provenance("typeify", app.params().effective_json().dump(),
                               {{"extract", extract_path}}, app.elapsed_s(), app.reproducible()));
    hair::h5::require_valid_output(file, hair::kTypesSchema);
    file.close();
    output.commit();
  });
}
