#pragma once
// The sense of grown strands, beyond their axis: strands that turn back on themselves
// (hairpins), that cut through air where the mesh has no hair (chords), and how much
// they curl against the cards they were grown from.

#include <array>
#include <cstdint>
#include <vector>

#include "hair/core/strand_set.h"
#include "hair/geom/triangle_mesh_distance.h"

namespace hair {

/// What counts as a kink (docs/grow.md, "Kinks and curls").
struct KinkLimits {
  /// A turn between consecutive segments sharper than this is a hairpin: real hair bends
  /// that sharply only where something folds it, and a card mesh shows no such fold.
  double hairpin_turn_deg = 90;
  /// A stretch of strand at least this long, every point of it farther than
  /// `air_distance_h` from the hair mesh, is a chord through air.
  double air_chord_length_m = 0.02;
  /// Farther than this (head heights) from every hair triangle is air: about twice the
  /// thickness of a card layer stacked on the head (4 to 6 mm), so that hair filling
  /// the space between two layers is not air.
  double air_distance_h = 0.04;
  /// Points are tested this far apart (head heights) along a segment, so that one long
  /// segment is judged along its whole length, not only at its ends.
  double air_sample_step_h = 0.01;
  /// A point far from the hair mesh is still in the hair where hair lies over it: within
  /// this distance (head heights) straight out from the body (from the body's nearest
  /// point through the point). Hair filling a shell mesh, or lying under a card layer,
  /// is not air; a chord above the hair, or beside it, is.
  double covered_reach_h = 0.5;
};

/// Kinks of a strand set; shares of strands (0 when there are none).
struct KinkMeasures {
  int64_t strands = 0;
  int64_t hairpin_strands = 0;    ///< with a turn sharper than hairpin_turn_deg
  int64_t air_chord_strands = 0;  ///< with a chord through air longer than air_chord_length_m
  int64_t kinked_strands = 0;     ///< with either
  /// The air-chord strands by the GrowRule that grew most of the length of their longest
  /// stretch through air: [1] field, [2] input strand, [3] bridge ([0] when no rule was
  /// given). Sums to air_chord_strands.
  std::array<int64_t, 4> air_chord_strands_by_rule{};
  /// The index of every kinked strand, in order.
  std::vector<int64_t> kinked;
  double kinked_share() const {
    return strands == 0 ? 0.0 : static_cast<double>(kinked_strands) / static_cast<double>(strands);
  }
};

/// Whether the polyline `points` (#n x 3, metres) turns by more than `turn_deg` between two
/// consecutive segments; segments shorter than 1e-9 m are skipped (a repeated point is
/// no turn).
bool has_hairpin(const Points3f& points, double turn_deg);

/// Where the air is around a hair mesh on a body: farther than `air_m` from every hair
/// triangle, and no hair triangle within `air_m` of the way straight out from the body
/// through the point, up to `reach_m` (tested every `air_m`). Without a body, every
/// point far from the hair is air.
class AirAroundHair {
 public:
  AirAroundHair(const TriangleMeshDistance& hair, const TriangleMeshDistance* body, double air_m,
                double reach_m)
      : hair_(hair), body_(body), air_m_(air_m), reach_m_(reach_m) {}
  bool is_air(const Eigen::Vector3d& point) const;

 private:
  const TriangleMeshDistance& hair_;
  const TriangleMeshDistance* body_;
  double air_m_, reach_m_;
};

/// The longest stretch of a polyline through air, and which segments it runs along.
struct AirStretch {
  double length_m = 0;  ///< arc length along which every tested point is air
  /// Arc length of the stretch along each segment: entry i for the segment ending at point
  /// i + 1.
  std::vector<double> length_by_segment_m;
};

/// The longest stretch (metres of arc length) of `points` along which every tested point
/// is air; points are tested at the vertices and every `step_m` between them.
AirStretch longest_air_stretch(const Points3f& points, const AirAroundHair& air, double step_m);
inline double longest_air_stretch_m(const Points3f& points, const AirAroundHair& air,
                                    double step_m) {
  return longest_air_stretch(points, air, step_m).length_m;
}

/// Kinks of every strand of `grown` against the hair mesh and the body (their distance
/// indices; the body may be null). With `point_rule` (the grow stage's /strands/point_rule,
/// one GrowRule value 0-3 per point), the air chords are also counted by the rule that grew
/// them. Deterministic; strands run in parallel (OpenMP). Throws hair::Error (bad input)
/// when `point_rule` is given without one entry per point or with a value outside 0-3.
KinkMeasures measure_kinks(const StrandSet& grown, const TriangleMeshDistance& hair_distance,
                           const TriangleMeshDistance* body_distance, double head_height_m,
                           const KinkLimits& limits = {},
                           const std::vector<int8_t>* point_rule = nullptr);

/// How much strands curl: the total turning angle over the total length (radians per
/// metre) of every strand resampled at `step_m` of arc length (strands shorter than
/// three steps are left out). At a common step the grown strands and the cards' input
/// strands compare, whatever the meshes' and the grower's point spacings.
double mean_curvature_per_m(const StrandSet& strands, double step_m);

}  // namespace hair
