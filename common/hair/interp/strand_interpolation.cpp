#include "hair/interp/strand_interpolation.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "hair/core/error.h"
#include "hair/geom/barycentric.h"
#include "hair/geom/point_index.h"
#include "hair/interp/interpolation_kernel.h"
#include "hair/interp/interpolation_params.h"
#include "hair/style/hair_style.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;

/// Per guide particle in a frame's table: eight 4-float columns (interpolation_kernel.h's
/// kParticleFloats: of the position and of each of the frame's three columns, P_j and
/// then Q_j), so that a point is a few SIMD multiply-adds per guide.
constexpr int kColumns = 8;
static_assert(kColumns * 4 == kParticleFloats);
using Column = Eigen::Array4f;

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

/// The guides that strands can follow (strand guides, not wisp centres), their anchors
/// in a k-d tree, their directions at rest, and every guide's rest length.
struct FollowableGuides {
  std::vector<int32_t> usable;         ///< guide indices
  Points3f anchors;                    ///< per usable guide: its first particle
  std::vector<Vec3> direction;         ///< per usable guide: anchor to tip at rest, unit
  std::optional<PointIndex> index;     ///< of the anchors
  std::vector<double> guide_length_m;  ///< per guide: rest length from its anchor to its tip
};

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

/// The wisps' bindings: each bound point's global tetrahedron and its position in that
/// tetrahedron's frame.
void bind_wisp_points(const InterpolationGuides& guides, int64_t point_count,
                      StrandBinding& binding) {
  for (size_t b = 0; b < guides.binding_point.size(); ++b) {
    int64_t row = guides.binding_point[b];
    int32_t wisp = guides.binding_wisp[b];
    if (row < 0 || row >= point_count || wisp < 0 ||
        static_cast<size_t>(wisp) + 1 >= guides.wisp_tetrahedron_offsets.size())
      throw Error::runtime("guides", "wisp binding " + std::to_string(b) +
                                         " names a point or wisp that does not exist");
    int32_t first = guides.wisp_tetrahedron_offsets[static_cast<size_t>(wisp)];
    int32_t tetrahedron = first + guides.binding_tetrahedron[b];
    if (guides.binding_tetrahedron[b] < 0 ||
        tetrahedron >= guides.wisp_tetrahedron_offsets[static_cast<size_t>(wisp) + 1])
      throw Error::runtime("guides", "wisp binding " + std::to_string(b) +
                                         " names a tetrahedron its wisp does not have");
    binding.tetrahedron[static_cast<size_t>(row)] = tetrahedron;
    binding.offset_m.row(row) = guides.binding_local_m[b].transpose();
  }
}

/// The seams of every strand's bound points (StrandBinding::seam_offsets and what
/// follows): where consecutive bound points lie in different tetrahedra, the points within
/// `seam_length_m` of arc of the seam's middle, each with the tetrahedron across the
/// nearest seam, weighted 0.5 (1 - d / seam_length_m) at arc distance d. Needs bound_from.
void bind_wisp_seams(const StrandSet& strands, const InterpolationGuides& guides,
                     double seam_length_m, StrandBinding& binding) {
  const int64_t strand_count = strands.strand_count();
  binding.seam_offsets.assign(static_cast<size_t>(strand_count) + 1, 0);
  std::vector<double> arc;
  std::vector<size_t> seams;  // index k in the bound run: tetrahedron[k] != tetrahedron[k - 1]
  for (int64_t s = 0; s < strand_count; ++s) {
    const auto si = static_cast<size_t>(s);
    const int64_t bound = strands.offsets[si] + binding.bound_from[si],
                  end = strands.offsets[si + 1];
    const auto tetrahedron_of = [&](size_t k) {
      return binding.tetrahedron[static_cast<size_t>(bound) + k];
    };
    seams.clear();
    if (seam_length_m > 0 && end - bound >= 2) {
      const auto n = static_cast<size_t>(end - bound);
      arc.assign(n, 0.0);
      for (size_t k = 1; k < n; ++k) {
        const auto row = bound + static_cast<int64_t>(k);
        arc[k] =
            arc[k - 1] + (point_of(strands.points, row) - point_of(strands.points, row - 1)).norm();
        if (tetrahedron_of(k) != tetrahedron_of(k - 1)) seams.push_back(k);
      }
      for (size_t k = 0; k < n && !seams.empty(); ++k) {
        // The nearest seam by arc; the point lies in the tetrahedron on its own side.
        double nearest_m = std::numeric_limits<double>::infinity();
        size_t seam = 0;
        for (size_t j : seams) {
          const double distance_m = std::abs(arc[k] - 0.5 * (arc[j - 1] + arc[j]));
          if (distance_m < nearest_m) {
            nearest_m = distance_m;
            seam = j;
          }
        }
        if (nearest_m >= seam_length_m) continue;
        const int32_t other = k < seam ? tetrahedron_of(seam) : tetrahedron_of(seam - 1);
        const float* rest = guides.wisp_rest_frames.data() + 7 * static_cast<size_t>(other);
        const Eigen::Quaterniond rotation(rest[3], rest[4], rest[5], rest[6]);
        const Vec3 local = rotation.normalized().conjugate() *
                           (point_of(strands.points, bound + static_cast<int64_t>(k)) -
                            Vec3(rest[0], rest[1], rest[2]));
        binding.seam_row.push_back(bound + static_cast<int64_t>(k));
        binding.seam_tetrahedron.push_back(other);
        binding.seam_weight.push_back(static_cast<float>(0.5 * (1 - nearest_m / seam_length_m)));
        for (int r = 0; r < 3; ++r) binding.seam_local_m.push_back(static_cast<float>(local[r]));
      }
    }
    binding.seam_offsets[si + 1] = static_cast<int64_t>(binding.seam_row.size());
  }
}

