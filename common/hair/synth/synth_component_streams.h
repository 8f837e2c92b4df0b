#pragma once
// The streams of each kind of hairstyle component (ComponentSpec::Kind): loose strips and
// cards, a short cap, a ponytail, a braid, each appended to the hairstyle's streams.

#include <vector>

#include "hair/synth/synth_head.h"
#include "hair/synth/synth_model.h"
#include "hair/synth/synth_rng.h"
#include "hair/synth/synth_stream.h"

namespace hair::synth {

/// Normal or short hair: one stream per root, cut into strips or cards.
void add_loose_streams(const ComponentSpec& component, int component_index,
                       const DefectSpec& defects, const Head& head, Rng& rng,
                       std::vector<Stream>& streams);

/// Short hair lying on the head (short02, short03): cap grids fanning out from a crown
/// whorl (the band position: `band_azimuth_deg`, `band_polar_deg`), one per stream, side
/// by side around it. A grid's root lies `polar_min_deg` to `polar_max_deg` from the
/// whorl; from there it flows over the head away from the whorl (turning by up to 12
/// degrees, all grids alike: the swirl of a crown) down to the front hairline, lying on
/// the scalp (scalp_lift_m at the root, 1.5 times that at the tip) and widening with the
/// angle from the whorl so that the grids tile the scalp. A stream ends at the hairline,
/// or before it when its drawn length is shorter. No band, no continuation: a stream is
/// one grid (root-free), or a root piece and a tip piece when normal_pieces_max allows (a
/// layered cut); every piece is short.
void add_short_cap(const ComponentSpec& component, int component_index, const DefectSpec& defects,
                   const Head& head, Rng& rng, std::vector<Stream>& streams);

/// A ponytail: cap grids from the hairline to a band (fixed), tail strips from the band
/// (normal), one stream per cap patch, a hidden gap at the band; with a bun radius, the
/// tails coil round the band (fixed).
void add_ponytail(const ComponentSpec& component, int component_index, const DefectSpec& defects,
                  const Head& head, Rng& rng, std::vector<Stream>& streams);

/// A braid: three streams, each a cap grid from a third of the scalp region to the braid
/// top (fixed), then many short pieces along a stream interleaving with the other two
/// around a hanging axis (braided): offsets a sin(wt + phi_k) across and b sin(2(wt +
/// phi_k)) out of the braid, phi_k = 2 pi k / 3, the classic parametric three-strand braid.
/// As artists make braids: each lobe woven from braid_cards_per_lobe such streams side by
/// side, the braid narrowing to braid_tip_width_share at its tip, its top braid_lift_m
/// farther off the head than the band point.
void add_braid(const ComponentSpec& component, int component_index, const DefectSpec& defects,
               const Head& head, Rng& rng, std::vector<Stream>& streams);

}  // namespace hair::synth
