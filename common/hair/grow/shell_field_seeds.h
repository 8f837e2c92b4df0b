#pragma once
// Seeds of the orientation fields under hair that lies off the head (a bob's shell, a cap
// puffed out over the crown). A field reaches only its band (GrowParams::field_band_h)
// around the strands that seed it: where the hair mesh lies farther than that from the
// scalp, the scalp under it is outside every field and the roots there have nothing to
// follow, so the hair grows only from where the mesh comes down to the head (its crown,
// its lower edge). The hair of such a mesh is rooted all over the scalp under it and
// rises to it: its field is seeded all the way down, with the direction of the hair above.

#include <cstdint>
#include <limits>
#include <vector>

#include "hair/core/strand_set.h"
#include "hair/geom/point_index.h"
#include "hair/geom/triangle_mesh_distance.h"

namespace hair {

/// Settings of seeds_under_strands().
struct ShellSeedParams {
  /// Levels of seeds lie this far apart above the body (metres, > 0): the field's band, so
  /// that the bands round successive levels meet. The lowest lies half of it above the
  /// body, the highest at least half of it under the strand.
  double spacing_m = 0.014;
  /// Points of a strand higher than this above the body (metres) seed nothing under them:
  /// hair that hangs away from the head (a tail, a braid, the ends of long hair) is not a
  /// shell over the scalp.
  double max_height_m = 0.07;
  /// Nor do points where the strand rises off the body (the cosine of its direction with
  /// the body's normal there above this): a card standing on the head (a spike) grows from
  /// its base, not from the scalp under its lean.
  double max_rise_cosine = 0.7071;
  /// Nor do points whose nearest body point lies lower than this (+Y up, metres; grow
  /// takes max_height_m under the scalp's lowest point): hair lying on the shoulders and
  /// the back is not a shell over the scalp.
  double min_foot_y_m = -std::numeric_limits<double>::infinity();
};

/// The seeds under `strands` (polylines, root first, metres) over the body `body`: for each
/// level, the runs of consecutive points high enough to have it, each point moved along the
/// body's normal at its nearest body point (the direction from that point to it) down to
/// the level's height, and left out where a point of `hair` (the input strands that seed
/// fields, indexed) lies within half a spacing of it: an inner layer of hair under the
/// shell seeds its own direction there. Strand attributes "level" (int32, 0 the lowest)
/// and "strand" (int32, the index in `strands` of the strand it lies under).
/// Deterministic: in strand order, then level, then run.
StrandSet seeds_under_strands(const std::vector<Points3f>& strands,
                              const TriangleMeshDistance& body, const PointIndex& hair,
                              const ShellSeedParams& params);

}  // namespace hair
