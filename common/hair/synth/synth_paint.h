#pragma once
// The painted texture of a synthetic hair mesh, as artists paint hair cards: fine strokes
// along the hair and an alpha that fades out towards the tips, so that the paths that read
// the paint (extract/painted_flow.h) are checked against truth.

#include <cstdint>

#include "hair/mesh/mesh_material.h"

namespace hair::synth {

/// Side of the painted image, texels.
inline constexpr int kPaintedTextureSize_px = 256;
/// The alpha is 1 up to this texture v and falls linearly to kTipAlpha at v = 1 (the tips:
/// every synthetic patch's v runs from its root, 0, to its tip, 1).
inline constexpr double kFadeStart_v = 0.7;
inline constexpr double kTipAlpha = 0.25;

/// A material "hair" whose diffuse image (RGBA PNG, embedded) shows strokes along the
/// texture's v axis, 3-6 texels apart with a slight sway, varied by `seed`, and an alpha
/// fading towards v = 1; without `fade`, an alpha of 1 all over (a tiled hair texture, as
/// caps are often painted). Deterministic.
MeshMaterial painted_hair_material(uint32_t seed, bool fade = true);

}  // namespace hair::synth
