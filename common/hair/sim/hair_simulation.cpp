#include "hair/sim/hair_simulation.h"

#include <omp.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

#include "hair/core/error.h"
#include "hair/geom/body_sdf.h"
#include "hair/sim/body_collider.h"
#include "hair/sim/hair_density_field.h"
#include "hair/sim/wisp_gathering.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;

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

double polyline_length(const std::vector<Vec3>& points) {
  double length = 0;
  for (size_t i = 1; i < points.size(); ++i) length += (points[i] - points[i - 1]).norm();
  return length;
}

int segments_for(double length_m, double spacing_m) {
  return std::max(2, static_cast<int>(std::ceil(length_m / spacing_m - 1e-6)));
}

/// The orthonormal frame of a centre-strand tetrahedron: origin at its first corner, x
/// along its first edge, y toward its third corner.
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

void check_params(const SimulationParams& p) {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw Error::usage(what);
  };
  require(p.fps > 0 && std::isfinite(p.fps), "fps must be positive");
  require(p.duration_s >= 0 && std::isfinite(p.duration_s), "duration_s must be 0 or positive");
  require(p.substeps >= 1, "substeps must be at least 1");
  require(p.guide_count >= 0, "guide_count must be 0 or more");
  require(p.segment_length_h > 0, "segment_length_h must be positive");
  require(p.short_segment_factor > 0 && p.wisp_segment_factor > 0,
          "segment factors must be positive");
  require(p.mass_per_length_kg_m > 0, "mass_per_length_kg_m must be positive");
  require(p.body_voxel_h > 0 && p.body_clearance_h >= 0, "body field spacing must be positive");
  require(p.density_cell_h > 0, "density_cell_h must be positive");
  require(p.repulsion_interval_frames >= 1, "repulsion_interval_frames must be at least 1");
}

/// One simulated strand during the run.
struct RunningStrand {
  AltitudeStrand model;
  StrandState state;
  std::vector<StrandAnchor> anchors;    ///< wisp centres
  std::vector<Vec3> anchor_rest_m;      ///< the anchors at rest
  std::vector<Vec3> acceleration_m_s2;  ///< repulsion, per particle
  size_t first_output_point = 0;        ///< of this strand's hair particles in a frame
  std::vector<Vec3> frame_start_m;      ///< positions at the start of the frame
  double penetration_m = 0;             ///< deepest in this frame
  bool failed = false;
};

}  // namespace

Vec3 head_pivot(const Points3f& body_vertices, double head_height_m) {
  if (body_vertices.rows() == 0) return Vec3::Zero();
  double top = body_vertices.col(1).maxCoeff();
  Vec3 sum = Vec3::Zero();
  int64_t count = 0;
  for (Eigen::Index v = 0; v < body_vertices.rows(); ++v) {
    if (body_vertices(v, 1) < top - head_height_m) continue;
    sum += body_vertices.row(v).cast<double>().transpose();
    ++count;
  }
  Vec3 centre = sum / static_cast<double>(count);
  return Vec3(centre.x(), top - head_height_m, centre.z());
}

