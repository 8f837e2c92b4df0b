#pragma once
// The direction of each quad region's rails: what the rails say about it, the mesh's
// conventions learnt from the confident regions, and the passes by which paint, texture,
// height and continuation overrule a decision that rests on one cue.

#include <cstdint>
#include <vector>

#include "hair/extract/extract.h"
#include "hair/extract/region_rails.h"
#include "hair/extract/strand_orientation.h"
#include "hair/geom/triangle_mesh_distance.h"
#include "hair/mesh/patch_rails.h"
#include "hair/mesh/poly_mesh.h"

namespace hair {

/// What the rails of a region say about their direction (see OrientationEvidence).
OrientationEvidence orientation_evidence(const Points3f& vertices,
                                         const std::vector<std::vector<int32_t>>& rails,
                                         const EdgeFamily& along_family,
                                         const TriangleMeshDistance& head_distance,
                                         const ExtractParams& params);

/// Whether a region's direction rests on geometry alone, which the hair running on
/// through its ends may overrule: its vertex ids with the head distance silent, or its
/// head distance (with the height, or without it) against ids that agree among
/// themselves. A braid's pieces weave towards and away from the head and tilt as they
/// cross, so off the head their distance and height mislead; turned, such a piece
/// follows its ids and the pieces before and after it.
bool decided_by_one_cue(const RegionRails& region, const OrientationThresholds& thresholds);

/// Decides every region's direction: confident regions first, then continuation from
/// decided neighbours, then the mesh's conventions for the rest.
void decide_directions(const Points3f& vertices, std::vector<RegionRails>& regions,
                       const OrientationThresholds& thresholds, const ExtractParams& params,
                       double head_height_m, ExtractStats& stats);

}  // namespace hair
