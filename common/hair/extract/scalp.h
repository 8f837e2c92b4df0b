#pragma once
// The scalp: the body triangles that carry the hair's roots (extract.h5 /body/scalp_triangle;
// grow samples its roots there).

#include <cstdint>
#include <limits>
#include <vector>

#include "hair/core/strand_set.h"
#include "hair/geom/triangle_mesh_distance.h"
#include "hair/mesh/poly_mesh.h"

namespace hair {

/// A body triangle whose outward normal's +Z component exceeds this faces forward (the face
/// looks along +Z, as MakeHuman's does): hair hanging in front of it is rooted above it.
inline constexpr double kFaceNormalZ = 0.5;

/// The neighbourhood whose normals tell the face (face_triangles()), in head heights H:
/// 0.08 H (2 cm on the MakeHuman body), an eye socket's width, so that the faces inside a
/// socket, a nostril or the lips take the direction of the face round them.
inline constexpr double kFaceRadiusH = 0.08;

/// ...and the box behind the face's front (its frontmost point between the neck and the
/// brows, the nose's tip) in which every triangle below the brows is face, in H: 0.3 H deep
/// (7.3 cm on the MakeHuman body) and 0.2 H (4.8 cm) to either side of the nose's tip. The
/// insides of its eye sockets, nostrils and mouth, which face every way, lie 2-6 cm behind
/// the nose's tip and within 4.7 cm of the middle; the sideburns 6 cm or more to the side.
inline constexpr double kFaceDepthH = 0.3;
inline constexpr double kFaceHalfWidthH = 0.2;

/// A fold of the body thinner than this along a triangle's inward normal, in head heights
/// H, is an ear (thin_triangles()): 0.05 H (1.2 cm on the MakeHuman body, whose ears are
/// 0.3-1.2 cm thick where hair over them lies within the scalp distance; its skull is 15
/// cm across, its neck 10).
inline constexpr double kEarThicknessH = 0.05;

/// Where scalp_triangles() looks, in metres and heights (+Y up).
struct ScalpParams {
  double neck_y = 0;          ///< nothing below this is scalp
  double max_distance_m = 0;  ///< hair within this distance marks the triangle
  /// Hair standing off the head up to this far along the triangle's outward normal marks it
  /// too (no more than max_distance_m: the distance alone decides)...
  double under_hair_m = 0;
  /// ...on triangles at least this far above neck_y.
  double under_hair_min_height_m = 0;
  /// The face: triangles lower than this whose surroundings within face_radius_m face
  /// forward (their area-weighted normal's +Z over kFaceNormalZ), or that lie within
  /// face_depth_m behind the face's front and face_half_width_m of its middle, are never
  /// scalp (face_triangles()).
  double face_below_y = -std::numeric_limits<double>::infinity();
  double face_radius_m = 0;
  double face_depth_m = 0;
  double face_half_width_m = 0;
  /// Nor an ear: a triangle behind which the body is thinner than this along its inward
  /// normal (0: no such test).
  double ear_thickness_m = 0;
};

/// Marks (1) the body triangles whose centroid lies at or above `neck_y` and
///  - within `max_distance_m` of the hair mesh, or
///  - not facing forward (kFaceNormalZ), under hair that stands off the head: hair within
///    `max_distance_m` of a point on the triangle's outward normal (right-hand winding) at a
///    multiple of `max_distance_m` up to `under_hair_m` out. A bob's shell stands 2-4 cm off
///    the back of the head and its hair is rooted all over the scalp under it, where the
///    distance alone marks only the crown and the nape. Only for triangles at least
///    `under_hair_min_height_m` above `neck_y`: lower, at the bottom of the nape and under
///    the ears, hair standing off the head hangs past it from above (a ponytail's tail 2-4
///    cm off the nape, long hair) and is not rooted there;
/// except the face (face_triangles()) and the ears (thin_triangles()). A fringe or a lock
/// hanging over the eyes and cheeks lies within max_distance_m of them, and hair lying
/// over an ear too, and hair is not rooted there (counted on the face, bob01's and bob02's
/// fringes would root 7% of their strands there).
/// Deterministic whatever the thread count.
std::vector<uint8_t> scalp_triangles(const Points3f& body_vertices,
                                     const Triangles3i& body_triangles, const PolyMesh& hair_mesh,
                                     const ScalpParams& params);

/// Marks (1) the face as scalp_triangles() leaves it out: the triangles whose centroid lies
/// below `below_y` (the brows) and above `neck_y`, and around which the body within
/// `radius_m` faces forward (the area-weighted normal's +Z over kFaceNormalZ), or which lie
/// within `depth_m` behind the face's front (the body's vertex of largest Z between the
/// neck and below_y) and within `half_width_m` of it across (X): the insides of the eye
/// sockets, the nostrils and the mouth, whose faces and neighbourhoods face every way.
std::vector<uint8_t> face_triangles(const Points3f& body_vertices,
                                    const Triangles3i& body_triangles, double neck_y,
                                    double below_y, double radius_m, double depth_m,
                                    double half_width_m);

/// Marks (1) the triangles whose centroid lies above `neck_y` and behind which the body is
/// thinner than `max_thickness_m`: a ray from the centroid along the inward normal (left-
/// hand of the right-hand winding's outward one) meets another triangle within that
/// distance. On a head, the ears (and the insides of the mouth and eye sockets, which the
/// face takes too). With `only` (one flag per triangle), only the flagged ones are tested.
std::vector<uint8_t> thin_triangles(const Points3f& body_vertices,
                                    const Triangles3i& body_triangles, double neck_y,
                                    double max_thickness_m,
                                    const std::vector<uint8_t>* only = nullptr);

}  // namespace hair