/// Where the bridge of strand `s` to its wisp starts: its first point not held. The held
/// points (`held` from the root) give way from the end until the bridge, from the last
/// point still held to the first bound one, spans `length_m` of arc; the root stays held.
int64_t bridge_start(const StrandSet& strands, int64_t s, int64_t held, int64_t bound_from,
                     double length_m) {
  const int64_t begin = strands.offsets[static_cast<size_t>(s)];
  int64_t start = std::min(held, bound_from);
  if (start == 0) return 0;  // nothing held: bridged from the root
  double arc = 0;            // from point start - 1 to bound_from
  for (int64_t i = start; i <= bound_from; ++i)
    arc += (point_of(strands.points, begin + i) - point_of(strands.points, begin + i - 1)).norm();
  while (start > 1 && arc < length_m) {
    --start;
    arc += (point_of(strands.points, begin + start) - point_of(strands.points, begin + start - 1))
               .norm();
  }
  return start;
}

/// Where the bridge of strand `s` to its wisp ends: its first point still bound. Where the
/// held points gave way as far as they may (bridge_start(): the root stays held) and the
/// bridge from `start` - 1 to `bound_from` still spans less than `length_m` of arc (a strand
/// rooted right by the braid's top), the bound points give way from the first, up to the
/// last but one, until it does.
int64_t bridge_end(const StrandSet& strands, int64_t s, int64_t start, int64_t bound_from,
                   double length_m) {
  const int64_t begin = strands.offsets[static_cast<size_t>(s)];
  const int64_t size = strands.offsets[static_cast<size_t>(s) + 1] - begin;
  double arc = 0;  // from point max(start - 1, 0) to bound_from
  for (int64_t i = std::max<int64_t>(start, 1); i <= bound_from; ++i)
    arc += (point_of(strands.points, begin + i) - point_of(strands.points, begin + i - 1)).norm();
  while (bound_from + 2 < size && arc < length_m) {
    ++bound_from;
    arc += (point_of(strands.points, begin + bound_from) -
            point_of(strands.points, begin + bound_from - 1))
               .norm();
  }
  return bound_from;
}

