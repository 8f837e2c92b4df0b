#include "hair/sim/simulation_loop.h"

#include <omp.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <string>

#include "hair/core/error.h"
#include "hair/sim/body_collider.h"

namespace hair {

using Vec3 = Eigen::Vector3d;

SimulationLoop::SimulationLoop(const SimulationScene& scene, const HeadMotion& motion,
                               const SimulationParams& params, const std::optional<BodySdf>& body,
                               std::vector<RunningStrand> running, SimulationResult& result)
    : scene_(scene),
      motion_(motion),
      params_(params),
      body_(body),
      result_(result),
      running_(std::move(running)),
      h_(scene.head_height_m),
      clearance_m_(params.body_clearance_h * scene.head_height_m),
      dt_s_(1.0 / (params.fps * params.substeps)),
      gravity_(0, -params.gravity_m_s2, 0),
      density_(params.density_cell_h * scene.head_height_m),
      rest_density_(params.density_cell_h * scene.head_height_m),
      steppers_(static_cast<size_t>(omp_get_max_threads())),
      cohesion_(result.guides, running_, params.bundle_cohesion_per_s2,
                params.bundle_damping_ratio),
      shares_(running_.size()),
      spring_j_(running_.size()) {
  for (StrandStepper& stepper : steppers_) stepper.time_phases(params.profile_phases);
  if (cohesion_.active())
    spdlog::info("{}: {} tails hold together ({} guides, and {} of other clusters hanging in them)",
                 scene.source, cohesion_.bundle_count(), cohesion_.guide_count(),
                 cohesion_.follower_count());
}

void SimulationLoop::start() {
  for (size_t g = 0; g < running_.size(); ++g) {
    running_[g].first_output_point = hair_points_;
    hair_points_ += result_.guides[g].rest_m.size();
  }

  // Frames and time.
  double duration_s = params_.duration_s > 0 ? params_.duration_s : motion_.natural_duration_s();
  result_.frame_count =
      std::max(1, static_cast<int32_t>(std::lround(duration_s * params_.fps)) + 1);
  tetrahedra_ = result_.wisp_tetrahedron_offset.back();
  result_.guide_points_m.assign(static_cast<size_t>(result_.frame_count) * hair_points_ * 3, 0.0f);
  result_.wisp_frames.assign(
      static_cast<size_t>(result_.frame_count) * static_cast<size_t>(tetrahedra_) * 7, 0.0f);

  applied_m_s2_.assign(running_.size(), {});

  // Start: the rest shape where the head is at time 0, at rest.
  RigidTransform head = motion_.at(0);
  for (RunningStrand& strand : running_) {
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
  for (const RunningStrand& strand : running_)
    for (int32_t q : strand.model.hair_particle)
      rest_positions.push_back(strand.model.rest_m[static_cast<size_t>(q)]);
  rest_density_.build(rest_positions);
  if (cohesion_.active()) cohesion_.sample_all(running_);  // the first step's centre lines
  reference_density_ = rest_density_.mean_occupied_density();

  record_frame(0, head);
  result_.statistics.push_back(frame_statistics(0, head));
  pending_energy_frame_ = 0;
  previous_ = head;
}

void SimulationLoop::run() {
  {
    PhaseTimer timer(&profile_.loop_s);
    run_frames();
  }
  result_.profile = profile_;
  for (StrandStepper& stepper : steppers_) result_.profile += stepper.profile();
}

void SimulationLoop::run_frames() {
  const bool still = motion_.is_still();
  int quiet_frames = 0;
  for (int32_t frame = 1; frame < result_.frame_count; ++frame) {
    RigidTransform pose = motion_.at(frame / params_.fps);
    if (result_.settled_at_frame >= 0) {
      PhaseTimer timer(serial_phase(&SimulationProfile::frames_s));
      record_frame(frame, pose);
      FrameStatistics stats = result_.statistics.back();
      stats.time_s = frame / params_.fps;
      stats.integrated = false;
      result_.statistics.push_back(stats);
      continue;
    }
    integrate_frame(frame, pose);
    FrameStatistics stats;
    {
      PhaseTimer timer(serial_phase(&SimulationProfile::frames_s));
      record_frame(frame, pose);
      stats = frame_statistics(frame / params_.fps, pose);
      result_.statistics.push_back(stats);
    }
    pending_energy_frame_ = frame;
    if (still) {
      quiet_frames = stats.max_speed_m_s < params_.settle_speed_h_s * h_ ? quiet_frames + 1 : 0;
      if (quiet_frames >= params_.settle_frames) {
        result_.settled_at_frame = frame + 1;
        spring_energy_now();  // before the frames that repeat this one copy its statistics
        spdlog::info(
            "{}: the head is still and the hair settled at frame {}; the remaining {} "
            "frames repeat it",
            scene_.source, frame, result_.frame_count - frame - 1);
      }
    }
  }
  spring_energy_now();
  if (result_.settled_at_frame >= result_.frame_count) result_.settled_at_frame = -1;
}

void SimulationLoop::integrate_frame(int32_t frame, const RigidTransform& pose) {
  for (RunningStrand& strand : running_) strand.frame_start_m = strand.state.position_m;
  for (int step = 0; step < params_.substeps; ++step) {
    double t1 = (frame - 1) / params_.fps + (step + 1) * dt_s_;
    RigidTransform next = step + 1 == params_.substeps ? pose : motion_.at(t1);
    // Hair-hair repulsion from the density at the start of the frame, every
    // repulsion_interval_frames frames (from frame 1), held in between.
    const bool repel = params_.repulsion_m_s2 > 0 && step == 0 &&
                       (frame - 1) % params_.repulsion_interval_frames == 0;
    if (repel) {
      PhaseTimer timer(serial_phase(&SimulationProfile::hair_hair_s));
      gather_hair();
      density_.build(hair_positions_);
    }
    // The tails' cohesion from the positions at the start of each step (explicit, its
    // stiffness held to 1 / dt^2 so that a long step stays stable): the centre lines of
    // the members' polylines, which each strand sampled at the end of its last step.
    if (cohesion_.active()) {
      PhaseTimer timer(serial_phase(&SimulationProfile::bundles_s));
      cohesion_.update_centres();
    }
    // A few guides are not worth a thread team's barrier per step (on a busy machine a
    // barrier can wait out another process's time slice).
#pragma omp parallel for schedule(dynamic, 4) if (running_.size() >= 32)
    for (size_t g = 0; g < running_.size(); ++g) step_strand(g, step, repel, previous_, next);
    for (size_t g = 0; g < running_.size(); ++g) {
      if (running_[g].failed)
        throw Error::runtime(
            scene_.source,
            "simulation: frame " + std::to_string(frame) + ", guide " + std::to_string(g) +
                ": a position or velocity is not finite (or diverged beyond 1000 H)");
    }
    if (step == 0) settle_pending_energy();
    previous_ = next;
  }
  // The anchors where the frame's statistics measure their springs: at its end.
  for (RunningStrand& strand : running_)
    for (size_t a = 0; a < strand.anchors.size(); ++a)
      strand.anchors[a].position_m = pose.apply(strand.anchor_rest_m[a]);
}

void SimulationLoop::step_strand(size_t g, int step, bool repel, const RigidTransform& from,
                                 const RigidTransform& to) {
  RunningStrand& strand = running_[g];
  auto& x = strand.state.position_m;
  auto& v = strand.state.velocity_m_s;
  const AltitudeStrand& model = strand.model;
  try {
    for (int32_t q = 0; q < model.kinematic_count; ++q) {
      auto k = static_cast<size_t>(q);
      v[k] = (to.apply(model.rest_m[k]) - x[k]) / dt_s_;
    }
    for (size_t a = 0; a < strand.anchors.size(); ++a) {
      Vec3 start = from.apply(strand.anchor_rest_m[a]);
      strand.anchors[a].position_m = start;
      strand.anchors[a].velocity_m_s = (to.apply(strand.anchor_rest_m[a]) - start) / dt_s_;
    }
    StrandStepper& stepper = steppers_[static_cast<size_t>(omp_get_thread_num())];
    if (repel) {
      PhaseTimer timer(stepper.phase(&SimulationProfile::hair_hair_s));
      for (int32_t i = 0; i < model.hair_count(); ++i)
        strand.acceleration_m_s2[static_cast<size_t>(model.hair_particle[static_cast<size_t>(i)])] =
            repulsion(strand, i, from);
    }
    BodyCollider collider(*body_, from, to, clearance_m_, dt_s_);
    const Eigen::Matrix3d head_rotation = to.rotation.toRotationMatrix();
    const std::vector<Vec3>* acceleration = &strand.acceleration_m_s2;
    if (cohesion_.active() && cohesion_.member(g)) {
      PhaseTimer timer(stepper.phase(&SimulationProfile::bundles_s));
      std::vector<Vec3>& applied = applied_m_s2_[g];
      cohesion_.acceleration(g, running_, dt_s_, applied);
      for (size_t k = 0; k < applied.size(); ++k) applied[k] += strand.acceleration_m_s2[k];
      acceleration = &applied;
    }
    stepper.step(model, params_.material, *acceleration, gravity_, strand.anchors, dt_s_,
                 strand.state, params_.body_collisions ? &collider : nullptr, params_.friction,
                 &head_rotation);
    if (step == 0) spring_j_[g] = stepper.start_spring_energy_j();
    strand.penetration_m = std::max(strand.penetration_m, collider.deepest_m());
    for (int32_t q = 0; q < model.kinematic_count; ++q) {
      auto k = static_cast<size_t>(q);
      x[k] = to.apply(model.rest_m[k]);
    }
    if (cohesion_.active()) {  // for the next step's centre
      PhaseTimer timer(stepper.phase(&SimulationProfile::bundles_s));
      cohesion_.sample(g, running_);
    }
    // Not finite, or diverged so far that it soon will be.
    const Vec3 centre = to.translation_m;
    for (size_t k = 0; k < x.size(); ++k)
      if (!x[k].allFinite() || !v[k].allFinite() || (x[k] - centre).norm() > 1000 * h_)
        strand.failed = true;
  } catch (const std::exception&) {
    strand.failed = true;
  }
}

Vec3 SimulationLoop::repulsion(const RunningStrand& strand, int32_t i,
                               const RigidTransform& pose) const {
  if (!(reference_density_ > 0)) return Vec3::Zero();
  const AltitudeStrand& model = strand.model;
  // The excess cannot pass the dead band where the density, own splats included, is
  // under it: most particles stop here.
  const Vec3& here =
      strand.state.position_m[static_cast<size_t>(model.hair_particle[static_cast<size_t>(i)])];
  if (!(density_.density(here) > reference_density_)) return Vec3::Zero();
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
  const HairDensityField::SampleWithout now = density_.sample_without(position_m, mine);
  const HairDensityField::SampleWithout at_rest =
      rest_density_.sample_without(pose.apply_inverse(position_m), mine_at_rest);
  double excess = now.density - at_rest.density;
  // A dead band of one typical cell's worth of hair, so that hair that has merely
  // sagged a little is left alone, and the force faded in over the next.
  if (!(excess > reference_density_)) return Vec3::Zero();
  Vec3 gradient = now.gradient_per_cell - pose.rotate(at_rest.gradient_per_cell);
  double fade = std::min(1.0, excess / reference_density_ - 1);
  return -params_.repulsion_m_s2 * fade * gradient / reference_density_;
}

void SimulationLoop::gather_hair() {
  hair_positions_.clear();
  for (const RunningStrand& strand : running_)
    for (int32_t q : strand.model.hair_particle)
      hair_positions_.push_back(strand.state.position_m[static_cast<size_t>(q)]);
}

void SimulationLoop::record_frame(int32_t frame, const RigidTransform& pose) {
  result_.head.push_back(pose);
  size_t base = static_cast<size_t>(frame) * hair_points_ * 3;
  for (const RunningStrand& strand : running_) {
    size_t row = strand.first_output_point;
    for (int32_t q : strand.model.hair_particle) {
      const Vec3& p = strand.state.position_m[static_cast<size_t>(q)];
      for (int axis = 0; axis < 3; ++axis)
        result_.guide_points_m[base + 3 * row + static_cast<size_t>(axis)] =
            static_cast<float>(p[axis]);
      ++row;
    }
  }
  size_t tet_base = static_cast<size_t>(frame) * static_cast<size_t>(tetrahedra_) * 7;
  for (size_t w = 0; w < result_.wisp_guide.size(); ++w) {
    const RunningStrand& strand = running_[static_cast<size_t>(result_.wisp_guide[w])];
    const auto& x = strand.state.position_m;
    for (size_t t = 0; t < strand.model.tetrahedra.size(); ++t) {
      const auto& corner = strand.model.tetrahedra[t].particle;
      Eigen::Matrix3d frame_axes =
          tetrahedron_frame(x[static_cast<size_t>(corner[0])], x[static_cast<size_t>(corner[1])],
                            x[static_cast<size_t>(corner[2])]);
      Eigen::Quaterniond rotation(frame_axes);
      rotation.normalize();
      const Vec3& origin = x[static_cast<size_t>(corner[0])];
      size_t at = tet_base + 7 * (static_cast<size_t>(result_.wisp_tetrahedron_offset[w]) + t);
      float values[7] = {static_cast<float>(origin.x()),   static_cast<float>(origin.y()),
                         static_cast<float>(origin.z()),   static_cast<float>(rotation.w()),
                         static_cast<float>(rotation.x()), static_cast<float>(rotation.y()),
                         static_cast<float>(rotation.z())};
      std::copy(values, values + 7, result_.wisp_frames.begin() + static_cast<std::ptrdiff_t>(at));
    }
  }
}

FrameStatistics SimulationLoop::frame_statistics(double time_s, const RigidTransform& pose) {
#pragma omp parallel for schedule(dynamic, 4) if (running_.size() >= 32)
  for (size_t g = 0; g < running_.size(); ++g) {
    RunningStrand& strand = running_[g];
    StrandShare share;
    const auto& x = strand.state.position_m;
    const auto& v = strand.state.velocity_m_s;
    for (size_t k = 0; k < x.size(); ++k)
      share.kinetic_j += 0.5 * strand.model.mass_kg[k] * v[k].squaredNorm();
    for (int32_t q : strand.model.hair_particle) {
      auto k = static_cast<size_t>(q);
      share.gravity_j += strand.model.mass_kg[k] * params_.gravity_m_s2 *
                         (x[k].y() - pose.apply(strand.model.rest_m[k]).y());
      if (!strand.frame_start_m.empty())
        share.max_speed_m_s =
            std::max(share.max_speed_m_s, (x[k] - strand.frame_start_m[k]).norm() * params_.fps);
    }
    share.anchor_j = anchor_elastic_energy(strand.model, params_.material, x, strand.anchors);
    share.strain = std::abs(max_hair_strain(strand.model, x));
    share.penetration_m = strand.penetration_m;
    strand.penetration_m = 0;
    if (body_) {
      for (int32_t q : strand.model.hair_particle) {
        ++share.hair;
        Vec3 rest = pose.apply_inverse(x[static_cast<size_t>(q)]);
        if (!body_->certainly_farther_than(rest, 0.0) && body_->distance(rest) < 0) ++share.inside;
      }
    }
    shares_[g] = share;
  }
  FrameStatistics stats;
  stats.time_s = time_s;
  int64_t inside = 0, hair_total = 0;
  for (const StrandShare& share : shares_) {
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
}

void SimulationLoop::settle_pending_energy() {
  if (pending_energy_frame_ < 0) return;
  double elastic_j = 0;
  for (size_t g = 0; g < running_.size(); ++g) elastic_j += spring_j_[g] + shares_[g].anchor_j;
  result_.statistics[static_cast<size_t>(pending_energy_frame_)].elastic_energy_j = elastic_j;
  pending_energy_frame_ = -1;
}

void SimulationLoop::spring_energy_now() {
  if (pending_energy_frame_ < 0) return;
#pragma omp parallel for schedule(dynamic, 4) if (running_.size() >= 32)
  for (size_t g = 0; g < running_.size(); ++g)
    spring_j_[g] =
        strand_spring_energy(running_[g].model, params_.material, running_[g].state.position_m);
  settle_pending_energy();
}

}  // namespace hair
