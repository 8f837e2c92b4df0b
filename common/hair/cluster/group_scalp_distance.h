#pragma once

#include <cstdint>
#include <vector>

#include "hair/core/strand_set.h"
#include "hair/geom/triangle_mesh_distance.h"

namespace hair {

/// Distance in metres from the first point of each strand of `centres` (a group's centre
/// strand, root first) to the scalp: the body triangles flagged in `scalp_triangle` (the
/// whole body when none is flagged). A group whose centre strand starts this far from the
/// scalp does not start at a root, whatever lies before it.
///
/// @param centres         one strand per group
/// @param body_vertices   #V x 3, metres
/// @param body_triangles  #T x 3 vertex ids (non-empty)
/// @param scalp_triangle  #T flags, 1 for the scalp
std::vector<double> start_scalp_distances(const StrandSet& centres, const Points3f& body_vertices,
                                          const Triangles3i& body_triangles,
                                          const std::vector<uint8_t>& scalp_triangle);

}  // namespace hair
