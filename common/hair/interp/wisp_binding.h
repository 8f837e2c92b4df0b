#pragma once
// Strands bound to wisps (braids): the wisps' bound points, the seams between their
// tetrahedra, and the bridge from the head to a braided strand's first bound point.

#include <cstdint>

#include "hair/core/strand_set.h"
#include "hair/interp/strand_interpolation.h"

namespace hair {

/// The wisps' bindings: each bound point's global tetrahedron and its position in that
/// tetrahedron's frame.
void bind_wisp_points(const InterpolationGuides& guides, int64_t point_count,
                      StrandBinding& binding);

/// The seams of every strand's bound points (StrandBinding::seam_offsets and what
/// follows): where consecutive bound points lie in different tetrahedra, the points within
/// `seam_length_m` of arc of the seam's middle, each with the tetrahedron across the
/// nearest seam, weighted 0.5 (1 - d / seam_length_m) at arc distance d. Needs bound_from.
void bind_wisp_seams(const StrandSet& strands, const InterpolationGuides& guides,
                     double seam_length_m, StrandBinding& binding);

/// Where the bridge of strand `s` to its wisp starts: its first point not held. The held
/// points (`held` from the root) give way from the end until the bridge, from the last
/// point still held to the first bound one, spans `length_m` of arc; the root stays held.
int64_t bridge_start(const StrandSet& strands, int64_t s, int64_t held, int64_t bound_from,
                     double length_m);

/// Where the bridge of strand `s` to its wisp ends: its first point still bound. Where the
/// held points gave way as far as they may (bridge_start(): the root stays held) and the
/// bridge from `start` - 1 to `bound_from` still spans less than `length_m` of arc (a strand
/// rooted right by the braid's top), the bound points give way from the first, up to the
/// last but one, until it does.
int64_t bridge_end(const StrandSet& strands, int64_t s, int64_t start, int64_t bound_from,
                   double length_m);

/// The points of strand `s` between its held points and its wisp (a braided strand),
/// bridged from the head (the last held point, or the root) to the wisp by arc length.
void bridge_to_wisp(const StrandSet& strands, int64_t s, StrandBinding& binding);

}  // namespace hair
