// The style-specific simulation on a hand-made scene with known geometry: a sphere for a
// head, hair draped over it (normal), a ponytail that leaves a fixed cap, and a braid of
// three strands hanging from the cap.
#include <gtest/gtest.h>
#include <omp.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "hair/core/error.h"
#include "hair/sim/guide_selection.h"
#include "hair/sim/hair_simulation.h"
#include "unit/icosphere.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;

constexpr double kRadius = 0.1;  // the head, a sphere about the origin
constexpr double kHeadHeight = 0.2;
enum Cluster : int32_t { kCap = 0, kDraped = 1, kTail = 2, kBraid = 3 };

/// A point on the sphere (grown `out_m` off it) at polar angle `theta` from +Y and
/// azimuth `phi` about Y from +Z.
Vec3 on_sphere(double theta, double phi, double out_m) {
  return (kRadius + out_m) *
         Vec3(std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi));
}

struct StrandBuilder {
  StrandSet strands;
  std::vector<int32_t> point_cluster, strand_cluster;
  std::vector<Vec3> points;
  std::vector<int32_t> clusters;
  void add(const Vec3& p, int32_t cluster) {
    points.push_back(p);
    clusters.push_back(cluster);
  }
  void finish_strand() {
    Points3f block(static_cast<Eigen::Index>(points.size()), 3);
    for (size_t i = 0; i < points.size(); ++i)
      block.row(static_cast<Eigen::Index>(i)) = points[i].cast<float>().transpose();
    strands.append_strand(block);
    strand_cluster.push_back(clusters.front());
    point_cluster.insert(point_cluster.end(), clusters.begin(), clusters.end());
    points.clear();
    clusters.clear();
  }
};

/// The scene: six draped strands, four ponytail strands (cap then tail), three braided
/// strands (cap then a three-strand helix).
SimulationScene make_scene() {
  StrandBuilder b;
  const double step = 0.005;
  // Draped: from polar angle 0.5 over the sphere to its equator, then straight down.
  for (int i = 0; i < 6; ++i) {
    double phi = std::numbers::pi / 2 + (i - 2.5) * 0.25;  // around +X
    for (double theta = 0.5; theta <= std::numbers::pi / 2; theta += step / kRadius)
      b.add(on_sphere(theta, phi, 0.004), kDraped);
    Vec3 edge = on_sphere(std::numbers::pi / 2, phi, 0.004);
    for (double y = step; y <= 0.15; y += step) b.add(edge - Vec3(0, y, 0), kDraped);
    b.finish_strand();
  }
  // Ponytail: a cap from the crown over the back, then a tail hanging behind.
  for (int i = 0; i < 4; ++i) {
    double phi = std::numbers::pi + (i - 1.5) * 0.1;
    for (double theta = 0.2; theta <= 2.0; theta += step / kRadius)
      b.add(on_sphere(theta, phi, 0.004), kCap);
    Vec3 band = on_sphere(2.0, phi, 0.03);
    for (double y = 0; y <= 0.2; y += step) b.add(band - Vec3(0, y, 0), kTail);
    b.finish_strand();
  }
  // Braid: a cap on the left, then three strands twisted about a vertical axis.
  Vec3 axis_top = on_sphere(1.9, 1.5 * std::numbers::pi, 0.03);
  for (int i = 0; i < 3; ++i) {
    double phi = 1.5 * std::numbers::pi + (i - 1) * 0.1;
    for (double theta = 0.3; theta <= 1.8; theta += step / kRadius)
      b.add(on_sphere(theta, phi, 0.004), kCap);
    for (double y = 0; y <= 0.2; y += step) {
      double angle = 2 * std::numbers::pi * (i / 3.0 + y / 0.05);
      b.add(axis_top + Vec3(0.01 * std::cos(angle), -y, 0.01 * std::sin(angle)), kBraid);
    }
    b.finish_strand();
  }
  SimulationScene scene;
  scene.strands = std::move(b.strands);
  scene.strands.point_attributes["cluster"] = b.point_cluster;
  scene.strands.strand_attributes["cluster"] = b.strand_cluster;
  scene.cluster_style = {
      static_cast<int8_t>(HairStyle::fixed), static_cast<int8_t>(HairStyle::normal),
      static_cast<int8_t>(HairStyle::normal), static_cast<int8_t>(HairStyle::braided)};
  testing::SphereMesh sphere = testing::icosphere(4, kRadius);
  scene.body_vertices = sphere.vertices;
  scene.body_triangles = sphere.triangles;
  scene.head_height_m = kHeadHeight;
  scene.source = "scene";
  return scene;
}