/// The points of strand `s` between its held points and its wisp (a braided strand),
/// bridged from the head (the last held point, or the root) to the wisp by arc length.
void bridge_to_wisp(const StrandSet& strands, int64_t s, StrandBinding& binding) {
  const auto si = static_cast<size_t>(s);
  const int64_t begin = strands.offsets[si];
  const int64_t held = binding.held_count[si], bound_from = binding.bound_from[si];
  const int64_t from = held > 0 ? held - 1 : 0;
  std::vector<double> arc(static_cast<size_t>(bound_from - from + 1), 0.0);
  for (int64_t i = from + 1; i <= bound_from; ++i)
    arc[static_cast<size_t>(i - from)] =
        arc[static_cast<size_t>(i - from - 1)] +
        (point_of(strands.points, begin + i) - point_of(strands.points, begin + i - 1)).norm();
  for (int64_t i = held; i < bound_from; ++i) {
    const auto row = static_cast<size_t>(begin + i);
    binding.parameter[row] =
        arc.back() > 0 ? static_cast<float>(arc[static_cast<size_t>(i - from)] / arc.back()) : 0.0f;
    binding.offset_m.row(begin + i) = strands.points.row(begin + i);
  }
  binding.bridged[si] = 1;
  binding.method[si] = InterpolationMethod::braided;
}

/// The moving part of one strand to interpolate (points held to bound_from): its anchor
/// (the last held point, or the root), its cluster (that of its first moving point) and
/// its arc length from the anchor.
struct MovingStrand {
  const StrandSet& strands;
  int64_t begin = 0, held = 0, bound_from = 0, anchor = 0;
  Vec3 anchor_m = Vec3::Zero();
  int32_t cluster = 0;
  std::vector<double> arc;  ///< from the anchor, per point from it to the tip
  double length = 0;

  MovingStrand(const StrandSet& strands_in, int64_t s, int64_t held_in, int64_t bound_from_in,
               int32_t cluster_in)
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

  /// The arc parameter of point i along guides of rest length `guide_m`: a strand as long
  /// as they are or longer spans them (its tip follows theirs), a shorter one follows
  /// their first `length` metres (its tip follows the guide's point as far from the
  /// anchor). Spread over the whole guide, a strand a fifth its length would have each
  /// point follow a guide point five times as far out, and stretch as the guide bends.
  double parameter_along(int64_t i, double guide_m) const {
    const double span = std::max(length, guide_m);
    return span > 0 ? arc[static_cast<size_t>(i - anchor)] / span : 0.0;
  }

  /// Mean distance at rest from the moving points to guide g at the same arc parameter:
  /// the size of the offsets g would have to carry.
  double mean_offset_m(const InterpolationGuides& guides, const FollowableGuides& followable,
                       int32_t g) const {
    double sum = 0;
    for (int64_t i = held; i < bound_from; ++i)
      sum += (point_of(strands.points, begin + i) -
              guide_rest_point(
                  guides, g, parameter_along(i, followable.guide_length_m[static_cast<size_t>(g)])))
                 .norm();
    return sum / static_cast<double>(std::max<int64_t>(1, bound_from - held));
  }
};

/// The guides a strand follows and their weights.
struct GuideChoice {
  std::array<int32_t, 3> chosen = {-1, -1, -1};
  std::array<double, 3> weights = {1, 0, 0};
  bool barycentric = false;
};

/// Barycentric: the three nearest candidates (`nearest`, indices into followable.usable),
/// if they are of the strand's cluster, long enough, point alike and make no sliver;
/// else no choice (nullopt).
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

/// Clump: of the candidates `nearest`, the guide whose rest shape lies closest to the
/// strand's (the least mean offset: the nearest root alone can be a short guide that a
/// long strand would swing around): one of the strand's cluster long enough to follow;
/// else one long enough of another cluster simulated alike (`simulated_as`); else the best
/// of the cluster whatever its length; else the nearest guide of the cluster; else the
/// nearest guide.
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

/// Strand s follows `choice`: its method, guides and weights (normalised again in float,
/// so that they sum to 1 as the frames use them), and each moving point's arc parameter
/// and rest offset from the weighted guides there, along the guides' weighted length (one
/// parameter for the three guides of a barycentric strand).
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

