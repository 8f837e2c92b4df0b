#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace hair {

/// Style of a cluster of strands (paper, section 5.1), which decides how it is simulated
/// (section 5.2). The values are those stored in the pipeline's files.
enum class HairStyle : int8_t {
  normal = 0,      ///< none of the others: mass-spring model
  fixed = 1,       ///< held to the head (hair bands, buns): not simulated
  short_hair = 2,  ///< short strands: mass-spring model with fewer, stiffer particles
  braided = 3,     ///< a braid of several streams: wisp model around the centre strand
};

/// The paper's word for a style: "normal", "fixed", "short", "braided"; "unknown" for a
/// value outside the enumeration.
const char* hair_style_name(HairStyle style);

/// The word of a class label (a HairStyle value) in a report, or the label's number for
/// one outside the styles.
std::string hair_style_label_text(int32_t label);

/// The style named by one of hair_style_name()'s words; nullopt for any other text.
std::optional<HairStyle> hair_style_from_name(std::string_view name);

}  // namespace hair
