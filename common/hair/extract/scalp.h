#pragma once
// The scalp: the body triangles that carry the hair's roots (extract.h5 /body/scalp_triangle;
// grow samples its roots there).

#include <cstdint>
#include <vector>

#include "hair/core/strand_set.h"
#include "hair/geom/triangle_mesh_distance.h"
#include "hair/mesh/poly_mesh.h"

namespace hair {

/// A body triangle whose outward normal's +Z component exceeds this faces forward (the face
/// looks along +Z, as MakeHuman's does): hair hanging in front of it is rooted above it.
inline constexpr double kFaceNormalZ = 0.5;

/// Marks (1) the body triangles whose centroid lies at or above `neck_y` (+Y up) and
///  - within `max_distance_m` of the hair mesh, or
///  - not facing forward (kFaceNormalZ), under hair that stands off the head: hair within
///    `max_distance_m` of a point on the triangle's outward normal (right-hand winding) at a
///    multiple of `max_distance_m` up to `under_hair_m` out. A bob's shell stands 2-4 cm off
///    the back of the head and its hair is rooted all over the scalp under it, where the
///    distance alone marks only the crown and the nape. under_hair_m no more than
///    max_distance_m: the distance alone decides. Only for triangles at least
///    `under_hair_min_height_m` above `neck_y`: lower, at the bottom of the nape and under
///    the ears, hair standing off the head hangs past it from above (a ponytail's tail 2-4
///    cm off the nape, long hair) and is not rooted there.
/// Deterministic whatever the thread count.
std::vector<uint8_t> scalp_triangles(const Points3f& body_vertices,
                                     const Triangles3i& body_triangles, double neck_y,
                                     const PolyMesh& hair_mesh, double max_distance_m,
                                     double under_hair_m, double under_hair_min_height_m);

}  // namespace hair
