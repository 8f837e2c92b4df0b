#pragma once
// Seeds of the orientation fields from the flow an artist painted on the hair mesh (issue
// 25, point 4: "orientation fields seeded from the painted flow as well as the input
// strands"). Input strands are a card's rails or, on a cap whose rails run across its
// paint, streamlines traced along the paint; either way they are lines a centimetre or so
// apart, and between them the field is interpolated. Where such lines radiate from a point
// (a crown whorl) or turn, the interpolation between them averages directions that differ
// and the grown strands circle (short01's crown). The paint is known on every face: each
// face whose strokes are clear seeds the voxels it covers with its stroke axis, signed by
// the input strands of its own group nearby, so the field follows the paint wherever the
// mesh is.

#include <cstdint>
#include <vector>

#include "hair/core/strand_set.h"
#include "hair/geom/triangle_mesh_distance.h"

namespace hair {

/// Settings of painted_field_seeds().
struct PaintedFieldSeedParams {
  /// Faces are sampled at about this spacing (metres, > 0); each sample is a segment of
  /// half this length along the face's painted axis, so that a voxel of twice this edge
  /// that a face covers gets about one voxel's length of direction, as a strand through it.
  double spacing_m = 0.0025;
  /// A face's axis is signed by the input strands of its own group nearest its centroid,
  /// up to `sign_strands` of them within this distance (metres), each by its segment
  /// nearest the centroid; a face with none is left out...
  double sign_radius_m = 0.015;
  int sign_strands = 3;
  /// ...and so is one where any of them runs across the axis (|cosine| under this: the
  /// paint and the group's strands disagree) or they run along it in opposite senses (a
  /// parting, where a draped card's two halves run apart; a whorl).
  double min_axis_cosine = 0.5;
};

/// The seeds: one two-point strand per sample, strand attribute "group" (int32).
///
/// @param vertices        the hair mesh's vertices (extract.h5 /mesh/vertices)
/// @param triangles       its faces as triangles
/// @param triangle_group  per triangle, its group (-1: none)
/// @param triangle_flow   per triangle, its face's painted axis (unit), or zero where the
///                        face's paint is not clear
/// @param seeding_group   per group, whether its faces seed (the groups whose strands seed
///                        the fields)
/// @param input_strands   extract's strands, root first, strand attribute "group"
/// Deterministic: seeds come in triangle order, samples in a fixed order.
StrandSet painted_field_seeds(const Points3f& vertices, const Triangles3i& triangles,
                              const std::vector<int32_t>& triangle_group,
                              const Points3f& triangle_flow,
                              const std::vector<uint8_t>& seeding_group,
                              const StrandSet& input_strands, const PaintedFieldSeedParams& params);

}  // namespace hair