const Vec3 kPivot(0, -kRadius, 0);

SimulationParams test_params() {
  SimulationParams params;
  params.guide_count = 6;
  params.duration_s = 1.0;
  return params;
}

Vec3 frame_point(const SimulationResult& result, int32_t frame, size_t row) {
  size_t points = result.guide_points_m.size() / 3 / static_cast<size_t>(result.frame_count);
  size_t at = 3 * (static_cast<size_t>(frame) * points + row);
  return Vec3(result.guide_points_m[at], result.guide_points_m[at + 1],
              result.guide_points_m[at + 2]);
}

TEST(GuidePlan, GuidesByShareOfCandidatesAndOneWispPerBraid) {
  SimulationScene scene = make_scene();
  GuidePlan plan = plan_guides(scene.strands, scene.cluster_style, 6);
  // 6 draped and 4 tail candidates: shares 3.6 and 2.4, so 4 and 2.
  EXPECT_EQ(plan.cluster_candidates[kDraped], 6);
  EXPECT_EQ(plan.cluster_candidates[kTail], 4);
  EXPECT_EQ(plan.cluster_guides[kDraped], 4);
  EXPECT_EQ(plan.cluster_guides[kTail], 2);
  EXPECT_EQ(plan.cluster_guides[kCap], 0);  // fixed: not simulated
  ASSERT_EQ(plan.guides.size(), 6u);
  const auto& point_cluster =
      std::get<std::vector<int32_t>>(scene.strands.point_attributes.at("cluster"));
  for (const GuideStrand& guide : plan.guides) {
    int64_t anchor = scene.strands.offsets[static_cast<size_t>(guide.strand)] + guide.anchor_point;
    if (guide.cluster == kDraped) {
      EXPECT_EQ(guide.anchor_point, 0);  // from the root
    } else {
      // A tail hangs from the last point of the fixed cap.
      EXPECT_EQ(point_cluster[static_cast<size_t>(anchor)], kCap);
      EXPECT_EQ(point_cluster[static_cast<size_t>(anchor) + 1], kTail);
    }
  }
  ASSERT_EQ(plan.wisps.size(), 1u);
  EXPECT_EQ(plan.wisps[0].cluster, kBraid);
  EXPECT_EQ(plan.wisps[0].member_strand.size(), 3u);
  EXPECT_EQ(plan.wisps[0].loose_anchor_count, 0);
}

TEST(GuidePlan, FarthestPointSamplingSpreadsOut) {
  // Points on a line: the middle first, then the two ends.
  std::vector<Vec3> points;
  for (int i = 0; i <= 10; ++i) points.emplace_back(i, 0, 0);
  std::vector<int64_t> taken = farthest_point_sample(points, 3);
  ASSERT_EQ(taken.size(), 3u);
  EXPECT_EQ(taken[0], 5);
  EXPECT_EQ(taken[1], 0);  // tie between 0 and 10: the lower index
  EXPECT_EQ(taken[2], 10);
  EXPECT_EQ(farthest_point_sample(points, 50).size(), points.size());
}

TEST(HairSimulation, AnchorsFollowTheHeadExactlyAndHairStaysOutsideTheBody) {
  SimulationScene scene = make_scene();
  HeadMotion motion = HeadMotion::preset("nod", kPivot);
  SimulationResult result = simulate_hair(scene, motion, test_params());
  ASSERT_EQ(result.frame_count, 31);
  ASSERT_EQ(result.guides.size(), 7u);  // 6 guides and the braid's wisp centre
  double deepest = -1, worst_stretch = 0;
  for (int32_t frame = 0; frame < result.frame_count; ++frame) {
    const RigidTransform& head = result.head[static_cast<size_t>(frame)];
    size_t row = 0;
    for (const SimulatedGuide& guide : result.guides) {
      if (guide.kind == GuideKind::strand) {  // the first particle is held by the head
        Vec3 expected = head.apply(guide.rest_m.front());
        EXPECT_LT((frame_point(result, frame, row) - expected).norm(), 1e-6) << frame;
      }
      for (size_t i = 0; i < guide.rest_m.size(); ++i) {
        Vec3 in_head = head.apply_inverse(frame_point(result, frame, row + i));
        deepest = std::max(deepest, kRadius - in_head.norm());
      }
      row += guide.rest_m.size();
    }
    worst_stretch =
        std::max(worst_stretch, result.statistics[static_cast<size_t>(frame)].max_stretch);
  }
  // The sphere's triangles lie up to 0.4 mm inside it; the field is within a voxel.
  EXPECT_LT(deepest, 0.0);  // every particle outside the sphere
  EXPECT_LT(worst_stretch, 0.05);
  // The nod moved the hair: the tails swung away from their rest in the head's frame.
  double largest_swing = 0;
  size_t row = 0;
  for (const SimulatedGuide& guide : result.guides) {
    for (size_t i = 0; i < guide.rest_m.size(); ++i) {
      Vec3 in_head = result.head[15].apply_inverse(frame_point(result, 15, row + i));
      largest_swing = std::max(largest_swing, (in_head - guide.rest_m[i]).norm());
    }
    row += guide.rest_m.size();
  }
  EXPECT_GT(largest_swing, 0.01);
}

