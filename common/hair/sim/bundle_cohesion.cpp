#include "hair/sim/bundle_cohesion.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "hair/geom/polyline.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;

/// A cluster's guides are a bundle where somewhere along their middle they are at most
/// this share as spread as at their roots.
constexpr double kGatheredSpreadRatio = 0.6;

/// Or where they pass, each somewhere along its length, this close to one point (their
/// waist) against their spread at the roots: strands of different lengths drawn through
/// one band (a low tail from the whole scalp), which meet it at different arc fractions.
/// Loose hair hanging side by side does not converge (its ratio stays near 1, a tail's
/// lies well under this; docs/simulate.md).
constexpr double kWaistSpreadRatio = 0.4;

/// Each hair particle's arc fraction along its strand (equal arcs: i / (n - 1)).
double fraction_of(int32_t i, int32_t hairs) { return hairs > 1 ? double(i) / (hairs - 1) : 0.0; }

/// The hair particles of running strand `g`, through `position_of(g, i)`, sampled at
/// kCentreSamples equal arc fractions in one walk, into samples[0 .. kCentreSamples); with
/// `velocities`, their velocities `velocity_of(g, i)` at the same places, interpolated
/// alike.
constexpr int kCentreSamples = 32;
template <typename PositionOf, typename VelocityOf>
void sample_fractions(PositionOf&& position_of, VelocityOf&& velocity_of, size_t g, int32_t hairs,
                      Vec3* samples, Vec3* velocities) {
  if (hairs < 2) {
    for (int k = 0; k < kCentreSamples; ++k) {
      samples[k] = position_of(g, 0);
      if (velocities) velocities[k] = velocity_of(g, 0);
    }
    return;
  }
  double length = 0;
  for (int32_t i = 0; i + 1 < hairs; ++i) length += (position_of(g, i + 1) - position_of(g, i)).norm();
  int32_t segment = 0;
  Vec3 a = position_of(g, 0), b = position_of(g, 1);
  double step = (b - a).norm(), walked = 0;
  for (int k = 0; k < kCentreSamples; ++k) {
    const double goal = length * k / (kCentreSamples - 1);
    while (walked + step < goal && segment + 2 < hairs) {
      walked += step;
      ++segment;
      a = b;
      b = position_of(g, segment + 1);
      step = (b - a).norm();
    }
    const double t = step > 0 ? std::clamp((goal - walked) / step, 0.0, 1.0) : 1.0;
    samples[k] = a + t * (b - a);
    if (velocities)
      velocities[k] = (1 - t) * velocity_of(g, segment) + t * velocity_of(g, segment + 1);
  }
}

/// The centre line's point at arc fraction `fraction`, from its samples.
Vec3 centre_at(const std::vector<Vec3>& centre, double fraction) {
  const double x = std::clamp(fraction, 0.0, 1.0) * (kCentreSamples - 1);
  const auto k = std::min(static_cast<int>(x), kCentreSamples - 2);
  const double t = x - k;
  return (1 - t) * centre[static_cast<size_t>(k)] + t * centre[static_cast<size_t>(k) + 1];
}

}  // namespace

