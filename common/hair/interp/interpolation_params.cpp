#include "hair/interp/interpolation_params.h"

namespace hair {

void declare_interpolation_params(ParamSet& p, InterpolationParams& params) {
  p.add("candidate_guides", params.candidate_guides,
                   "guides searched around a strand's anchor for the three nearest",
                   ParamRange::closed(3, 1000));
  p.add("min_direction_cosine", params.min_direction_cosine,
                   "barycentric only if the three guides' directions have pairwise cosines "
                   "at least this (else clump)",
                   ParamRange::closed(-1, 1));
  p.add("min_triangle_aspect", params.min_triangle_aspect,
                   "barycentric only if the guides' anchor triangle's smallest height is at "
                   "least this share of its longest edge",
                   ParamRange::closed(0, 1));
  p.add("min_guide_length_ratio", params.min_guide_length_ratio,
                   "a guide a strand follows is at least this share of the strand's length "
                   "(barycentric: all three, else clump; clump: from another cluster simulated "
                   "alike if its own has none among the candidates)",
                   ParamRange::closed(0, 1));
  p.add("wisp_bridge_length_m", params.wisp_bridge_length_m,
                   "a strand bound to a braid's wisp is bridged from the head to its first "
                   "bound point over at least this length, its last held points giving way "
                   "(0: held right up to the braid)",
                   ParamRange::closed(0, 1));
  p.add("wisp_seam_length_m", params.wisp_seam_length_m,
                   "a braided strand's points within this arc length of a seam between two "
                   "wisp tetrahedra move partly with the other one too (half at the seam; 0: "
                   "each with its own only)",
                   ParamRange::closed(0, 1));
}

void check_interpolation_params(const InterpolationParams& params) {
  check_params(params, declare_interpolation_params);
}

}  // namespace hair