TEST(HairSimulation, WispBindingsRebuildTheBraidAndFollowTheCentre) {
  SimulationScene scene = make_scene();
  SimulationResult result =
      simulate_hair(scene, HeadMotion::preset("shake", kPivot), test_params());
  ASSERT_EQ(result.wisp_guide.size(), 1u);
  const SimulatedGuide& centre = result.guides[static_cast<size_t>(result.wisp_guide[0])];
  EXPECT_EQ(centre.kind, GuideKind::wisp_centre);
  EXPECT_EQ(centre.mass_scale, 3);
  EXPECT_EQ(centre.anchor_count, 3);
  EXPECT_EQ(result.braided_strands, 3);
  int32_t tetrahedra = result.wisp_tetrahedron_offset.back();
  auto rebuilt = [&](int32_t frame, const WispBinding& binding) {
    size_t at =
        7 * (static_cast<size_t>(frame) * static_cast<size_t>(tetrahedra) +
             static_cast<size_t>(result.wisp_tetrahedron_offset[static_cast<size_t>(binding.wisp)] +
                                 binding.tetrahedron));
    const auto& f = result.wisp_frames;
    Vec3 origin(f[at], f[at + 1], f[at + 2]);
    Eigen::Quaterniond rotation(f[at + 3], f[at + 4], f[at + 5], f[at + 6]);
    return Vec3(origin + rotation * binding.local_m.cast<double>());
  };
  ASSERT_FALSE(result.wisp_bindings.empty());
  double worst_rest = 0, worst_later = 0;
  for (const WispBinding& binding : result.wisp_bindings) {
    Vec3 rest = scene.strands.points.row(binding.point).cast<double>().transpose();
    worst_rest = std::max(worst_rest, (rebuilt(0, binding) - rest).norm());
    // Later, a bound point stays as near the moving centre strand as it was at rest.
    auto nearest = [&](const Vec3& p, int32_t frame) {
      double best = 1e9;
      size_t row = 0;
      for (size_t g = 0; g < static_cast<size_t>(result.wisp_guide[0]); ++g)
        row += result.guides[g].rest_m.size();
      for (size_t i = 0; i < centre.rest_m.size(); ++i)
        best = std::min(best, (frame_point(result, frame, row + i) - p).norm());
      return best;
    };
    worst_later = std::max(worst_later, nearest(rebuilt(20, binding), 20) - nearest(rest, 0));
  }
  EXPECT_LT(worst_rest, 1e-5);
  EXPECT_LT(worst_later, 0.005);
}

TEST(HairSimulation, TwoRunsAndThreadCountsAgreeBitForBit) {
  SimulationScene scene = make_scene();
  HeadMotion motion = HeadMotion::preset("violent_shake", kPivot);
  SimulationParams params = test_params();
  params.duration_s = 0.5;
  int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  SimulationResult one = simulate_hair(scene, motion, params);
  omp_set_num_threads(std::max(2, threads));
  SimulationResult two = simulate_hair(scene, motion, params);
  omp_set_num_threads(threads);
  EXPECT_EQ(one.guide_points_m, two.guide_points_m);
  EXPECT_EQ(one.wisp_frames, two.wisp_frames);
}

