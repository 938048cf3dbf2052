// Conversions between 8-bit PNG images and float images.
#include "io/image_convert.h"

#include <algorithm>
#include <cmath>

namespace ewa {

FloatImage toFloatImage(const Image8& image) {
  FloatImage out(image.width, image.height, image.channels);
  for (size_t i = 0; i < out.values.size() && i < image.pixels.size(); ++i)
    out.values[i] = float(image.pixels[i]) / 255.0f;
  return out;
}

Image8 toImage8(const FloatImage& image) {
  Image8 out;
  out.width = image.width;
  out.height = image.height;
  out.channels = image.channels == 4 ? 4 : 3;
  out.pixels.resize(size_t(out.width) * out.height * out.channels);
  for (size_t p = 0; p < size_t(out.width) * out.height; ++p)
    for (int c = 0; c < out.channels; ++c) {
      const int src = image.channels == 1 ? 0 : c;
      const float v = image.values[p * image.channels + src];
      const float clamped = std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f;
      out.pixels[p * out.channels + c] = uint8_t(std::lround(clamped * 255.0f));
    }
  return out;
}

}  // namespace ewa
