#pragma once
// The truth's dense strands of a synthetic hairstyle: strands along each stream, and
// strands rooted on the scalp under cards that stand off the head.

#include <cstdint>
#include <vector>

#include "hair/core/strand_set.h"
#include "hair/synth/synth_head.h"
#include "hair/synth/synth_model.h"
#include "hair/synth/synth_rng.h"
#include "hair/synth/synth_stream.h"

namespace hair::synth {

/// Dense true strands of a stream: `count` strands at fixed places across the stream's
/// width and thickness (a third of its width; on the scalp: from half to 1.5 times its
/// lift; a tube: over its round section), following its centre; the style of every point is
/// appended to `point_style`.
void add_true_strands(const Stream& stream, int32_t stream_id, const Head& head, int count,
                      Rng& rng, std::vector<Points3f>& polylines,
                      std::vector<int32_t>& strand_stream, std::vector<HairStyle>& point_style);

/// True strands rooted on the scalp under `stream` (ComponentSpec::rooted_under_volume). A
/// root's place along the stream, s0, is drawn evenly over the stretches whose foot (the body
/// point nearest them, `lift_m` out) lies on the scalp above the hairline; its place across the
/// stream's width and thickness as add_true_strands() draws one. The strand leaves the foot
/// of that place at s0 and rises to the place itself over twice its height there (each point
/// the smoothstep blend of the card point and its foot, so that it leaves the scalp along the
/// card), then runs on along the stream to its (trimmed) tip. `count` strands for a stream
/// over the scalp all along, in proportion for one over it on part of its length.
void add_true_strands_under_volume(const Stream& stream, int32_t stream_id, const Head& head,
                                   int count, double lift_m, Rng& rng,
                                   std::vector<Points3f>& polylines,
                                   std::vector<int32_t>& strand_stream,
                                   std::vector<HairStyle>& point_style);

}  // namespace hair::synth