TEST(HairSimulation, TheProfileCountsEveryParticleStepAndSplitsTheFramesTime) {
  SimulationScene scene = make_scene();
  HeadMotion motion = HeadMotion::preset("nod", kPivot);
  for (bool collisions : {true, false}) {
    SimulationParams params = test_params();
    params.body_collisions = collisions;
    params.profile_phases = true;
    SimulationResult result = simulate_hair(scene, motion, params);
    // Every guide (the wisp centre too) steps its hair and ghost particles every substep of
    // every integrated frame.
    int64_t particles = 0;
    for (const SimulatedGuide& guide : result.guides)
      particles += static_cast<int64_t>(guide.rest_m.size()) + guide.ghost_count;
    int64_t integrated = 0;
    for (const FrameStatistics& stats : result.statistics) integrated += stats.integrated;
    integrated -= 1;  // frame 0, the rest
    ASSERT_GT(integrated, 0);
    const SimulationProfile& profile = result.profile;
    EXPECT_EQ(profile.particle_steps, particles * params.substeps * integrated);
    // The phases happen inside the frames: on one thread their sum is within the loop's
    // wall time; on several, within the threads' time.
    const double phases = profile.springs_s + profile.solve_s + profile.limits_s +
                          profile.collisions_s + profile.hair_hair_s + profile.bundles_s +
                          profile.frames_s;
    EXPECT_GT(profile.loop_s, 0.0);
    EXPECT_LE(phases, profile.loop_s * omp_get_max_threads() * 1.001 + 1e-4);
    for (double seconds : {profile.springs_s, profile.solve_s, profile.limits_s,
                           profile.frames_s})
      EXPECT_GT(seconds, 0.0);
    EXPECT_EQ(profile.collisions_s > 0, collisions);
    EXPECT_NEAR(profile.ns_per_particle_step(),
                1e9 * profile.loop_s / static_cast<double>(profile.particle_steps), 1e-9);
    EXPECT_NE(profile.summary().find("ns per particle-step"), std::string::npos);
    // Not asked, the phases are not timed; the frames' time and the steps still are.
    params.profile_phases = false;
    const SimulationProfile untimed = simulate_hair(scene, motion, params).profile;
    EXPECT_EQ(untimed.particle_steps, profile.particle_steps);
    EXPECT_GT(untimed.loop_s, 0.0);
    EXPECT_EQ(untimed.springs_s + untimed.solve_s + untimed.limits_s + untimed.collisions_s +
                  untimed.hair_hair_s + untimed.bundles_s + untimed.frames_s,
              0.0);
    EXPECT_EQ(untimed.summary().rfind("phases not timed (profile_phases); ", 0), 0u)
        << untimed.summary();
  }
}

TEST(SimulationProfile, SharesOfThePhasesSum) {
  SimulationProfile profile;
  profile.springs_s = 3;
  profile.solve_s = 1;
  profile.loop_s = 2;
  profile.particle_steps = 1000;
  EXPECT_EQ(profile.summary(),
            "springs 75.0%, solve 25.0%, limits 0.0%, collisions 0.0%, hair-hair 0.0%, "
            "bundles 0.0%, frames 0.0%; 2000000.0 ns per particle-step");
  SimulationProfile twice = profile;
  twice += profile;
  EXPECT_EQ(twice.particle_steps, 2000);
  EXPECT_DOUBLE_EQ(twice.ns_per_particle_step(), profile.ns_per_particle_step());
  EXPECT_EQ(SimulationProfile{}.ns_per_particle_step(), 0.0);
}

TEST(HairSimulation, ElasticEnergyReadOffTheNextStepEqualsItWorkedOutAtTheEnd) {
  // A frame's elastic energy comes from the next frame's first step, or is worked out at
  // the frame's end when it is the last: a run cut short at frame 6 works out that frame's
  // directly, and must agree with the longer run, bit for bit (the braid's wisp centre
  // has anchors, the rest not).
  SimulationScene scene = make_scene();
  HeadMotion motion = HeadMotion::preset("violent_shake", kPivot);
  SimulationParams params = test_params();
  params.duration_s = 0.5;
  SimulationResult longer = simulate_hair(scene, motion, params);
  params.duration_s = 0.2;
  SimulationResult shorter = simulate_hair(scene, motion, params);
  ASSERT_EQ(shorter.frame_count, 7);
  for (size_t frame = 0; frame < 7; ++frame) {
    EXPECT_EQ(shorter.statistics[frame].elastic_energy_j, longer.statistics[frame].elastic_energy_j)
        << "frame " << frame;
    if (frame > 0) {
      EXPECT_GT(longer.statistics[frame].elastic_energy_j, 0) << "frame " << frame;
    }
  }
  EXPECT_GT(longer.statistics.back().elastic_energy_j, 0);
}

