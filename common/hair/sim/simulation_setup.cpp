#include "hair/sim/simulation_setup.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "hair/core/error.h"
#include "hair/geom/polyline.h"
#include "hair/sim/body_collider.h"
#include "hair/sim/sag_free_rest.h"
#include "hair/sim/wisp_gathering.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;

/// Moves each point after the first that is closer to the body than `clearance_m` out
/// to it along the field's gradient.
void keep_clear_of_body(const BodySdf& body, double clearance_m, std::vector<Vec3>& points) {
  for (size_t i = 1; i < points.size(); ++i) {
    if (body.certainly_farther_than(points[i], clearance_m)) continue;
    const double distance = body.distance(points[i]);
    if (distance < clearance_m) push_out_along_gradient(body, points[i], distance, clearance_m);
  }
}

/// The polyline `points` resampled to `segments` equal arcs, both ends kept.
std::vector<Vec3> resample_polyline(const std::vector<Vec3>& points, int segments) {
  std::vector<double> arc(points.size(), 0.0);
  for (size_t i = 1; i < points.size(); ++i)
    arc[i] = arc[i - 1] + (points[i] - points[i - 1]).norm();
  std::vector<Vec3> resampled;
  resampled.reserve(static_cast<size_t>(segments) + 1);
  size_t segment = 0;
  for (int k = 0; k <= segments; ++k) {
    double target = arc.back() * k / segments;
    while (segment + 2 < points.size() && arc[segment + 1] < target) ++segment;
    double span = arc[segment + 1] - arc[segment];
    double t = span > 0 ? std::clamp((target - arc[segment]) / span, 0.0, 1.0) : 0.0;
    resampled.push_back((1 - t) * points[segment] + t * points[segment + 1]);
  }
  resampled.front() = points.front();
  resampled.back() = points.back();
  return resampled;
}

int segments_for(double length_m, double spacing_m) {
  return std::max(2, static_cast<int>(std::ceil(length_m / spacing_m - 1e-6)));
}

const std::vector<int32_t>& point_clusters(const StrandSet& strands) {
  return std::get<std::vector<int32_t>>(strands.point_attributes.at("cluster"));
}

/// Gathers the wisp of every braided cluster of result.plan into `centres` (kept from an
/// earlier call) and its members that end away from the braid into `loose` (cleared
/// first). A cluster that does not gather is simulated as fixed hair if most of its points
/// lie on the body, as normal hair otherwise (result.simulated_style); returns whether
/// there was one. `say`: log the loose members.
bool gather_wisps(const SimulationScene& scene, const SimulationParams& params,
                  const std::optional<BodySdf>& body, bool say, SimulationResult& result,
                  WispCentres& centres, std::vector<GuideStrand>& loose) {
  const double h = scene.head_height_m;
  const StrandSet& strands = scene.strands;
  const double clearance_m = params.body_clearance_h * h;
  bool failed = false;
  loose.clear();
  for (WispPlan& wisp : result.plan.wisps) {
    std::vector<GuideStrand> outside;
    std::vector<Vec3> centre =
        gather_wisp(strands, wisp, params.segment_length_h * h * params.wisp_segment_factor,
                    params.wisp_gather_radius_h * h, *body, clearance_m, outside);
    if (centre.empty()) {
      // Not a braid: hair lying on the head (most of its points within 0.1 H of the
      // body, as a cap gathered into a braid) is held there, other hair hangs free.
      int64_t points = 0, lying = 0;
      for (size_t m = 0; m < wisp.member_strand.size(); ++m) {
        int64_t base = strands.offsets[static_cast<size_t>(wisp.member_strand[m])];
        for (int64_t i = wisp.member_first_point[m]; i < wisp.member_end_point[m]; ++i) {
          ++points;
          lying += body->distance(point_of(strands.points, base + i)) < 0.1 * h;
        }
      }
      HairStyle instead = 2 * lying >= points ? HairStyle::fixed : HairStyle::normal;
      spdlog::warn(
          "{}: braided cluster {}: its {} strands do not gather into a bundle; {}% of its "
          "points lie on the body: simulated as {} hair",
          scene.source, wisp.cluster, wisp.member_strand.size(),
          points ? 100 * lying / points : 0, hair_style_name(instead));
      result.simulated_style[static_cast<size_t>(wisp.cluster)] = static_cast<int8_t>(instead);
      failed = true;
      continue;
    }
    if (say && !outside.empty())
      spdlog::info(
          "{}: braided cluster {}: {} of its strands end away from the braid; "
          "simulated as normal hair",
          scene.source, wisp.cluster, outside.size());
    centres[wisp.cluster] = std::move(centre);
    loose.insert(loose.end(), outside.begin(), outside.end());
  }
  return failed;
}

