#include "hair/synth/synth_paint.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <random>

#include "hair/core/error.h"

namespace hair::synth {

MeshMaterial painted_hair_material(uint32_t seed, bool fade) {
  const int size = kPaintedTextureSize_px;
  std::mt19937 engine(seed ^ 0x68a1c0deu);
  auto uniform = [&](double lo, double hi) {
    return lo + (hi - lo) * (static_cast<double>(engine()) / 4294967296.0);
  };
  // Per column: a brightness drawn afresh every 3-6 texels (a stroke's width), and a
  // sway of the strokes along the image.
  std::vector<double> column_level(static_cast<size_t>(size));
  for (int x = 0; x < size;) {
    const int width = static_cast<int>(uniform(3, 7));
    const double level = uniform(-1, 1);
    for (int k = 0; k < width && x < size; ++k, ++x) column_level[static_cast<size_t>(x)] = level;
  }
  const double sway_px = uniform(1, 3), sway_period_px = uniform(60, 120);
  cv::Mat image(size, size, CV_8UC4);
  for (int y = 0; y < size; ++y) {
    // Row 0 is v = 1 (the tips).
    const double v = 1.0 - (y + 0.5) / size;
    const double alpha = !fade || v <= kFadeStart_v
                             ? 1.0
                             : 1.0 - (1.0 - kTipAlpha) * (v - kFadeStart_v) / (1.0 - kFadeStart_v);
    const double shift = sway_px * std::sin(2 * std::numbers::pi * y / sway_period_px);
    for (int x = 0; x < size; ++x) {
      const int column = ((x + static_cast<int>(std::lround(shift))) % size + size) % size;
      const double level = 0.45 + 0.25 * column_level[static_cast<size_t>(column)];
      const auto value = [&](double scale) {
        return static_cast<uint8_t>(std::clamp(255.0 * level * scale, 0.0, 255.0));
      };
      image.at<cv::Vec4b>(y, x) = {value(0.55), value(0.8), value(1.0),
                                   static_cast<uint8_t>(std::lround(255 * alpha))};
    }
  }
  MeshMaterial material;
  material.name = "hair";
  std::vector<uint8_t> encoded;
  if (!cv::imencode(".png", image, encoded))
    throw Error::runtime("painted_hair_material", "OpenCV cannot encode a PNG");
  material.diffuse.encoded = std::move(encoded);
  return material;
}

}  // namespace hair::synth
