#include "hair/cluster/typeify_params.h"

namespace hair {

void declare_typeify_params(ParamSet& p, TypeifyParams& params) {
  p.add("centre_points", params.centre_points,
        "points of each group's centre strand (its strands resampled and averaged)",
        ParamRange::closed(4, 1000));
  p.add("neighbour_distance_h", params.neighbour_distance_h,
        "a group is close to another's beginning or end within this distance, in H",
        ParamRange::above(0));
  p.add("root_scalp_distance_h", params.root_scalp_distance_h,
        "a group starting this close to the scalp, in H, has before it only the groups ending "
        "near its start; 0 turns this off",
        ParamRange::at_least(0));
  p.add("connect_angle_deg", params.connect_angle_deg,
        "largest angle between a root group's end and a nearby group's start for the two to "
        "be connected; 0 takes it from the distribution of those angles (Otsu)",
        ParamRange::closed(0, 180));
  p.add("min_connect_angle_deg", params.min_connect_angle_deg,
        "lower bound of the threshold taken from the distribution",
        ParamRange::closed(0, 180));
  p.add("max_connect_angle_deg", params.max_connect_angle_deg,
        "upper bound of the threshold taken from the distribution",
        ParamRange::closed(0, 180));
  p.add_check([&]() -> std::optional<std::string> {
    if (params.min_connect_angle_deg > params.max_connect_angle_deg)
      return "min_connect_angle_deg must not exceed max_connect_angle_deg";
    return std::nullopt;
  });
}

void check_typeify_params(const TypeifyParams& params) {
  check_params(params, declare_typeify_params);
}

}  // namespace hair