BundleCohesion::BundleCohesion(const std::vector<SimulatedGuide>& guides,
                               const std::vector<RunningStrand>& running, double stiffness_per_s2,
                               double damping_ratio, int min_guides)
    : stiffness_per_s2_(stiffness_per_s2), damping_ratio_(damping_ratio) {
  if (!(stiffness_per_s2 > 0)) return;
  std::map<int32_t, std::vector<size_t>> by_cluster;
  for (size_t g = 0; g < guides.size() && g < running.size(); ++g)
    if (guides[g].kind == GuideKind::strand) by_cluster[guides[g].cluster].push_back(g);
  auto rest_point = [&](size_t g, double fraction) {
    const AltitudeStrand& model = running[g].model;
    std::vector<Vec3> line;
    for (int32_t q : model.hair_particle) line.push_back(model.rest_m[static_cast<size_t>(q)]);
    return point_at_arc_fraction(line, fraction);
  };
  auto spread = [&](const std::vector<size_t>& members, double fraction) {
    Vec3 mean = Vec3::Zero();
    std::vector<Vec3> points;
    for (size_t g : members) points.push_back(rest_point(g, fraction)), mean += points.back();
    mean /= static_cast<double>(points.size());
    double sum = 0;
    for (const Vec3& p : points) sum += (p - mean).squaredNorm();
    return std::sqrt(sum / static_cast<double>(points.size()));
  };
  // The spread at the members' waist: over every rest hair particle P of the members
  // beyond the first fifth of its strand, the root mean square of each member's nearest
  // distance to P, the least of them.
  auto waist_spread = [&](const std::vector<size_t>& members) {
    std::vector<std::vector<Vec3>> lines;
    for (size_t g : members) {
      const AltitudeStrand& model = running[g].model;
      std::vector<Vec3> line;
      for (int32_t q : model.hair_particle) line.push_back(model.rest_m[static_cast<size_t>(q)]);
      lines.push_back(std::move(line));
    }
    double best = std::numeric_limits<double>::infinity();
    for (const auto& line : lines)
      for (size_t i = line.size() / 5; i < line.size(); ++i) {
        double sum = 0;
        for (const auto& other : lines) {
          double nearest = std::numeric_limits<double>::infinity();
          for (size_t j = 0; j + 1 < other.size(); ++j) {
            const Vec3 d = other[j + 1] - other[j];
            const double t = d.squaredNorm() > 0 ? std::clamp((line[i] - other[j]).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
            nearest = std::min(nearest, (other[j] + t * d - line[i]).squaredNorm());
          }
          sum += nearest;
        }
        best = std::min(best, std::sqrt(sum / static_cast<double>(lines.size())));
      }
    return best;
  };
  for (const auto& [cluster, members] : by_cluster) {
    if (static_cast<int>(members.size()) < min_guides) continue;
    // Gathered: hanging from fixed hair (a band), or somewhere along their middle (a fifth
    // to four fifths of their length) at most kGatheredSpreadRatio as spread as at their
    // roots (a tail whose strands run from the scalp through a band), or passing close to
    // one point somewhere along their lengths (their waist: a band they meet at different
    // arc fractions).
    bool from_band = true;
    for (size_t g : members) from_band = from_band && guides[g].anchor_point > 0;
    double narrowest = std::numeric_limits<double>::infinity();
    for (int k = 0; k <= 12; ++k) narrowest = std::min(narrowest, spread(members, 0.2 + 0.05 * k));
    const double root_spread = spread(members, 0.0);
    if (!from_band && !(narrowest <= kGatheredSpreadRatio * root_spread) &&
        !(waist_spread(members) <= kWaistSpreadRatio * root_spread))
      continue;
    Bundle bundle;
    bundle.cluster = cluster;
    bundle.members = members;
    auto rest = [&](size_t g, int32_t i) {
      const AltitudeStrand& model = running[g].model;
      return model.rest_m[static_cast<size_t>(model.hair_particle[static_cast<size_t>(i)])];
    };
    std::vector<Vec3> centre(kCentreSamples, Vec3::Zero()), samples(kCentreSamples);
    for (size_t g : members) {  // in member order: deterministic
      sample_fractions(
          rest, [](size_t, int32_t) { return Vec3::Zero().eval(); }, g,
          running[g].model.hair_count(), samples.data(), nullptr);
      for (int k = 0; k < kCentreSamples; ++k) centre[static_cast<size_t>(k)] += samples[static_cast<size_t>(k)];
    }
    for (Vec3& point : centre) point /= static_cast<double>(members.size());
    for (size_t m = 0; m < members.size(); ++m) {
      std::vector<double> radius;
      const int32_t hairs = running[members[m]].model.hair_count();
      for (int32_t i = 0; i < hairs; ++i)
        radius.push_back((rest(members[m], i) - centre_at(centre, fraction_of(i, hairs))).norm());
      bundle.rest_radius_m.push_back(std::move(radius));
    }
    bundle.centre = std::move(centre);
    bundle.centre_velocity.assign(kCentreSamples, Vec3::Zero());
    bundle_of_.resize(running.size(), -1);
    slot_of_.resize(running.size(), -1);
    for (size_t m = 0; m < bundle.members.size(); ++m) {
      bundle_of_[bundle.members[m]] = static_cast<int32_t>(bundles_.size());
      slot_of_[bundle.members[m]] = static_cast<int32_t>(m);
    }
    bundles_.push_back(std::move(bundle));
  }
  add_followers(guides, running);
}

void BundleCohesion::add_followers(const std::vector<SimulatedGuide>& guides,
                                   const std::vector<RunningStrand>& running) {
  auto rest = [&](size_t g, int32_t i) {
    const AltitudeStrand& model = running[g].model;
    return model.rest_m[static_cast<size_t>(model.hair_particle[static_cast<size_t>(i)])];
  };
  // Root mean square of a strand's rest offsets from the centre line over the lower three
  // quarters of its hair particles (below where a band or the scalp holds it).
  auto lower_rms = [](const std::vector<double>& radius) {
    double sum = 0;
    size_t count = 0;
    for (size_t i = radius.size() / 4; i < radius.size(); ++i)
      sum += radius[i] * radius[i], ++count;
    return count > 0 ? std::sqrt(sum / static_cast<double>(count)) : 0.0;
  };
  std::vector<double> widest(bundles_.size(), 0);  // per bundle: its widest member's
  for (size_t b = 0; b < bundles_.size(); ++b)
    for (size_t m = 0; m < bundles_[b].members.size(); ++m)
      widest[b] = std::max(widest[b], lower_rms(bundles_[b].rest_radius_m[m]));
  for (size_t g = 0; g < guides.size() && g < running.size(); ++g) {
    if (guides[g].kind != GuideKind::strand || member(g)) continue;
    const int32_t hairs = running[g].model.hair_count();
    if (hairs < 2) continue;
    int32_t best = -1;
    double best_share = 1;  // at most as far out as the bundle's widest member
    std::vector<double> best_radius;
    for (size_t b = 0; b < bundles_.size(); ++b) {
      std::vector<double> radius;
      for (int32_t i = 0; i < hairs; ++i)
        radius.push_back(
            (rest(g, i) - centre_at(bundles_[b].centre, fraction_of(i, hairs))).norm());
      const double share = widest[b] > 0 ? lower_rms(radius) / widest[b] : 2.0;
      if (share <= best_share)
        best = static_cast<int32_t>(b), best_share = share, best_radius = std::move(radius);
    }
    if (best < 0) continue;
    Bundle& bundle = bundles_[static_cast<size_t>(best)];
    bundle_of_[g] = best;
    slot_of_[g] = static_cast<int32_t>(bundle.rest_radius_m.size());
    bundle.followers.push_back(g);
    bundle.rest_radius_m.push_back(std::move(best_radius));
  }
}

double BundleCohesion::damping_for_step(double dt_s) const {
  const double critical_per_s = 2 * std::sqrt(stiffness_for_step(dt_s));
  const double damping_per_s = damping_ratio_ * critical_per_s;
  return dt_s > 0 ? std::min(damping_per_s, 1.0 / dt_s) : damping_per_s;
}

int64_t BundleCohesion::guide_count() const {
  int64_t count = 0;
  for (const Bundle& bundle : bundles_) count += static_cast<int64_t>(bundle.members.size());
  return count;
}

int64_t BundleCohesion::follower_count() const {
  int64_t count = 0;
  for (const Bundle& bundle : bundles_) count += static_cast<int64_t>(bundle.followers.size());
  return count;
}

double BundleCohesion::stiffness_for_step(double dt_s) const {
  if (!(dt_s > 0)) return stiffness_per_s2_;
  return std::min(stiffness_per_s2_, 1.0 / (dt_s * dt_s));
}

void BundleCohesion::sample(size_t g, const std::vector<RunningStrand>& running) {
  if (!member(g)) return;
  auto now = [&](size_t strand, int32_t i) -> const Vec3& {
    const AltitudeStrand& model = running[strand].model;
    return running[strand].state.position_m[static_cast<size_t>(model.hair_particle[static_cast<size_t>(i)])];
  };
  auto velocity = [&](size_t strand, int32_t i) -> const Vec3& {
    const AltitudeStrand& model = running[strand].model;
    return running[strand]
        .state.velocity_m_s[static_cast<size_t>(model.hair_particle[static_cast<size_t>(i)])];
  };
  sample_fractions(now, velocity, g, running[g].model.hair_count(),
                   samples_.data() + g * kCentreSamples,
                   velocity_samples_.data() + g * kCentreSamples);
}

void BundleCohesion::sample_all(const std::vector<RunningStrand>& running) {
  samples_.resize(running.size() * kCentreSamples);
  velocity_samples_.resize(running.size() * kCentreSamples);
  for (size_t g = 0; g < running.size(); ++g) sample(g, running);
}

void BundleCohesion::update_centres() {
  for (Bundle& bundle : bundles_) {
    bundle.centre.assign(kCentreSamples, Vec3::Zero());
    bundle.centre_velocity.assign(kCentreSamples, Vec3::Zero());
    for (size_t g : bundle.members)  // in member order: deterministic
      for (size_t k = 0; k < kCentreSamples; ++k) {
        bundle.centre[k] += samples_[g * kCentreSamples + k];
        bundle.centre_velocity[k] += velocity_samples_[g * kCentreSamples + k];
      }
    for (Vec3& point : bundle.centre) point /= static_cast<double>(bundle.members.size());
    for (Vec3& velocity : bundle.centre_velocity)
      velocity /= static_cast<double>(bundle.members.size());
  }
}

void BundleCohesion::acceleration(size_t g, const std::vector<RunningStrand>& running,
                                  double dt_s, std::vector<Vec3>& acceleration_m_s2) const {
  const AltitudeStrand& model = running[g].model;
  acceleration_m_s2.assign(model.rest_m.size(), Vec3::Zero());
  if (!active() || !member(g)) return;
  const Bundle& bundle = bundles_[static_cast<size_t>(bundle_of_[g])];
  const std::vector<double>& rest_radius = bundle.rest_radius_m[static_cast<size_t>(slot_of_[g])];
  const double stiffness_per_s2 = stiffness_for_step(dt_s);
  const double damping_per_s = damping_for_step(dt_s);
  const int32_t hairs = model.hair_count();
  for (int32_t i = 0; i < hairs; ++i) {
    const auto q = static_cast<size_t>(model.hair_particle[static_cast<size_t>(i)]);
    if (static_cast<int32_t>(q) < model.kinematic_count) continue;
    const Vec3 off = running[g].state.position_m[q] - centre_at(bundle.centre, fraction_of(i, hairs));
    const double radius = off.norm();
    const double excess = radius - rest_radius[static_cast<size_t>(i)];
    if (!(excess > 0) || !(radius > 0)) continue;
    const Vec3 outward = off / radius;
    const double outward_speed_m_s = (running[g].state.velocity_m_s[q] -
                                      centre_at(bundle.centre_velocity, fraction_of(i, hairs)))
                                         .dot(outward);
    const double pull_m_s2 = stiffness_per_s2 * excess + damping_per_s * outward_speed_m_s;
    if (pull_m_s2 > 0) acceleration_m_s2[q] -= pull_m_s2 * outward;
  }
}

void BundleCohesion::accelerations(const std::vector<RunningStrand>& running, double dt_s,
                                   std::vector<std::vector<Vec3>>& acceleration_m_s2) {
  if (!active()) return;
  sample_all(running);
  update_centres();
  for (size_t g = 0; g < running.size(); ++g)
    if (member(g)) acceleration(g, running, dt_s, acceleration_m_s2[g]);
}

}  // namespace hair