/// Guides for the strands outside the bundles (`loose`), in proportion, as plan_guides
/// gives them: appended to result.plan.guides and counted in its cluster_guides.
void plan_loose_guides(const StrandSet& strands, const std::vector<GuideStrand>& loose,
                       int guide_count, SimulationResult& result) {
  if (loose.empty()) return;
  int64_t candidates = static_cast<int64_t>(loose.size());
  for (size_t c = 0; c < result.plan.cluster_candidates.size(); ++c) {
    int8_t style = result.simulated_style[c];
    if (style == static_cast<int8_t>(HairStyle::normal) ||
        style == static_cast<int8_t>(HairStyle::short_hair))
      candidates += result.plan.cluster_candidates[c];
  }
  std::map<int32_t, std::vector<GuideStrand>> by_cluster;
  for (const GuideStrand& guide : loose) by_cluster[guide.cluster].push_back(guide);
  for (auto& [cluster, members] : by_cluster) {
    auto count = std::max<int64_t>(
        1, std::llround(static_cast<double>(guide_count) * static_cast<double>(members.size()) /
                        static_cast<double>(candidates)));
    std::vector<Vec3> anchors;
    for (const GuideStrand& guide : members)
      anchors.push_back(
          point_of(strands.points,
                   strands.offsets[static_cast<size_t>(guide.strand)] + guide.anchor_point));
    for (int64_t k : farthest_point_sample(anchors, count))
      result.plan.guides.push_back(members[static_cast<size_t>(k)]);
    result.plan.cluster_guides[static_cast<size_t>(cluster)] +=
        static_cast<int32_t>(std::min<int64_t>(count, static_cast<int64_t>(members.size())));
  }
}

/// Binds every point of `wisp`'s members from the braid on to the nearest tetrahedron
/// (by centroid) of its centre strand `model` at rest: result.wisp_bindings, with the
/// wisp's index `wisp_index`.
void bind_wisp_members(const StrandSet& strands, const WispPlan& wisp, int32_t wisp_index,
                       const AltitudeStrand& model, const std::string& source,
                       SimulationResult& result) {
  const auto& rest = model.rest_m;
  std::vector<Vec3> centroid;
  std::vector<Eigen::Matrix3d> frame;
  for (const ChainTetrahedron& t : model.tetrahedra) {
    Vec3 sum = Vec3::Zero();
    for (int32_t q : t.particle) sum += rest[static_cast<size_t>(q)];
    centroid.push_back(sum / 4);
    frame.push_back(tetrahedron_frame(rest[static_cast<size_t>(t.particle[0])],
                                      rest[static_cast<size_t>(t.particle[1])],
                                      rest[static_cast<size_t>(t.particle[2])]));
  }
  if (centroid.empty())  // gather_wisp() gives three centre points at least
    throw Error::runtime(source, "the wisp of braided cluster " + std::to_string(wisp.cluster) +
                                     " has no tetrahedron");
  result.wisp_tetrahedron_offset.push_back(result.wisp_tetrahedron_offset.back() +
                                           static_cast<int32_t>(centroid.size()));
  for (size_t m = 0; m < wisp.member_strand.size(); ++m) {
    int64_t base = strands.offsets[static_cast<size_t>(wisp.member_strand[m])];
    int64_t end = strands.offsets[static_cast<size_t>(wisp.member_strand[m]) + 1];
    for (int64_t row = base + wisp.member_first_point[m]; row < end; ++row) {
      Vec3 p = point_of(strands.points, row);
      size_t nearest = 0;
      double best = std::numeric_limits<double>::infinity();
      for (size_t t = 0; t < centroid.size(); ++t) {
        double d = (centroid[t] - p).squaredNorm();
        if (d < best) {
          best = d;
          nearest = t;
        }
      }
      WispBinding binding;
      binding.point = row;
      binding.wisp = wisp_index;
      binding.tetrahedron = static_cast<int32_t>(nearest);
      const Vec3& origin = rest[static_cast<size_t>(model.tetrahedra[nearest].particle[0])];
      binding.local_m = (frame[nearest].transpose() * (p - origin)).cast<float>();
      result.wisp_bindings.push_back(binding);
    }
    ++result.braided_strands;
  }
}

}  // namespace

