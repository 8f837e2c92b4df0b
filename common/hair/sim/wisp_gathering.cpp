#include "hair/sim/wisp_gathering.h"

#include <algorithm>
#include <cmath>

#include "hair/sim/body_collider.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;

/// The bundle of all of `wisp`'s members (gather_wisp() without the choice of members).
std::vector<Vec3> gather_bundle(const StrandSet& strands, WispPlan& wisp, double step_m,
                                double gather_radius_m, const BodySdf& body, double clearance_m) {
  struct Run {
    std::vector<Vec3> points;
    std::vector<double> from_tip;  ///< arc length from the tip, decreasing
  };
  std::vector<Run> runs(wisp.member_strand.size());
  double longest = 0;
  for (size_t m = 0; m < runs.size(); ++m) {
    int64_t base = strands.offsets[static_cast<size_t>(wisp.member_strand[m])];
    Run& run = runs[m];
    for (int64_t i = wisp.member_first_point[m]; i < wisp.member_end_point[m]; ++i)
      run.points.push_back(point_of(strands.points, base + i));
    run.from_tip.assign(run.points.size(), 0.0);
    for (size_t i = run.points.size() - 1; i-- > 0;)
      run.from_tip[i] = run.from_tip[i + 1] + (run.points[i + 1] - run.points[i]).norm();
    longest = std::max(longest, run.from_tip.front());
  }
  // The point of `run` at arc length `s` from its tip.
  auto at = [](const Run& run, double s) {
    size_t i = run.points.size() - 1;
    while (i > 0 && run.from_tip[i - 1] < s) --i;
    if (i == 0) return run.points.front();
    double span = run.from_tip[i - 1] - run.from_tip[i];
    double t = span > 0 ? (s - run.from_tip[i]) / span : 0.0;
    return Vec3((1 - t) * run.points[i] + t * run.points[i - 1]);
  };
  int samples = static_cast<int>(std::floor(longest / step_m)) + 1;
  std::vector<Vec3> mean(static_cast<size_t>(samples), Vec3::Zero());
  std::vector<uint8_t> gathered(static_cast<size_t>(samples), 0);
  for (int k = 0; k < samples; ++k) {
    double s = k * step_m;
    std::vector<Vec3> reached;
    for (const Run& run : runs)
      if (run.from_tip.front() >= s) reached.push_back(at(run, s));
    if (2 * reached.size() < runs.size() || reached.empty()) continue;
    Vec3 sum = Vec3::Zero();
    for (const Vec3& p : reached) sum += p;
    mean[static_cast<size_t>(k)] = sum / static_cast<double>(reached.size());
    double spread = 0;
    for (const Vec3& p : reached) spread += (p - mean[static_cast<size_t>(k)]).norm();
    gathered[static_cast<size_t>(k)] =
        spread / static_cast<double>(reached.size()) <= gather_radius_m;
  }
  int best_first = 0, best_count = 0;
  for (int k = 0; k < samples;) {
    if (!gathered[static_cast<size_t>(k)]) {
      ++k;
      continue;
    }
    int first = k;
    while (k < samples && gathered[static_cast<size_t>(k)]) ++k;
    if (k - first > best_count) {
      best_count = k - first;
      best_first = first;
    }
  }
  // Three points at least: simulate hangs the wisp from a chain of tetrahedra (the
  // centre, with a ghost after its first point), and two points make none.
  if (best_count < 3) return {};
  std::vector<Vec3> centre;
  for (int k = best_first + best_count - 1; k >= best_first; --k) {
    Vec3 p = mean[static_cast<size_t>(k)];
    double distance = body.distance(p);
    if (distance < clearance_m) push_out_along_gradient(body, p, distance, clearance_m);
    if (body.distance(p) < 0) return {};
    centre.push_back(p);
  }
  for (size_t k = 1; k < centre.size(); ++k)
    if (!((centre[k] - centre[k - 1]).norm() > 1e-9)) return {};
  // Where each member enters the bundle, and what it hangs from.
  const double bundle_from_tip = (best_first + best_count - 1) * step_m;
  for (size_t m = 0; m < runs.size(); ++m) {
    size_t i = 0;
    while (i + 1 < runs[m].points.size() && runs[m].from_tip[i] > bundle_from_tip + 1e-12) ++i;
    int64_t first = wisp.member_first_point[m] + static_cast<int64_t>(i);
    wisp.member_first_point[m] = first;
    int64_t base = strands.offsets[static_cast<size_t>(wisp.member_strand[m])];
    wisp.anchor_m[m] = point_of(strands.points, base + std::max<int64_t>(0, first - 1));
  }
  return centre;
}

}  // namespace

