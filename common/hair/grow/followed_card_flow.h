#pragma once

#include <cstdint>
#include <vector>

#include "hair/core/strand_set.h"
#include "hair/extract/extract_io.h"

namespace hair {

/// How grown strands run along the flow of the card each one follows (hair-grow-report,
/// docs/grow.md). hair-grow-report's "grown along flow" judges every segment against the
/// flow of the nearest face of the hair mesh; where cards cross or interpenetrate (short
/// spiky cards, a braid's locks), a strand that keeps to its own card can lie nearer
/// another, and that measure counts it as off the flow. Here a segment grown along an
/// input strand (`point_rule` 2, input_strand, with `point_group` its group) is judged
/// against the nearest face among its group's own faces (`face_group`); every other
/// segment (along the field, a bridge) against the nearest face of any group, as there.
/// Judged as segments_along_painted_flow() judges: within `max_angle_deg` of the face's
/// flow axis (either sense), faces with coherence under `min_coherence` or farther than
/// `max_distance_m` not judged. Returns the share of the judged segments that run along,
/// and `counted` the segments judged (0: the share is 0). Throws hair::Error (bad input)
/// when the per-face or per-point arrays do not match the mesh or the strands.
double followed_card_flow_agreement(const PolyMesh& mesh, const std::vector<int32_t>& face_group,
                                    const PaintedFlow& flow, const StrandSet& grown,
                                    const std::vector<int32_t>& point_group,
                                    const std::vector<int8_t>& point_rule, double min_coherence,
                                    double max_angle_deg, double max_distance_m, int64_t& counted);

}  // namespace hair