Eigen::Matrix3d tetrahedron_frame(const Vec3& q0, const Vec3& q1, const Vec3& q2) {
  Vec3 x = (q1 - q0).normalized();
  Vec3 y = q2 - q0;
  y = (y - y.dot(x) * x).normalized();
  Eigen::Matrix3d frame;
  frame.col(0) = x;
  frame.col(1) = y;
  frame.col(2) = x.cross(y);
  return frame;
}

std::vector<int8_t> styles_to_simulate(const std::vector<int8_t>& cluster_style, bool by_style) {
  std::vector<int8_t> simulated_style = cluster_style;
  if (!by_style)
    for (int8_t& style : simulated_style)
      if (style >= 0) style = static_cast<int8_t>(HairStyle::normal);
  return simulated_style;
}

std::optional<BodySdf> body_field_over_hair(const SimulationScene& scene,
                                            const std::vector<int8_t>& simulated_style,
                                            const SimulationParams& params) {
  const double h = scene.head_height_m;
  const StrandSet& strands = scene.strands;
  const std::vector<int32_t>& point_cluster = point_clusters(strands);
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (int64_t row = 0; row < strands.point_count(); ++row) {
    int8_t style = simulated_style[static_cast<size_t>(point_cluster[static_cast<size_t>(row)])];
    if (style < 0 || style == static_cast<int8_t>(HairStyle::fixed)) continue;
    low = low.cwiseMin(point_of(strands.points, row));
    high = high.cwiseMax(point_of(strands.points, row));
  }
  std::optional<BodySdf> body;
  if (low.x() <= high.x()) {
    Vec3 margin = Vec3::Constant(0.25 * h);
    body.emplace(scene.body_vertices, scene.body_triangles, low - margin, high + margin,
                 params.body_voxel_h * h, params.body_band_h * h, scene.source);
  }
  return body;
}

WispCentres plan_simulation(const SimulationScene& scene, const SimulationParams& params,
                            const std::optional<BodySdf>& body, SimulationResult& result) {
  const StrandSet& strands = scene.strands;
  result.plan = plan_guides(strands, result.simulated_style, params.guide_count);
  WispCentres centres;
  std::vector<GuideStrand> loose;  // braided clusters' strands outside their bundles
  if (gather_wisps(scene, params, body, true, result, centres, loose)) {
    // again without the clusters that are not braids
    result.plan = plan_guides(strands, result.simulated_style, params.guide_count);
    gather_wisps(scene, params, body, false, result, centres, loose);
  }
  const std::vector<int32_t>& point_cluster = point_clusters(strands);
  for (int64_t s = 0; s < strands.strand_count(); ++s) {
    int8_t style = result.simulated_style[static_cast<size_t>(
        point_cluster[static_cast<size_t>(strands.offsets[static_cast<size_t>(s)])])];
    if (style == static_cast<int8_t>(HairStyle::fixed)) ++result.fixed_strands;
  }
  plan_loose_guides(strands, loose, params.guide_count, result);
  return centres;
}

