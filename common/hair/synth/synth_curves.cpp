// Curves that streams of synthetic hair follow over and off the head: grown under gravity,
// rounded, stood off the head, laid over the cap to a band.
#include "hair/synth/synth_curves.h"

#include <algorithm>
#include <cmath>

#include "hair/synth/synth_stream.h"

namespace hair::synth {

namespace {

/// Where a draped cap grid from `root_dir` passes on its way to the band: the side of the
/// head above the ear (polar 80 degrees), at the root's own azimuth, pushed at least 70
/// degrees from the face so the hair is swept off it.
Vec3 drape_direction(const Vec3& root_dir) {
  Vec3 r = root_dir.normalized();
  double azimuth_deg = std::atan2(r.x(), r.z()) * 180.0 / kPi;
  double polar_deg = std::acos(std::clamp(r.y(), -1.0, 1.0)) * 180.0 / kPi;
  double side = azimuth_deg < 0 ? -1.0 : 1.0;
  double via_azimuth = std::abs(azimuth_deg) < 70.0 ? side * 70.0 : azimuth_deg;
  return direction(via_azimuth, std::max(polar_deg, 80.0));
}

/// Unit directions from `from` to `to` (unit vectors) along the great circle, `steps` + 1 of
/// them, both ends included.
std::vector<Vec3> great_circle(const Vec3& from, const Vec3& to, int steps) {
  double angle = std::acos(std::clamp(from.dot(to), -1.0, 1.0));
  std::vector<Vec3> out;
  for (int i = 0; i <= steps; ++i) {
    double t = static_cast<double>(i) / steps;
    out.push_back(std::abs(std::sin(angle)) < 1e-6
                      ? from
                      : Vec3((std::sin((1 - t) * angle) * from + std::sin(t * angle) * to) /
                             std::sin(angle)));
  }
  return out;
}

}  // namespace

std::vector<Vec3> grown_curve(const Head& head, const Vec3& root, const Vec3& start,
                              double length_m, double bend_m, double clearance_m, bool hug_scalp) {
  std::vector<Vec3> points{root};
  Vec3 dir = start.normalized();
  Vec3 p = root;
  int steps = std::max(2, static_cast<int>(std::ceil(length_m / kStep_m)));
  double step = length_m / steps;
  for (int i = 0; i < steps; ++i) {
    dir = (dir + (step / bend_m) * Vec3(0, -1, 0)).normalized();
    Vec3 next = head.pushed_out(p + step * dir, clearance_m);
    if (hug_scalp && next.y() > head.centre.y() - 0.2 * head.radius_m) {
      // Over the head, hair lies on the scalp (held by the hair under it) until it
      // falls off the head's sides and back.
      auto nearest = head.body.nearest(next);
      if (nearest.distance > clearance_m && nearest.distance > 0)
        next = nearest.closest_point +
               (next - nearest.closest_point) * (clearance_m / nearest.distance);
    }
    // Keep the step length: a push changes the direction, not the speed.
    Vec3 moved = next - p;
    if (moved.norm() > 1e-9) {
      dir = moved.normalized();
      next = p + step * dir;
    }
    p = next;
    points.push_back(p);
  }
  // Three passes of Laplacian smoothing, roots fixed, then pushed out again.
  for (int pass = 0; pass < 3; ++pass)
    for (size_t i = 1; i + 1 < points.size(); ++i)
      points[i] =
          head.pushed_out(0.5 * points[i] + 0.25 * (points[i - 1] + points[i + 1]), clearance_m);
  return points;
}

void round_creases(const Head& head, std::vector<Vec3>& curve, double min_radius_m,
                   double clearance_m, int max_passes) {
  for (int pass = 0; pass < max_passes; ++pass) {
    std::vector<size_t> creased;
    for (size_t i = 1; i + 1 < curve.size(); ++i) {
      Vec3 before = curve[i] - curve[i - 1], after = curve[i + 1] - curve[i];
      double turn = std::acos(std::clamp(before.normalized().dot(after.normalized()), -1.0, 1.0));
      if (turn > 0.5 * (before.norm() + after.norm()) / min_radius_m) creased.push_back(i);
    }
    if (creased.empty()) return;
    for (size_t i : creased)
      curve[i] =
          head.pushed_out(0.5 * curve[i] + 0.25 * (curve[i - 1] + curve[i + 1]), clearance_m);
  }
}

void stand_off(const Head& head, std::vector<Vec3>& curve, double volume_m, double clearance_m) {
  std::vector<double> along(curve.size(), 0.0);
  for (size_t i = 1; i < curve.size(); ++i)
    along[i] = along[i - 1] + (curve[i] - curve[i - 1]).norm();
  if (curve.size() < 2 || along.back() <= 0) return;
  for (size_t i = 1; i < curve.size(); ++i) {
    auto smoothstep = [](double t) {
      t = std::clamp(t, 0.0, 1.0);
      return t * t * (3 - 2 * t);
    };
    double lift = volume_m * smoothstep(along[i] / (0.4 * along.back())) *
                  smoothstep((along.back() - along[i]) / (0.25 * along.back()));
    Vec3 outward = curve[i] - head.centre;
    outward.y() = 0;
    if (outward.norm() < 1e-9) continue;
    curve[i] = head.pushed_out(curve[i] + lift * outward.normalized(), clearance_m);
  }
}

std::vector<Vec3> cap_curve(const Head& head, const Vec3& root_dir, const Vec3& band_end,
                            double lift_root_m, double clearance_m, const CapShape& shape) {
  Vec3 band_dir = (band_end - head.centre).normalized();
  Vec3 from = root_dir.normalized();
  auto steps_for = [&](const Vec3& a, const Vec3& b) {
    double angle = std::acos(std::clamp(a.dot(b), -1.0, 1.0));
    return std::max(4, static_cast<int>(angle * head.radius_m / kStep_m));
  };
  std::vector<Vec3> directions;
  if (shape.drape) {
    Vec3 via = drape_direction(from);
    directions = great_circle(from, via, steps_for(from, via));
    std::vector<Vec3> second = great_circle(via, band_dir, steps_for(via, band_dir));
    directions.insert(directions.end(), second.begin() + 1, second.end());
  } else {
    directions = great_circle(from, band_dir, steps_for(from, band_dir));
  }
  // Where along the way each direction lies (0 at the root, 1 at the band), by angle.
  std::vector<double> along(directions.size(), 0.0);
  for (size_t i = 1; i < directions.size(); ++i)
    along[i] =
        along[i - 1] + std::acos(std::clamp(directions[i - 1].dot(directions[i]), -1.0, 1.0));
  std::vector<Vec3> points;
  auto [band_surface, band_outward] = head.surface(band_dir);
  double band_lift = (band_end - band_surface).norm();
  const size_t last = directions.size() - 1;
  for (size_t i = 0; i <= last; ++i) {
    // Along one great circle the directions are evenly spaced: i / last exactly.
    double t = !shape.drape       ? static_cast<double>(i) / static_cast<double>(last)
               : along.back() > 0 ? along[i] / along.back()
                                  : 1.0;
    auto [surface, outward] = head.surface(directions[i]);
    double lift = lift_root_m + (band_lift - lift_root_m) * t * t +
                  shape.volume_m * std::max(0.0, std::sin(kPi * t));
    points.push_back(i == last ? band_end
                               : head.pushed_out(surface + lift * outward, clearance_m * 0.5));
  }
  return points;
}

void append_points(std::vector<Vec3>& points, const std::vector<Vec3>& tail) {
  for (const Vec3& p : tail)
    if (points.empty() || (p - points.back()).norm() > 1e-9) points.push_back(p);
}

std::pair<Vec3, Vec3> band_point(const Head& head, const ComponentSpec& component) {
  auto [surface, outward] =
      head.surface(direction(component.band_azimuth_deg, component.band_polar_deg));
  return {surface + 0.012 * outward, outward};
}

}  // namespace hair::synth
