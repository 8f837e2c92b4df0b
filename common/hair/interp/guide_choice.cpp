// The guides an interpolated strand follows and its binding to them (guide_choice.h).
#include "hair/interp/guide_choice.h"

#include <cmath>
#include <limits>
#include <string>

#include "hair/core/error.h"
#include "hair/geom/barycentric.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;

/// Smallest height of triangle (a, b, c) over its longest edge.
double triangle_aspect(const Vec3& a, const Vec3& b, const Vec3& c) {
  double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
  if (!(longest > 0)) return 0;
  double twice_area = (b - a).cross(c - a).norm();
  return twice_area / longest / longest;
}

/// The guide's point at arc parameter u in [0, 1] at rest (guides are resampled to equal
/// arcs, so the parameter is linear in the particle index).
Vec3 guide_rest_point(const InterpolationGuides& guides, int32_t g, double u) {
  int64_t first = guides.offsets[static_cast<size_t>(g)];
  int64_t segments = guides.offsets[static_cast<size_t>(g) + 1] - first - 1;
  double x = u * static_cast<double>(segments);
  int64_t k = std::clamp<int64_t>(static_cast<int64_t>(std::floor(x)), 0, segments - 1);
  double f = x - static_cast<double>(k);
  Vec3 p0 = point_of(guides.rest_points, first + k);
  Vec3 p1 = point_of(guides.rest_points, first + k + 1);
  return p0 + f * (p1 - p0);
}

}  // namespace

FollowableGuides followable_guides(const InterpolationGuides& guides) {
  FollowableGuides followable;
  std::vector<int32_t>& usable = followable.usable;
  for (int32_t g = 0; g < static_cast<int32_t>(guides.guide_count()); ++g) {
    if (guides.offsets[static_cast<size_t>(g) + 1] - guides.offsets[static_cast<size_t>(g)] < 2)
      throw Error::runtime("guides", "guide " + std::to_string(g) + " has fewer than 2 particles");
    if (!guides.is_wisp_centre[static_cast<size_t>(g)]) usable.push_back(g);
  }
  followable.anchors.resize(static_cast<Eigen::Index>(usable.size()), 3);
  for (size_t i = 0; i < usable.size(); ++i) {
    int32_t g = usable[i];
    Vec3 first = point_of(guides.rest_points, guides.offsets[static_cast<size_t>(g)]);
    Vec3 last = point_of(guides.rest_points, guides.offsets[static_cast<size_t>(g) + 1] - 1);
    followable.anchors.row(static_cast<Eigen::Index>(i)) = first.cast<float>().transpose();
    followable.direction.push_back((last - first).normalized());
  }
  followable.index.emplace(followable.anchors);
  followable.guide_length_m.assign(static_cast<size_t>(guides.guide_count()), 0.0);
  for (int32_t g = 0; g < static_cast<int32_t>(guides.guide_count()); ++g)
    for (int64_t k = guides.offsets[static_cast<size_t>(g)] + 1;
         k < guides.offsets[static_cast<size_t>(g) + 1]; ++k)
      followable.guide_length_m[static_cast<size_t>(g)] +=
          (point_of(guides.rest_points, k) - point_of(guides.rest_points, k - 1)).norm();
  return followable;
}

MovingStrand::MovingStrand(const StrandSet& strands_in, int64_t s, int64_t held_in,
                           int64_t bound_from_in, int32_t cluster_in)
    : strands(strands_in),
      begin(strands_in.offsets[static_cast<size_t>(s)]),
      held(held_in),
      bound_from(bound_from_in),
      anchor(held_in > 0 ? held_in - 1 : 0),
      anchor_m(point_of(strands_in.points, begin + anchor)),
      cluster(cluster_in) {
  const int64_t size = strands.offsets[static_cast<size_t>(s) + 1] - begin;
  arc.assign(static_cast<size_t>(size - anchor), 0.0);
  for (int64_t i = anchor + 1; i < size; ++i)
    arc[static_cast<size_t>(i - anchor)] =
        arc[static_cast<size_t>(i - anchor - 1)] +
        (point_of(strands.points, begin + i) - point_of(strands.points, begin + i - 1)).norm();
  length = arc.back();
}

double MovingStrand::mean_offset_m(const InterpolationGuides& guides,
                                   const FollowableGuides& followable, int32_t g) const {
  double sum = 0;
  for (int64_t i = held; i < bound_from; ++i)
    sum += (point_of(strands.points, begin + i) -
            guide_rest_point(
                guides, g, parameter_along(i, followable.guide_length_m[static_cast<size_t>(g)])))
               .norm();
  return sum / static_cast<double>(std::max<int64_t>(1, bound_from - held));
}

