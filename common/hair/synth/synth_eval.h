#pragma once
// Measuring a stage against the truth of a synthetic hairstyle (synth_model.h).

#include <array>
#include <cstdint>
#include <vector>

#include "hair/extract/extract.h"
#include "hair/synth/synth_model.h"

namespace hair::synth {

/// The patch each extract group was read from, by the vertices of the group's faces
/// (the mesh must be the model's, read keeping its vertex order): #groups patch ids,
/// -1 for a group whose faces span patches.
std::vector<int32_t> group_patches(const SynthModel& model, const ExtractResult& extract);

/// How extract oriented a group against the truth.
enum class GroupOrientation : int8_t {
  root_to_tip = 0,  ///< most strands run root to tip along the stream
  tip_to_root = 1,  ///< most run the wrong way
  across = 2,       ///< most were read across the hair (both ends at one arc length)
};

/// The orientation of every group by majority of its strands (#groups); groups
/// without a patch count as `across`.
std::vector<GroupOrientation> group_orientations(const SynthModel& model,
                                                 const ExtractResult& extract,
                                                 const std::vector<int32_t>& patch_of_group);

}  // namespace hair::synth