namespace {

/// Per guide particle of one frame: its position and frame (see interpolate_frame()).
void guide_frame_table(const StrandBinding& binding, const GuideFrame& frame, Column* table) {
  const float* rest_points = binding.guide_rest_points.data();
  const int64_t guides = static_cast<int64_t>(binding.guide_offsets.size()) - 1;
  const Eigen::Quaterniond head = frame.head.rotation.normalized();
  auto put = [&](int64_t row, const Eigen::Quaterniond& q) {
    Eigen::Matrix3f m = q.toRotationMatrix().cast<float>();
    Column* out = table + row * kColumns;
    const float* p = frame.guide_points_m + 3 * row;
    out[0] = Column(p[0], p[1], p[2], 0);
    for (int c = 0; c < 3; ++c) out[2 + 2 * c] = Column(m(0, c), m(1, c), m(2, c), 0);
  };
  std::vector<Eigen::Quaterniond> segment;
  for (int64_t g = 0; g < guides; ++g) {
    const int64_t first = binding.guide_offsets[static_cast<size_t>(g)];
    const int64_t count = binding.guide_offsets[static_cast<size_t>(g) + 1] - first;
    segment.resize(static_cast<size_t>(count - 1));
    for (int64_t j = 0; j + 1 < count; ++j) {
      const float* r0 = rest_points + 3 * (first + j);
      const float* p0 = frame.guide_points_m + 3 * (first + j);
      Vec3 rest_direction(r0[3] - r0[0], r0[4] - r0[1], r0[5] - r0[2]);
      Vec3 now(p0[3] - p0[0], p0[4] - p0[1], p0[5] - p0[2]);
      Vec3 carried = head * rest_direction;
      Eigen::Quaterniond turn = Eigen::Quaterniond::Identity();
      if (carried.squaredNorm() > 0 && now.squaredNorm() > 0)
        turn = Eigen::Quaterniond::FromTwoVectors(carried, now);
      segment[static_cast<size_t>(j)] = (turn * head).normalized();
    }
    put(first, head);
    for (int64_t k = 1; k < count; ++k) {
      Eigen::Quaterniond q = segment[static_cast<size_t>(k - 1)];
      if (k + 1 < count) {
        Eigen::Quaterniond next = segment[static_cast<size_t>(k)];
        if (q.dot(next) < 0) next.coeffs() = -next.coeffs();
        q.coeffs() += next.coeffs();
        q.normalize();
      }
      put(first + k, q);
    }
    // Particle k's record as the kernel reads it: the columns C_k and the steps B_k =
    // C_k+1 - C_k make C(u) = C_k + (u S - k) B_k on the segment (S segments), so the
    // record holds, per column, P_k = C_k - k B_k and then Q_k = S B_k, and C(u) = P_k +
    // u Q_k.
    const auto segments = static_cast<float>(count - 1);
    for (int64_t k = 0; k < count; ++k) {
      Column* here = table + (first + k) * kColumns;
      for (int c = 0; c < 8; c += 2) {
        const Column step = k + 1 < count ? Column(here[kColumns + c] - here[c]) : Column::Zero();
        here[c] -= static_cast<float>(k) * step;
        here[c + 1] = segments * step;
      }
    }
  }
}

}  // namespace