TEST(HairSimulation, RefusesARepulsionIntervalUnderOneFrame) {
  SimulationParams params = test_params();
  params.repulsion_interval_frames = 0;
  EXPECT_THROW(simulate_hair(make_scene(), HeadMotion::preset("nod", kPivot), params), Error);
}

TEST(HairSimulation, StillHeadSettlesAndStopsEarly) {
  SimulationScene scene = make_scene();
  SimulationParams params = test_params();
  params.duration_s = 10;
  SimulationResult result = simulate_hair(scene, HeadMotion::preset("still", kPivot), params);
  ASSERT_GT(result.settled_at_frame, 0);
  EXPECT_LT(result.settled_at_frame, result.frame_count);
  const auto& first_skipped = result.statistics[static_cast<size_t>(result.settled_at_frame)];
  EXPECT_FALSE(first_skipped.integrated);
  EXPECT_TRUE(result.statistics[static_cast<size_t>(result.settled_at_frame) - 1].integrated);
  // They repeat its statistics, its elastic energy too (worked out as it settled, with
  // no next step to read it off).
  const auto& last_integrated = result.statistics[static_cast<size_t>(result.settled_at_frame) - 1];
  EXPECT_GT(last_integrated.elastic_energy_j, 0);
  EXPECT_EQ(result.statistics.back().elastic_energy_j, last_integrated.elastic_energy_j);
  // Later frames repeat the last integrated one.
  size_t points = result.guide_points_m.size() / 3 / static_cast<size_t>(result.frame_count);
  for (size_t row = 0; row < points; ++row)
    EXPECT_EQ(frame_point(result, result.frame_count - 1, row),
              frame_point(result, result.settled_at_frame - 1, row));
}

TEST(HairSimulation, NonFiniteMotionAbortsNamingFrameAndGuide) {
  SimulationScene scene = make_scene();
  SimulationParams params = test_params();
  // The head thrown 1e308 m in a second: the roots' pull overflows to infinity in the
  // first step (the parameters themselves are held to their ranges).
  HeadKeyframe start, thrown;
  thrown.time_s = 1;
  thrown.offset_m = Eigen::Vector3d(1e308, 0, 0);
  try {
    simulate_hair(scene, HeadMotion::from_keyframes({start, thrown}, kPivot, "thrown"), params);
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::runtime);
    EXPECT_NE(std::string(error.what()).find("frame 1"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("guide 0"), std::string::npos) << error.what();
  }
}

TEST(HairSimulation, FixedHairIsNotSimulated) {
  SimulationScene scene = make_scene();
  for (int8_t& style : scene.cluster_style) style = static_cast<int8_t>(HairStyle::fixed);
  SimulationResult result = simulate_hair(scene, HeadMotion::preset("nod", kPivot), test_params());
  EXPECT_TRUE(result.guides.empty());
  EXPECT_EQ(result.fixed_strands, scene.strands.strand_count());
  EXPECT_EQ(result.frame_count, 31);  // the head's frames are still written
}

TEST(HairSimulation, WithTheStyleRulesOffEveryClusterIsNormalHair) {
  SimulationScene scene = make_scene();
  SimulationParams params = test_params();
  params.by_style = false;
  params.guide_count = static_cast<int>(scene.strands.strand_count());
  SimulationResult result = simulate_hair(scene, HeadMotion::preset("nod", kPivot), params);
  for (int8_t style : result.simulated_style)
    EXPECT_EQ(style, static_cast<int8_t>(HairStyle::normal));
  EXPECT_EQ(result.fixed_strands, 0);
  EXPECT_TRUE(result.plan.wisps.empty());
  EXPECT_EQ(static_cast<int64_t>(result.guides.size()), scene.strands.strand_count());
  for (const SimulatedGuide& guide : result.guides) EXPECT_EQ(guide.style, HairStyle::normal);
  // By style, the same scene has fixed hair and a wisp.
  params.by_style = true;
  SimulationResult by_style = simulate_hair(scene, HeadMotion::preset("nod", kPivot), params);
  EXPECT_GT(by_style.fixed_strands, 0);
  EXPECT_EQ(by_style.plan.wisps.size(), 1u);
}

}  // namespace
}  // namespace hair
