// typeify: the type of every strand group of extract.h5 (paper section 4.1,
// Algorithm 1): root_free, root_connected, middle or tip -> types.h5.
#include <spdlog/spdlog.h>

#include "hair/cluster/group_scalp_distance.h"
#include "hair/cluster/typeify.h"
#include "hair/cluster/typeify_io.h"
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
  hair::ParamSet& p = app.params();
  p.add("centre_points", params.centre_points,
        "points of each group's centre strand (its strands resampled and averaged)",
        hair::ParamRange::closed(4, 1000));
  p.add("neighbour_distance_h", params.neighbour_distance_h,
        "a group is close to another's beginning or end within this distance, in H",
        hair::ParamRange::above(0));
  p.add("root_scalp_distance_h", params.root_scalp_distance_h,
        "a group starting this close to the scalp, in H, has before it only the groups ending "
        "near its start; 0 turns this off",
        hair::ParamRange::at_least(0));
  p.add("connect_angle_deg", params.connect_angle_deg,
        "largest angle between a root group's end and a nearby group's start for the two to "
        "be connected; 0 takes it from the distribution of those angles (Otsu)",
        hair::ParamRange::closed(0, 180));
  p.add("min_connect_angle_deg", params.min_connect_angle_deg,
        "lower bound of the threshold taken from the distribution",
        hair::ParamRange::closed(0, 180));
  p.add("max_connect_angle_deg", params.max_connect_angle_deg,
        "upper bound of the threshold taken from the distribution",
        hair::ParamRange::closed(0, 180));
  p.add_check([&]() -> std::optional<std::string> {
    if (params.min_connect_angle_deg > params.max_connect_angle_deg)
      return "min_connect_angle_deg must not exceed max_connect_angle_deg";
    return std::nullopt;
  });

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