void interpolate_frame(const StrandBinding& binding, const StrandSet& strands,
                       const GuideFrame& frame, std::vector<float>& points_m) {
  const int64_t strand_count = strands.strand_count();
  points_m.resize(static_cast<size_t>(strands.point_count()) * 3);
  // The table on a 64-byte boundary (the kernel's loads are aligned).
  std::vector<Column> table_storage(
      static_cast<size_t>(binding.guide_rest_points.rows()) * kColumns + 3);
  Column* table = table_storage.data() +
                  (4 - reinterpret_cast<uintptr_t>(table_storage.data()) / sizeof(Column) % 4) % 4;
  guide_frame_table(binding, frame, table);
  // Rigid frames in transform_points()'s layout: per wisp tetrahedron, where it is now;
  // and the head.
  auto put_frame = [](float* record, const Eigen::Vector3f& origin, const Eigen::Matrix3f& m) {
    for (int r = 0; r < 3; ++r) {
      record[r] = origin[r];
      for (int c = 0; c < 3; ++c) record[4 + 4 * c + r] = m(r, c);
    }
  };
  const auto tetrahedron_count = static_cast<size_t>(binding.tetrahedron_count);
  std::vector<float> tetrahedron_frames(tetrahedron_count * kFrameFloats);
  for (int64_t t = 0; t < binding.tetrahedron_count; ++t) {
    const float* in = frame.wisp_frames + 7 * t;
    Eigen::Matrix3f m =
        Eigen::Quaternionf(in[3], in[4], in[5], in[6]).normalized().toRotationMatrix();
    put_frame(tetrahedron_frames.data() + t * kFrameFloats, Eigen::Vector3f(in[0], in[1], in[2]),
              m);
  }
  float head_frame[kFrameFloats] = {};
  put_frame(head_frame, frame.head.translation_m.cast<float>(),
            frame.head.rotation.normalized().toRotationMatrix().cast<float>());
  const float* offset = binding.offset_m.data();
  float* out = points_m.data();

#pragma omp parallel for schedule(dynamic, 256)
  for (int64_t s = 0; s < strand_count; ++s) {
    const auto si = static_cast<size_t>(s);
    const int64_t begin = strands.offsets[si];
    const int64_t end = strands.offsets[si + 1];
    const int64_t interpolated = begin + binding.interpolated_from[si];
    const int64_t bound = begin + binding.bound_from[si];
    // Held: R p + t.
    transform_points(head_frame, nullptr, offset + 3 * begin, interpolated - begin,
                     out + 3 * begin);
    // Bound: origin + R_tet local.
    transform_points(tetrahedron_frames.data(), binding.tetrahedron.data() + bound,
                     offset + 3 * bound, end - bound, out + 3 * bound);
    // Near a seam between two tetrahedra: (1 - w)(o_own + R_own l_own) + w (o + R l) of
    // the other one.
    for (int64_t e = binding.seam_offsets[si]; e < binding.seam_offsets[si + 1]; ++e) {
      const auto ei = static_cast<size_t>(e);
      const float* f = tetrahedron_frames.data() +
                       static_cast<size_t>(binding.seam_tetrahedron[ei]) * kFrameFloats;
      const float* l = binding.seam_local_m.data() + 3 * ei;
      const float w = binding.seam_weight[ei];
      float* p = out + 3 * binding.seam_row[ei];
      for (int r = 0; r < 3; ++r)
        p[r] = (1 - w) * p[r] + w * (f[r] + f[4 + r] * l[0] + f[8 + r] * l[1] + f[12 + r] * l[2]);
    }
    // Bridged: R p + t + s (x_b - (R b + t)), b the first bound point at rest and x_b where
    // its tetrahedron carries it: the head's motion plus a share of how far the wisp's top
    // moved from where the head would have carried it (no lever arm from the tetrahedron).
    if (binding.bridged[si]) {
      const float* h = head_frame;
      float junction_move[3];
      for (int r = 0; r < 3; ++r) {
        const float b = h[4 + r] * strands.points(bound, 0) + h[8 + r] * strands.points(bound, 1) +
                        h[12 + r] * strands.points(bound, 2) + h[r];
        junction_move[r] = out[3 * bound + r] - b;
      }
      for (int64_t row = interpolated; row < bound; ++row) {
        const float share = binding.parameter[static_cast<size_t>(row)];
        const float* p = offset + 3 * row;
        for (int r = 0; r < 3; ++r)
          out[3 * row + r] = h[4 + r] * p[0] + h[8 + r] * p[1] + h[12 + r] * p[2] + h[r] +
                             share * junction_move[r];
      }
    } else if (interpolated < bound) {
      // Interpolated: sum_g w_g (G_g(u) + F_g(u) d), in runs where the strand has them.
      const StrandGuides used = strand_guides(binding, s);
      const float* guide_table[3];
      for (size_t k = 0; k < static_cast<size_t>(used.count); ++k)
        guide_table[k] = table->data() + binding.guide_offsets[static_cast<size_t>(used.guide[k])] *
                                             kParticleFloats;
      const int64_t first_run = binding.run_offsets[si];
      const auto run_count = static_cast<int>(binding.run_offsets[si + 1] - first_run);
      if (run_count > 0)
        interpolate_strand_runs(guide_table, used.weight.data(), used.count,
                                binding.run_particles.data() + first_run, run_count,
                                binding.run_of_point.data() + interpolated,
                                binding.parameter.data() + interpolated, offset + 3 * interpolated,
                                bound - interpolated, out + 3 * interpolated);
      else
        interpolate_strand_points(guide_table, used.segments.data(), used.weight.data(), used.count,
                                  binding.parameter.data() + interpolated,
                                  offset + 3 * interpolated, bound - interpolated,
                                  out + 3 * interpolated);
    }
  }
}

}  // namespace hair
