#include "hair/interp/strand_interpolation.h"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "hair/core/error.h"
#include "hair/interp/guide_choice.h"
#include "hair/interp/interpolation_kernel.h"
#include "hair/interp/interpolation_params.h"
#include "hair/interp/wisp_binding.h"
#include "hair/style/hair_style.h"

namespace hair {
namespace {

/// A binding of `point_count` points of `strand_count` strands, every strand fixed, with
/// the guides' rest data copied in.
StrandBinding empty_binding(int64_t strand_count, int64_t point_count,
                            const InterpolationGuides& guides) {
  StrandBinding binding;
  binding.method.assign(static_cast<size_t>(strand_count), InterpolationMethod::fixed);
  binding.guides.assign(static_cast<size_t>(strand_count), {-1, -1, -1});
  binding.weights.assign(static_cast<size_t>(strand_count), {0.0f, 0.0f, 0.0f});
  binding.held_count.assign(static_cast<size_t>(strand_count), 0);
  binding.bound_from.assign(static_cast<size_t>(strand_count), 0);
  binding.interpolated_from.assign(static_cast<size_t>(strand_count), 0);
  binding.parameter.assign(static_cast<size_t>(point_count), 0.0f);
  binding.offset_m = Points3f::Zero(point_count, 3);
  binding.tetrahedron.assign(static_cast<size_t>(point_count), -1);
  binding.guide_offsets = guides.offsets;
  binding.guide_rest_points = guides.rest_points;
  binding.tetrahedron_count = guides.wisp_tetrahedron_offsets.back();
  binding.bridged.assign(static_cast<size_t>(strand_count), 0);
  if (static_cast<int64_t>(guides.wisp_rest_frames.size()) != 7 * binding.tetrahedron_count)
    throw Error::runtime("guides", "the wisps' rest frames are not 7 values per tetrahedron");
  return binding;
}

/// The interpolated points' runs of every strand (interpolation_kernel.h).
void find_runs(const StrandSet& strands, StrandBinding& binding) {
  const int64_t strand_count = strands.strand_count();
  binding.run_offsets.assign(static_cast<size_t>(strand_count) + 1, 0);
  binding.run_of_point.assign(static_cast<size_t>(strands.point_count()), 0);
  for (int64_t s = 0; s < strand_count; ++s) {
    const auto si = static_cast<size_t>(s);
    const int64_t begin = strands.offsets[si];
    const int64_t from = begin + binding.interpolated_from[si];
    const int64_t to = begin + binding.bound_from[si];
    if (!binding.bridged[si] && from < to) {
      const StrandGuides used = strand_guides(binding, s);
      strand_runs(used.segments.data(), used.count, binding.parameter.data() + from, to - from,
                  binding.run_of_point.data() + from, binding.run_particles);
    }
    binding.run_offsets[si + 1] = static_cast<int64_t>(binding.run_particles.size());
  }
}

}  // namespace

const char* interpolation_method_name(InterpolationMethod method) {
  switch (method) {
    case InterpolationMethod::fixed:
      return "fixed";
    case InterpolationMethod::barycentric:
      return "barycentric";
    case InterpolationMethod::clump:
      return "clump";
    case InterpolationMethod::braided:
      return "braided";
  }
  return "unknown";
}

StrandBinding bind_strands(const StrandSet& strands, const InterpolationGuides& guides,
                           const InterpolationParams& params) {
  check_interpolation_params(params);
  const auto& point_cluster =
      std::get<std::vector<int32_t>>(strands.point_attributes.at("cluster"));
  const int64_t strand_count = strands.strand_count();
  const int64_t point_count = strands.point_count();
  StrandBinding binding = empty_binding(strand_count, point_count, guides);
  const FollowableGuides followable = followable_guides(guides);
  bind_wisp_points(guides, point_count, binding);

  const int8_t fixed_style = static_cast<int8_t>(HairStyle::fixed);
  auto style_of_point = [&](int64_t row) {
    int32_t cluster = point_cluster[static_cast<size_t>(row)];
    if (cluster < 0 || static_cast<size_t>(cluster) >= guides.cluster_simulated_style.size())
      throw Error::runtime("strands", "point " + std::to_string(row) + " names cluster " +
                                          std::to_string(cluster) + ", which the guides lack");
    return guides.cluster_simulated_style[static_cast<size_t>(cluster)];
  };

  for (int64_t s = 0; s < strand_count; ++s) {
    const auto si = static_cast<size_t>(s);
    const int64_t begin = strands.offsets[si], end = strands.offsets[si + 1];
    const int64_t size = end - begin;
    // Bound points run from the first one to the tip.
    int64_t bound_from = size;
    for (int64_t i = 0; i < size; ++i) {
      if (binding.tetrahedron[static_cast<size_t>(begin + i)] >= 0) {
        bound_from = i;
        break;
      }
    }
    for (int64_t i = bound_from; i < size; ++i)
      if (binding.tetrahedron[static_cast<size_t>(begin + i)] < 0)
        throw Error::runtime("guides", "strand " + std::to_string(s) +
                                           ": its points bound to a wisp do not run to its tip");
    int64_t held = 0;
    while (held < bound_from && style_of_point(begin + held) == fixed_style) ++held;
    binding.bound_from[si] = bound_from;
    binding.held_count[si] = held;
    binding.interpolated_from[si] = held;
    for (int64_t i = 0; i < held; ++i)
      binding.offset_m.row(begin + i) = strands.points.row(begin + i);

    if (bound_from < size && bound_from > 0) {
      held = bridge_start(strands, s, held, bound_from, params.wisp_bridge_length_m);
      binding.held_count[si] = held;
      binding.interpolated_from[si] = held;
      if (held < bound_from) {
        const int64_t bridged_to =
            bridge_end(strands, s, held, bound_from, params.wisp_bridge_length_m);
        for (int64_t i = bound_from; i < bridged_to; ++i)
          binding.tetrahedron[static_cast<size_t>(begin + i)] = -1;  // bridged, not bound
        bound_from = bridged_to;
        binding.bound_from[si] = bound_from;
      }
      if (held < bound_from)
        bridge_to_wisp(strands, s, binding);
      else
        binding.method[si] = InterpolationMethod::braided;  // no bridge asked for
      continue;
    }
    if (held == bound_from) {
      binding.method[si] = held == size ? InterpolationMethod::fixed : InterpolationMethod::braided;
      continue;
    }
    if (followable.usable.empty()) {  // nothing to follow: held by the head
      binding.held_count[si] = bound_from;
      binding.interpolated_from[si] = bound_from;
      for (int64_t i = held; i < bound_from; ++i)
        binding.offset_m.row(begin + i) = strands.points.row(begin + i);
      binding.method[si] = InterpolationMethod::fixed;
      continue;
    }

    const MovingStrand moving(strands, s, held, bound_from,
                              point_cluster[static_cast<size_t>(begin + held)]);
    std::vector<int32_t> nearest = followable.index->nearest(
        moving.anchor_m.cast<float>(),
        std::min<int>(params.candidate_guides, static_cast<int>(followable.usable.size())));
    std::optional<GuideChoice> choice =
        barycentric_choice(moving, guides, followable, nearest, params);
    if (!choice)
      choice =
          clump_choice(moving, guides, followable, nearest, style_of_point(begin + held), params);
    follow(moving, s, *choice, guides, followable, binding);
  }
  find_runs(strands, binding);
  bind_wisp_seams(strands, guides, params.wisp_seam_length_m, binding);
  return binding;
}

StrandGuides strand_guides(const StrandBinding& binding, int64_t strand) {
  StrandGuides used;
  const auto si = static_cast<size_t>(strand);
  for (size_t k = 0; k < 3; ++k) {
    const int32_t g = binding.guides[si][k];
    if (g < 0) continue;
    const auto n = static_cast<size_t>(used.count++);
    used.guide[n] = g;
    used.segments[n] = static_cast<float>(binding.guide_offsets[static_cast<size_t>(g) + 1] -
                                          binding.guide_offsets[static_cast<size_t>(g)] - 1);
    used.weight[n] = binding.weights[si][k];
  }
  return used;
}

}  // namespace hair