SimulationResult simulate_hair(const SimulationScene& scene, const HeadMotion& motion,
                               const SimulationParams& params) {
  check_params(params);
  check_strand_set(scene.strands, 1);  // names a strand with a non-finite point
  auto setup_start = std::chrono::steady_clock::now();
  const double h = scene.head_height_m;
  const StrandSet& strands = scene.strands;
  SimulationResult result;
  result.fps = params.fps;
  const auto& point_cluster =
      std::get<std::vector<int32_t>>(strands.point_attributes.at("cluster"));

  // The style each cluster is simulated by: its own, or normal with the style rules off.
  result.simulated_style = scene.cluster_style;
  if (!params.by_style)
    for (int8_t& style : result.simulated_style)
      if (style >= 0) style = static_cast<int8_t>(HairStyle::normal);

  // The body's signed distance field over the hair to simulate at rest (with a margin
  // for its swing), built only when there is some.
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (int64_t row = 0; row < strands.point_count(); ++row) {
    int8_t style =
        result.simulated_style[static_cast<size_t>(point_cluster[static_cast<size_t>(row)])];
    if (style < 0 || style == static_cast<int8_t>(HairStyle::fixed)) continue;
    low = low.cwiseMin(point_of(strands.points, row));
    high = high.cwiseMax(point_of(strands.points, row));
  }
  std::optional<BodySdf> body;
  const double clearance_m = params.body_clearance_h * h;
  if (low.x() <= high.x()) {
    Vec3 margin = Vec3::Constant(0.25 * h);
    body.emplace(scene.body_vertices, scene.body_triangles, low - margin, high + margin,
                 params.body_voxel_h * h, params.body_band_h * h, scene.source);
  }

  // The plan, and each braided cluster's centre strand; a braided cluster whose centre
  // strand cannot be had is simulated as normal hair.
  result.plan = plan_guides(strands, result.simulated_style, params.guide_count);
  std::map<int32_t, std::vector<Vec3>> centres;
  std::vector<GuideStrand> loose;  // braided clusters' strands outside their bundles
  auto gather_all = [&](bool say) {
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
  };
  if (gather_all(true)) {  // again without the clusters that are not braids
    result.plan = plan_guides(strands, result.simulated_style, params.guide_count);
    gather_all(false);
  }
  for (int64_t s = 0; s < strands.strand_count(); ++s) {
    int8_t style = result.simulated_style[static_cast<size_t>(
        point_cluster[static_cast<size_t>(strands.offsets[static_cast<size_t>(s)])])];
    if (style == static_cast<int8_t>(HairStyle::fixed)) ++result.fixed_strands;
  }

  // Guides for the strands outside the bundles, in proportion, as plan_guides gives them.
  if (!loose.empty()) {
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
          1, std::llround(static_cast<double>(params.guide_count) *
                          static_cast<double>(members.size()) / static_cast<double>(candidates)));
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

  // The guides' strands.
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
    RunningStrand strand;
    strand.model = build_altitude_strand(simulated.rest_m, params.mass_per_length_kg_m);
    simulated.ghost_count = strand.model.ghost_count();
    result.guides.push_back(std::move(simulated));
    running.push_back(std::move(strand));
  }

  // The wisps: a centre strand hung from its members' anchors; their points bound to it.
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
    strand.model = build_altitude_strand(centre, params.mass_per_length_kg_m * count);
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

    // Bind every point of the members from the braid on to the nearest tetrahedron.
    auto wisp_index = static_cast<int32_t>(result.wisp_guide.size());
    result.wisp_guide.push_back(static_cast<int32_t>(result.guides.size()));
    if (result.wisp_tetrahedron_offset.empty()) result.wisp_tetrahedron_offset.push_back(0);
    const auto& rest = strand.model.rest_m;
    std::vector<Vec3> centroid;
    std::vector<Eigen::Matrix3d> frame;
    for (const ChainTetrahedron& t : strand.model.tetrahedra) {
      Vec3 sum = Vec3::Zero();
      for (int32_t q : t.particle) sum += rest[static_cast<size_t>(q)];
      centroid.push_back(sum / 4);
      frame.push_back(tetrahedron_frame(rest[static_cast<size_t>(t.particle[0])],
                                        rest[static_cast<size_t>(t.particle[1])],
                                        rest[static_cast<size_t>(t.particle[2])]));
    }
    if (centroid.empty())  // gather_wisp() gives three centre points at least
      throw Error::runtime(scene.source, "the wisp of braided cluster " +
                                             std::to_string(wisp.cluster) + " has no tetrahedron");
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
        const Vec3& origin =
            rest[static_cast<size_t>(strand.model.tetrahedra[nearest].particle[0])];
        binding.local_m = (frame[nearest].transpose() * (p - origin)).cast<float>();
        result.wisp_bindings.push_back(binding);
      }
      ++result.braided_strands;
    }
    result.guides.push_back(std::move(simulated));
    running.push_back(std::move(strand));
  }
  if (result.wisp_tetrahedron_offset.empty()) result.wisp_tetrahedron_offset.push_back(0);

  size_t hair_points = 0;
  for (size_t g = 0; g < running.size(); ++g) {
    running[g].first_output_point = hair_points;
    hair_points += result.guides[g].rest_m.size();
  }
  HairDensityField density(params.density_cell_h * h);
  std::vector<Vec3> hair_positions;
  auto gather_hair = [&] {
    hair_positions.clear();
    for (const RunningStrand& strand : running)
      for (int32_t q : strand.model.hair_particle)
        hair_positions.push_back(strand.state.position_m[static_cast<size_t>(q)]);
  };

  // Frames and time.
  double duration_s = params.duration_s > 0 ? params.duration_s : motion.natural_duration_s();
  result.frame_count = std::max(1, static_cast<int32_t>(std::lround(duration_s * params.fps)) + 1);
  const double dt_s = 1.0 / (params.fps * params.substeps);
  const Vec3 gravity(0, -params.gravity_m_s2, 0);
  int32_t tetrahedra = result.wisp_tetrahedron_offset.back();
  result.guide_points_m.assign(static_cast<size_t>(result.frame_count) * hair_points * 3, 0.0f);
  result.wisp_frames.assign(
      static_cast<size_t>(result.frame_count) * static_cast<size_t>(tetrahedra) * 7, 0.0f);

  // Start: the rest shape where the head is at time 0, at rest.
  RigidTransform head = motion.at(0);
  for (RunningStrand& strand : running) {
    for (const Vec3& p : strand.model.rest_m) strand.state.position_m.push_back(head.apply(p));
    strand.state.velocity_m_s.assign(strand.model.rest_m.size(), Vec3::Zero());
    strand.acceleration_m_s2.assign(strand.model.rest_m.size(), Vec3::Zero());
    for (size_t a = 0; a < strand.anchors.size(); ++a)  // for frame 0's elastic energy
      strand.anchors[a].position_m = head.apply(strand.anchor_rest_m[a]);
  }
  // The rest state's density, in the head's frame: repulsion pushes only where the hair
  // is denser than it was at rest, by more than the mean density of an occupied cell
  // (the head is empty at rest, and would draw hair in).
  std::vector<Vec3> rest_positions;
  for (const RunningStrand& strand : running)
    for (int32_t q : strand.model.hair_particle)
      rest_positions.push_back(strand.model.rest_m[static_cast<size_t>(q)]);
  HairDensityField rest_density(params.density_cell_h * h);
  rest_density.build(rest_positions);
  const double reference_density = rest_density.mean_occupied_density();
  // Repulsion on hair particle i of `strand`, from the other strands' hair.
  auto repulsion = [&](const RunningStrand& strand, int32_t i, const RigidTransform& pose) -> Vec3 {
    if (!(reference_density > 0)) return Vec3::Zero();
    const AltitudeStrand& model = strand.model;
    // The excess cannot pass the dead band where the density, own splats included, is
    // under it: most particles stop here.
    const Vec3& here =
        strand.state.position_m[static_cast<size_t>(model.hair_particle[static_cast<size_t>(i)])];
    if (!(density.density(here) > reference_density)) return Vec3::Zero();
    std::array<Vec3, 3> own, own_rest;
    size_t count = 0;
    for (int32_t j = std::max(0, i - 1); j <= std::min(model.hair_count() - 1, i + 1); ++j) {
      auto q = static_cast<size_t>(model.hair_particle[static_cast<size_t>(j)]);
      own[count] = strand.state.position_m[q];
      own_rest[count++] = model.rest_m[q];
    }
    std::span<const Vec3> mine(own.data(), count), mine_at_rest(own_rest.data(), count);
    const Vec3& position_m = own[static_cast<size_t>(i - std::max(0, i - 1))];
    // Each field's density and gradient in one pass: the gradients are wanted for about
    // half the particles that get this far, and cost little beside the densities.
    const HairDensityField::SampleWithout now = density.sample_without(position_m, mine);
    const HairDensityField::SampleWithout at_rest =
        rest_density.sample_without(pose.apply_inverse(position_m), mine_at_rest);
    double excess = now.density - at_rest.density;
    // A dead band of one typical cell's worth of hair, so that hair that has merely
    // sagged a little is left alone, and the force faded in over the next.
    if (!(excess > reference_density)) return Vec3::Zero();
    Vec3 gradient = now.gradient_per_cell - pose.rotate(at_rest.gradient_per_cell);
    double fade = std::min(1.0, excess / reference_density - 1);
    return -params.repulsion_m_s2 * fade * gradient / reference_density;
  };

  auto record_frame = [&](int32_t frame, const RigidTransform& pose) {
    result.head.push_back(pose);
    size_t base = static_cast<size_t>(frame) * hair_points * 3;
    for (const RunningStrand& strand : running) {
      size_t row = strand.first_output_point;
      for (int32_t q : strand.model.hair_particle) {
        const Vec3& p = strand.state.position_m[static_cast<size_t>(q)];
        for (int axis = 0; axis < 3; ++axis)
          result.guide_points_m[base + 3 * row + static_cast<size_t>(axis)] =
              static_cast<float>(p[axis]);
        ++row;
      }
    }
    size_t tet_base = static_cast<size_t>(frame) * static_cast<size_t>(tetrahedra) * 7;
    for (size_t w = 0; w < result.wisp_guide.size(); ++w) {
      const RunningStrand& strand = running[static_cast<size_t>(result.wisp_guide[w])];
      const auto& x = strand.state.position_m;
      for (size_t t = 0; t < strand.model.tetrahedra.size(); ++t) {
        const auto& corner = strand.model.tetrahedra[t].particle;
        Eigen::Matrix3d frame_axes =
            tetrahedron_frame(x[static_cast<size_t>(corner[0])], x[static_cast<size_t>(corner[1])],
                              x[static_cast<size_t>(corner[2])]);
        Eigen::Quaterniond rotation(frame_axes);
        rotation.normalize();
        const Vec3& origin = x[static_cast<size_t>(corner[0])];
        size_t at = tet_base + 7 * (static_cast<size_t>(result.wisp_tetrahedron_offset[w]) + t);
        float values[7] = {static_cast<float>(origin.x()),   static_cast<float>(origin.y()),
                           static_cast<float>(origin.z()),   static_cast<float>(rotation.w()),
                           static_cast<float>(rotation.x()), static_cast<float>(rotation.y()),
                           static_cast<float>(rotation.z())};
        std::copy(values, values + 7, result.wisp_frames.begin() + static_cast<std::ptrdiff_t>(at));
      }
    }
  };
  // Each strand's share of a frame's statistics, in parallel; summed in strand order, so
  // the sums do not depend on the thread count.
  // The elastic energy's share of a strand's springs (anchors excluded) is what the next
  // frame's first step evaluates its springs at, so it is read off that step
  // (StrandStepper::start_spring_energy_j(), bit for bit) rather than evaluated here
  // again: the frame's statistics leave it pending until then, or work it out at once
  // where no step follows (the last frame, a settled head).
  struct StrandShare {
    double kinetic_j = 0, gravity_j = 0, anchor_j = 0, max_speed_m_s = 0, strain = 0,
           penetration_m = 0;
    int64_t inside = 0, hair = 0;
  };
  std::vector<StrandShare> shares(running.size());
  std::vector<double> spring_j(running.size());
  // The frame whose statistics wait for their springs' energy (shares[g].anchor_j kept
  // for it), or -1.
  int32_t pending_energy_frame = -1;
  auto settle_pending_energy = [&] {
    if (pending_energy_frame < 0) return;
    double elastic_j = 0;
    for (size_t g = 0; g < running.size(); ++g) elastic_j += spring_j[g] + shares[g].anchor_j;
    result.statistics[static_cast<size_t>(pending_energy_frame)].elastic_energy_j = elastic_j;
    pending_energy_frame = -1;
  };
  // At the present positions, for a frame no step follows.
  auto spring_energy_now = [&] {
    if (pending_energy_frame < 0) return;
#pragma omp parallel for schedule(dynamic, 4) if (running.size() >= 32)
    for (size_t g = 0; g < running.size(); ++g)
      spring_j[g] =
          strand_spring_energy(running[g].model, params.material, running[g].state.position_m);
    settle_pending_energy();
  };
  auto frame_statistics = [&](double time_s, const RigidTransform& pose) {
#pragma omp parallel for schedule(dynamic, 4) if (running.size() >= 32)
    for (size_t g = 0; g < running.size(); ++g) {
      RunningStrand& strand = running[g];
      StrandShare share;
      const auto& x = strand.state.position_m;
      const auto& v = strand.state.velocity_m_s;
      for (size_t k = 0; k < x.size(); ++k)
        share.kinetic_j += 0.5 * strand.model.mass_kg[k] * v[k].squaredNorm();
      for (int32_t q : strand.model.hair_particle) {
        auto k = static_cast<size_t>(q);
        share.gravity_j += strand.model.mass_kg[k] * params.gravity_m_s2 *
                           (x[k].y() - pose.apply(strand.model.rest_m[k]).y());
        if (!strand.frame_start_m.empty())
          share.max_speed_m_s =
              std::max(share.max_speed_m_s, (x[k] - strand.frame_start_m[k]).norm() * params.fps);
      }
      share.anchor_j = anchor_elastic_energy(strand.model, params.material, x, strand.anchors);
      share.strain = std::abs(max_hair_strain(strand.model, x));
      share.penetration_m = strand.penetration_m;
      strand.penetration_m = 0;
      if (body) {
        for (int32_t q : strand.model.hair_particle) {
          ++share.hair;
          Vec3 rest = pose.apply_inverse(x[static_cast<size_t>(q)]);
          if (!body->certainly_farther_than(rest, 0.0) && body->distance(rest) < 0) ++share.inside;
        }
      }
      shares[g] = share;
    }
    FrameStatistics stats;
    stats.time_s = time_s;
    int64_t inside = 0, hair_total = 0;
    for (const StrandShare& share : shares) {
      stats.kinetic_energy_j += share.kinetic_j;
      stats.gravity_energy_j += share.gravity_j;
      stats.max_speed_m_s = std::max(stats.max_speed_m_s, share.max_speed_m_s);
      stats.max_stretch = std::max(stats.max_stretch, share.strain);
      stats.max_penetration_m = std::max(stats.max_penetration_m, share.penetration_m);
      inside += share.inside;
      hair_total += share.hair;
    }
    stats.inside_fraction =
        hair_total ? static_cast<double>(inside) / static_cast<double>(hair_total) : 0.0;
    return stats;
  };

  record_frame(0, head);
  result.statistics.push_back(frame_statistics(0, head));
  pending_energy_frame = 0;
  result.setup_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - setup_start).count();
  spdlog::info(
      "{}: {} guides ({} ghost particles), {} wisps, {} frames of {} steps of {:.2f} ms",
      scene.source, result.guides.size(),
      [&] {
        int64_t ghosts = 0;
        for (const auto& g : result.guides) ghosts += g.ghost_count;
        return ghosts;
      }(),
      result.wisp_guide.size(), result.frame_count, params.substeps, dt_s * 1e3);

  auto simulation_start = std::chrono::steady_clock::now();
  std::vector<StrandStepper> steppers(static_cast<size_t>(omp_get_max_threads()));
  const bool still = motion.is_still();
  int quiet_frames = 0;
  RigidTransform previous = head;
  for (int32_t frame = 1; frame < result.frame_count; ++frame) {
    RigidTransform pose = motion.at(frame / params.fps);
    if (result.settled_at_frame >= 0) {
      record_frame(frame, pose);
      FrameStatistics stats = result.statistics.back();
      stats.time_s = frame / params.fps;
      stats.integrated = false;
      result.statistics.push_back(stats);
      continue;
    }
    for (RunningStrand& strand : running) strand.frame_start_m = strand.state.position_m;
    for (int step = 0; step < params.substeps; ++step) {
      double t1 = (frame - 1) / params.fps + (step + 1) * dt_s;
      RigidTransform next = step + 1 == params.substeps ? pose : motion.at(t1);
      // Hair-hair repulsion from the density at the start of the frame, every
      // repulsion_interval_frames frames (from frame 1), held in between.
      const bool repel = params.repulsion_m_s2 > 0 && step == 0 &&
                         (frame - 1) % params.repulsion_interval_frames == 0;
      if (repel) {
        gather_hair();
        density.build(hair_positions);
      }
      // A few guides are not worth a thread team's barrier per step (on a busy machine a
      // barrier can wait out another process's time slice).
#pragma omp parallel for schedule(dynamic, 4) if (running.size() >= 32)
      for (size_t g = 0; g < running.size(); ++g) {
        RunningStrand& strand = running[g];
        auto& x = strand.state.position_m;
        auto& v = strand.state.velocity_m_s;
        const AltitudeStrand& model = strand.model;
        try {
          for (int32_t q = 0; q < model.kinematic_count; ++q) {
            auto k = static_cast<size_t>(q);
            v[k] = (next.apply(model.rest_m[k]) - x[k]) / dt_s;
          }
          for (size_t a = 0; a < strand.anchors.size(); ++a) {
            Vec3 from = previous.apply(strand.anchor_rest_m[a]);
            strand.anchors[a].position_m = from;
            strand.anchors[a].velocity_m_s = (next.apply(strand.anchor_rest_m[a]) - from) / dt_s;
          }
          if (repel) {
            for (int32_t i = 0; i < model.hair_count(); ++i)
              strand.acceleration_m_s2[static_cast<size_t>(
                  model.hair_particle[static_cast<size_t>(i)])] = repulsion(strand, i, previous);
          }
          BodyCollider collider(*body, previous, next, clearance_m, dt_s);
          StrandStepper& stepper = steppers[static_cast<size_t>(omp_get_thread_num())];
          stepper.step(model, params.material, strand.acceleration_m_s2, gravity, strand.anchors,
                       dt_s, strand.state, params.body_collisions ? &collider : nullptr,
                       params.friction);
          if (step == 0) spring_j[g] = stepper.start_spring_energy_j();
          strand.penetration_m = std::max(strand.penetration_m, collider.deepest_m());
          for (int32_t q = 0; q < model.kinematic_count; ++q) {
            auto k = static_cast<size_t>(q);
            x[k] = next.apply(model.rest_m[k]);
          }
          // Not finite, or diverged so far that it soon will be.
          const Vec3 centre = next.translation_m;
          for (size_t k = 0; k < x.size(); ++k)
            if (!x[k].allFinite() || !v[k].allFinite() || (x[k] - centre).norm() > 1000 * h)
              strand.failed = true;
        } catch (const std::exception&) {
          strand.failed = true;
        }
      }
      for (size_t g = 0; g < running.size(); ++g) {
        if (running[g].failed)
          throw Error::runtime(
              scene.source,
              "simulation: frame " + std::to_string(frame) + ", guide " + std::to_string(g) +
                  ": a position or velocity is not finite (or diverged beyond 1000 H)");
      }
      if (step == 0) settle_pending_energy();
      previous = next;
    }
    // The anchors where the frame's statistics measure their springs: at its end.
    for (RunningStrand& strand : running)
      for (size_t a = 0; a < strand.anchors.size(); ++a)
        strand.anchors[a].position_m = pose.apply(strand.anchor_rest_m[a]);
    record_frame(frame, pose);
    FrameStatistics stats = frame_statistics(frame / params.fps, pose);
    result.statistics.push_back(stats);
    pending_energy_frame = frame;
    if (still) {
      quiet_frames = stats.max_speed_m_s < params.settle_speed_h_s * h ? quiet_frames + 1 : 0;
      if (quiet_frames >= params.settle_frames) {
        result.settled_at_frame = frame + 1;
        spring_energy_now();  // before the frames that repeat this one copy its statistics
        spdlog::info(
            "{}: the head is still and the hair settled at frame {}; the remaining {} "
            "frames repeat it",
            scene.source, frame, result.frame_count - frame - 1);
      }
    }
  }
  spring_energy_now();
  if (result.settled_at_frame >= result.frame_count) result.settled_at_frame = -1;
  result.simulation_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - simulation_start).count();
  return result;
}

}  // namespace hair
