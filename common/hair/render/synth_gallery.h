#pragma once
// Pictures of synthetic hairstyles (hair/synth): their true strands.

#include <opencv2/core.hpp>
#include <vector>

#include "hair/render/strand_render.h"
#include "hair/synth/synth_model.h"

namespace hair {

/// #points colours of a model's true strands by the style of the hair at each point:
/// normal yellow, fixed brown, short green, braided blue (the paper's Figure 9).
PointColours colours_by_style(const synth::SynthModel& model);

/// The models side by side, two to a row: each as its true strands coloured by stream,
/// then by style, seen from the side and the back, over the body.
///
/// @param models        hairstyles to draw (non-empty)
/// @param body_m        the body they are fitted on, in metres
/// @param view_size_px  size of each square view
cv::Mat synth_gallery(const std::vector<synth::SynthModel>& models, const PolyMesh& body_m,
                      int view_size_px);

}  // namespace hair