std::optional<GuideChoice> barycentric_choice(const MovingStrand& strand,
                                              const InterpolationGuides& guides,
                                              const FollowableGuides& followable,
                                              const std::vector<int32_t>& nearest,
                                              const InterpolationParams& params) {
  if (nearest.size() < 3) return std::nullopt;
  const std::vector<int32_t>& usable = followable.usable;
  const double shortest_m = params.min_guide_length_ratio * strand.length;
  for (size_t k = 0; k < 3; ++k)
    if (guides.cluster[static_cast<size_t>(usable[static_cast<size_t>(nearest[k])])] !=
        strand.cluster)
      return std::nullopt;
  for (size_t k = 0; k < 3; ++k)
    if (!(followable.guide_length_m[static_cast<size_t>(usable[static_cast<size_t>(nearest[k])])] >=
          shortest_m))
      return std::nullopt;
  for (size_t a = 0; a < 3; ++a)
    for (size_t b = a + 1; b < 3; ++b)
      if (followable.direction[static_cast<size_t>(nearest[a])].dot(
              followable.direction[static_cast<size_t>(nearest[b])]) < params.min_direction_cosine)
        return std::nullopt;
  Vec3 a = followable.anchors.row(nearest[0]).cast<double>().transpose();
  Vec3 b = followable.anchors.row(nearest[1]).cast<double>().transpose();
  Vec3 c = followable.anchors.row(nearest[2]).cast<double>().transpose();
  if (triangle_aspect(a, b, c) < params.min_triangle_aspect) return std::nullopt;
  GuideChoice choice;
  choice.barycentric = true;
  choice.weights = clamped_barycentric(strand.anchor_m, a, b, c);
  for (size_t k = 0; k < 3; ++k) choice.chosen[k] = usable[static_cast<size_t>(nearest[k])];
  return choice;
}

GuideChoice clump_choice(const MovingStrand& strand, const InterpolationGuides& guides,
                         const FollowableGuides& followable, const std::vector<int32_t>& nearest,
                         int8_t simulated_as, const InterpolationParams& params) {
  const std::vector<int32_t>& usable = followable.usable;
  const double shortest_m = params.min_guide_length_ratio * strand.length;
  auto long_enough = [&](int32_t g) {
    return followable.guide_length_m[static_cast<size_t>(g)] >= shortest_m;
  };
  std::vector<double> candidate_offset_m(nearest.size(), -1);  // each worked out once
  auto best_of = [&](auto&& admits) {
    int32_t found = -1;
    double best_offset = std::numeric_limits<double>::infinity();
    for (size_t c = 0; c < nearest.size(); ++c) {
      const int32_t g = usable[static_cast<size_t>(nearest[c])];
      if (!admits(g)) continue;
      if (candidate_offset_m[c] < 0)
        candidate_offset_m[c] = strand.mean_offset_m(guides, followable, g);
      if (candidate_offset_m[c] < best_offset) {
        best_offset = candidate_offset_m[c];
        found = nearest[c];
      }
    }
    return found;
  };
  auto in_cluster = [&](int32_t g) {
    return guides.cluster[static_cast<size_t>(g)] == strand.cluster;
  };
  int32_t best = best_of([&](int32_t g) { return in_cluster(g) && long_enough(g); });
  if (best < 0)
    best = best_of([&](int32_t g) {
      const auto guide_cluster = static_cast<size_t>(guides.cluster[static_cast<size_t>(g)]);
      return long_enough(g) && guide_cluster < guides.cluster_simulated_style.size() &&
             guides.cluster_simulated_style[guide_cluster] == simulated_as;
    });
  if (best < 0) best = best_of(in_cluster);
  if (best < 0) {
    double best_distance = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < usable.size(); ++i) {
      if (guides.cluster[static_cast<size_t>(usable[i])] != strand.cluster) continue;
      double d = (followable.anchors.row(static_cast<Eigen::Index>(i)).cast<double>().transpose() -
                  strand.anchor_m)
                     .squaredNorm();
      if (d < best_distance) {
        best_distance = d;
        best = static_cast<int32_t>(i);
      }
    }
  }
  if (best < 0) best = nearest.front();
  GuideChoice choice;
  choice.chosen = {usable[static_cast<size_t>(best)], -1, -1};
  return choice;
}

void follow(const MovingStrand& strand, int64_t s, const GuideChoice& choice,
            const InterpolationGuides& guides, const FollowableGuides& followable,
            StrandBinding& binding) {
  const auto si = static_cast<size_t>(s);
  const std::array<int32_t, 3>& chosen = choice.chosen;
  binding.method[si] =
      choice.barycentric ? InterpolationMethod::barycentric : InterpolationMethod::clump;
  binding.guides[si] = chosen;
  for (size_t k = 0; k < 3; ++k) binding.weights[si][k] = static_cast<float>(choice.weights[k]);
  float sum = binding.weights[si][0] + binding.weights[si][1] + binding.weights[si][2];
  for (float& weight : binding.weights[si]) weight /= sum;

  double guides_m = 0;
  for (size_t k = 0; k < 3; ++k)
    if (chosen[k] >= 0)
      guides_m += static_cast<double>(binding.weights[si][k]) *
                  followable.guide_length_m[static_cast<size_t>(chosen[k])];
  const StrandSet& strands = strand.strands;
  for (int64_t i = strand.held; i < strand.bound_from; ++i) {
    auto uf = static_cast<float>(strand.parameter_along(i, guides_m));
    Vec3 blended = Vec3::Zero();
    for (size_t k = 0; k < 3; ++k)
      if (chosen[k] >= 0)
        blended += static_cast<double>(binding.weights[si][k]) *
                   guide_rest_point(guides, chosen[k], static_cast<double>(uf));
    binding.parameter[static_cast<size_t>(strand.begin + i)] = uf;
    binding.offset_m.row(strand.begin + i) =
        (point_of(strands.points, strand.begin + i) - blended).cast<float>().transpose();
  }
}

}  // namespace hair