std::vector<RunningStrand> build_strand_guides(const SimulationScene& scene,
                                               const SimulationParams& params,
                                               const StrandStiffness& stiffness,
                                               const std::optional<BodySdf>& body,
                                               SimulationResult& result) {
  const double h = scene.head_height_m;
  const double clearance_m = params.body_clearance_h * h;
  const StrandSet& strands = scene.strands;
  std::vector<RunningStrand> running;
  for (const GuideStrand& guide : result.plan.guides) {
    int64_t begin = strands.offsets[static_cast<size_t>(guide.strand)] + guide.anchor_point;
    int64_t end = strands.offsets[static_cast<size_t>(guide.strand) + 1];
    std::vector<Vec3> polyline;
    for (int64_t row = begin; row < end; ++row) polyline.push_back(point_of(strands.points, row));
    double length = polyline_length(polyline);
    if (!(length > 1e-4 * h)) continue;
    double spacing = params.segment_length_h * h *
                     (guide.style == HairStyle::short_hair ? params.short_segment_factor : 1.0);
    SimulatedGuide simulated;
    simulated.kind = GuideKind::strand;
    simulated.strand = guide.strand;
    simulated.anchor_point = guide.anchor_point;
    simulated.cluster = guide.cluster;
    simulated.style = guide.style;
    simulated.rest_m = resample_polyline(polyline, segments_for(length, spacing));
    if (body && params.body_collisions) keep_clear_of_body(*body, clearance_m, simulated.rest_m);
    RunningStrand strand;
    strand.model = build_hair_strand(simulated.rest_m, stiffness);
    simulated.ghost_count = strand.model.ghost_count();
    result.guides.push_back(std::move(simulated));
    running.push_back(std::move(strand));
  }
  return running;
}

void build_wisps(const SimulationScene& scene, const StrandStiffness& stiffness, const WispCentres& centres, SimulationResult& result,
                 std::vector<RunningStrand>& running) {
  for (size_t w = 0; w < result.plan.wisps.size(); ++w) {
    const WispPlan& wisp = result.plan.wisps[w];
    const std::vector<Vec3>& centre = centres.at(wisp.cluster);
    auto count = static_cast<double>(wisp.member_strand.size());
    SimulatedGuide simulated;
    simulated.kind = GuideKind::wisp_centre;
    simulated.cluster = wisp.cluster;
    simulated.style = HairStyle::braided;
    simulated.mass_scale = count;
    simulated.rest_m = centre;
    simulated.anchor_count = static_cast<int32_t>(wisp.anchor_m.size());
    RunningStrand strand;
    AltitudeStrandOptions hung;  // from its anchors, not clamped at a root
    hung.clamped_root = false;
    strand.model = build_hair_strand(centre, stiffness, count, hung);
    strand.model.kinematic_count = 0;  // it hangs from its anchors
    simulated.ghost_count = strand.model.ghost_count();
    for (const Vec3& anchor : wisp.anchor_m) {
      StrandAnchor spring;
      spring.rest_length_m = (centre.front() - anchor).norm();
      strand.anchors.push_back(spring);
      strand.anchor_rest_m.push_back(anchor);
    }
    if (wisp.loose_anchor_count > 0)
      spdlog::info(
          "{}: {} strands enter braided cluster {} from simulated hair; their ends are "
          "moved with the head",
          scene.source, wisp.loose_anchor_count, wisp.cluster);

    auto wisp_index = static_cast<int32_t>(result.wisp_guide.size());
    result.wisp_guide.push_back(static_cast<int32_t>(result.guides.size()));
    if (result.wisp_tetrahedron_offset.empty()) result.wisp_tetrahedron_offset.push_back(0);
    bind_wisp_members(scene.strands, wisp, wisp_index, strand.model, scene.source, result);
    result.guides.push_back(std::move(simulated));
    running.push_back(std::move(strand));
  }
  if (result.wisp_tetrahedron_offset.empty()) result.wisp_tetrahedron_offset.push_back(0);
}

void make_rests_sag_free(const SimulationParams& params, const HeadMotion& motion,
                         const std::string& source, std::vector<RunningStrand>& running) {
  // Gravity in the rest frame, as the head holds the body at time 0.
  const RigidTransform head = motion.at(0);
  const Vec3 gravity = head.rotation.conjugate() * Vec3(0, -params.gravity_m_s2, 0);
  double weight_n = 0, support_n = 0, strain = 0;
  for (RunningStrand& strand : running) {
    const SagFreeReport report = make_sag_free(strand.model, params.material, gravity);
    weight_n += report.weight_n;
    support_n += report.support_n;
    strain = std::max(strain, report.largest_tension_strain);
  }
  spdlog::info(
      "{}: sag-free rest: the strands hang {:.0f}% of their weight from their roots along "
      "themselves (largest strain {:.1e}); their support holds up {:.0f}%",
      source, 100 * (1 - support_n / std::max(weight_n, 1e-300)), strain,
      100 * support_n / std::max(weight_n, 1e-300));
}

}  // namespace hair