std::vector<Vec3> gather_wisp(const StrandSet& strands, WispPlan& wisp, double step_m,
                              double gather_radius_m, const BodySdf& body, double clearance_m,
                              std::vector<GuideStrand>& loose) {
  // The members that end together.
  std::vector<Vec3> tip(wisp.member_strand.size());
  for (size_t m = 0; m < tip.size(); ++m)
    tip[m] = point_of(strands.points, strands.offsets[static_cast<size_t>(wisp.member_strand[m])] +
                                          wisp.member_end_point[m] - 1);
  // Start from the densest tip (of at most 256 evenly spread ones): the one with the
  // most tips within twice the radius; then the mean of those near the centre, until it
  // settles.
  const double reach = 2 * gather_radius_m;
  size_t stride = std::max<size_t>(1, (tip.size() + 255) / 256), best = 0, best_count = 0;
  for (size_t c = 0; c < tip.size(); c += stride) {
    size_t count = 0;
    for (const Vec3& other : tip) count += (other - tip[c]).norm() <= reach;
    if (count > best_count) {
      best_count = count;
      best = c;
    }
  }
  Vec3 tip_centre = tip.empty() ? Vec3::Zero() : tip[best];
  std::vector<uint8_t> in(tip.size(), 0);
  for (int round = 0; round < 20; ++round) {
    bool changed = false;
    Vec3 sum = Vec3::Zero();
    size_t count = 0;
    for (size_t m = 0; m < tip.size(); ++m) {
      uint8_t near = (tip[m] - tip_centre).norm() <= reach;
      changed |= near != in[m];
      in[m] = near;
      if (near) {
        sum += tip[m];
        ++count;
      }
    }
    if (count == 0) return {};
    tip_centre = sum / static_cast<double>(count);
    if (!changed) break;
  }
  size_t kept = 0;
  for (uint8_t i : in) kept += i;
  if (kept < 2) return {};
  WispPlan core = wisp;
  core.member_strand.clear();
  core.member_first_point.clear();
  core.member_end_point.clear();
  core.anchor_m.clear();
  std::vector<GuideStrand> outside;
  for (size_t m = 0; m < tip.size(); ++m) {
    if (in[m]) {
      core.member_strand.push_back(wisp.member_strand[m]);
      core.member_first_point.push_back(wisp.member_first_point[m]);
      core.member_end_point.push_back(wisp.member_end_point[m]);
      core.anchor_m.push_back(wisp.anchor_m[m]);
    } else {
      GuideStrand guide;
      guide.strand = wisp.member_strand[m];
      guide.anchor_point = std::max<int64_t>(0, wisp.member_first_point[m] - 1);
      guide.cluster = wisp.cluster;
      guide.style = HairStyle::normal;
      outside.push_back(guide);
    }
  }
  std::vector<Vec3> centre =
      gather_bundle(strands, core, step_m, gather_radius_m, body, clearance_m);
  if (centre.empty()) return {};
  // Members that end inside the bundle part-way (strands that run into a braid and stop in
  // it) belong to the wisp too, from where their run last comes within reach of the centre
  // strand, hanging from the point before.
  auto near_centre = [&](const Vec3& p) {
    for (size_t k = 0; k + 1 < centre.size(); ++k) {
      Vec3 ab = centre[k + 1] - centre[k];
      double t = std::clamp((p - centre[k]).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      if ((centre[k] + t * ab - p).norm() <= reach) return true;
    }
    return false;
  };
  std::vector<GuideStrand> still_outside;
  for (size_t m = 0, o = 0; m < tip.size(); ++m) {
    if (in[m]) continue;
    const GuideStrand& guide = outside[o++];
    int64_t base = strands.offsets[static_cast<size_t>(wisp.member_strand[m])];
    int64_t first = wisp.member_end_point[m] - 1;
    if (!near_centre(point_of(strands.points, base + first))) {
      still_outside.push_back(guide);
      continue;
    }
    while (first > wisp.member_first_point[m] &&
           near_centre(point_of(strands.points, base + first - 1)))
      --first;
    core.member_strand.push_back(wisp.member_strand[m]);
    core.member_first_point.push_back(first);
    core.member_end_point.push_back(wisp.member_end_point[m]);
    core.anchor_m.push_back(point_of(strands.points, base + std::max<int64_t>(0, first - 1)));
  }
  wisp = std::move(core);
  loose = std::move(still_outside);
  return centre;
}

}  // namespace hair
