#pragma once
// Curves that streams of synthetic hair follow over and off the head: grown under gravity,
// rounded, stood off the head, laid over the cap to a band.

#include <utility>
#include <vector>

#include "hair/synth/synth_head.h"
#include "hair/synth/synth_model.h"

namespace hair::synth {

/// A hair grown from `root` in direction `start` for `length_m`: bending down under
/// gravity (radius of the bend about `bend_m`) and kept `clearance_m` off the body.
std::vector<Vec3> grown_curve(const Head& head, const Vec3& root, const Vec3& start,
                              double length_m, double bend_m, double clearance_m,
                              bool hug_scalp = false);

/// Rounds the creases out of `curve`: where it turns between consecutive segments by more
/// than a bend of radius `min_radius_m` allows, the point is moved towards its
/// neighbours' midpoint (and kept `clearance_m` off the body), pass after pass until no
/// point turns too sharply (at most `max_passes`). Ends stay; a curve that bends less
/// everywhere is returned unchanged. A braid's axis grown down onto a shoulder is pushed
/// off it within a step or two, a fold no braid a few centimetres wide makes.
void round_creases(const Head& head, std::vector<Vec3>& curve, double min_radius_m,
                   double clearance_m, int max_passes = 400);

/// Lifts a hanging curve away from the head's vertical axis by up to `volume_m`: nothing at
/// the root, rising as a smoothstep over the first 40% of its length, falling back as one
/// over the last 25% (the tips turn in), as a bob's cards stand off the head below the
/// crown; kept `clearance_m` off the body.
void stand_off(const Head& head, std::vector<Vec3>& curve, double volume_m, double clearance_m);

/// How a cap's grids lie between their roots and the band: close over the head (the
/// default), or loose hair drawn low over the ears with volume (ComponentSpec::cap_volume_m,
/// cap_drape).
struct CapShape {
  double volume_m = 0;  ///< the grids stand up to this far off the head between root and band
  bool drape = false;   ///< the grids fall down the side of the head before sweeping back
};

/// A curve over the head from `root` to `band`: directions from the head centre
/// interpolated on the sphere (through the side of the head when `shape.drape`), each put
/// on the surface, lifted from `lift_root_m` at the root to the band's own height at the end
/// and, with volume, up to `shape.volume_m` more in between (sin(pi t), t the share of the
/// way: rising from the root, drawn in to the band at the end).
std::vector<Vec3> cap_curve(const Head& head, const Vec3& root_dir, const Vec3& band_end,
                            double lift_root_m, double clearance_m, const CapShape& shape = {});

/// Appends `tail` (its first point excluded when it repeats the last) to `points`.
void append_points(std::vector<Vec3>& points, const std::vector<Vec3>& tail);

/// A band on the head: its point (lifted off the hair under it) and outward normal.
std::pair<Vec3, Vec3> band_point(const Head& head, const ComponentSpec& component);

}  // namespace hair::synth
