#include "hair/style/hair_style.h"

namespace hair {

const char* hair_style_name(HairStyle style) {
  switch (style) {
    case HairStyle::normal:
      return "normal";
    case HairStyle::fixed:
      return "fixed";
    case HairStyle::short_hair:
      return "short";
    case HairStyle::braided:
      return "braided";
  }
  return "unknown";
}

std::optional<HairStyle> hair_style_from_name(std::string_view name) {
  for (HairStyle style :
       {HairStyle::normal, HairStyle::fixed, HairStyle::short_hair, HairStyle::braided})
    if (name == hair_style_name(style)) return style;
  return std::nullopt;
}

std::string hair_style_label_text(int32_t label) {
  if (label >= 0 && label <= 3) return hair_style_name(static_cast<HairStyle>(label));
  return std::to_string(label);
}

}  // namespace hair
