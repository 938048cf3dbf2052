// overlayChannels: the additive overlay of channel pictures, and the channels' colours.
#include "core/channel_overlay.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <stdexcept>

namespace ewa {

glm::dvec3 channelColor(int channel, int count) {
  if (count == 2) return channel % 2 == 0 ? glm::dvec3(1, 0, 1) : glm::dvec3(0, 1, 0);
  static const glm::dvec3 kCycle[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1},
                                      {0, 1, 1}, {1, 0, 1}, {1, 1, 0}};
  return kCycle[size_t(std::max(channel, 0)) % 7];
}

TransferFunction inChannelColor(TransferFunction tf, const glm::dvec3& rgb) {
  const double value = tf.color.empty() ? 0.0 : tf.color.front().value;
  tf.color = {ColorPoint{value, glm::clamp(rgb, 0.0, 1.0)}};
  return tf;
}

Image8 overlayChannels(const std::vector<Image8>& overBlack, const std::vector<Image8>& overWhite,
                       const glm::dvec3& background) {
  if (overBlack.empty()) throw std::invalid_argument("overlay: no channel pictures");
  const Image8& first = overBlack.front();
  const auto sameSize = [&](const Image8& i) {
    return i.width == first.width && i.height == first.height && i.channels == first.channels &&
           i.pixels.size() == first.pixels.size();
  };
  const bool white = !overWhite.empty();
  if (!std::all_of(overBlack.begin(), overBlack.end(), sameSize) ||
      (white && (overWhite.size() != overBlack.size() ||
                 !std::all_of(overWhite.begin(), overWhite.end(), sameSize))))
    throw std::invalid_argument("overlay: channel pictures of different sizes");
  Image8 out = first;
  const size_t n = size_t(first.width) * size_t(first.height), step = size_t(first.channels);
  const double bg[3] = {background.x, background.y, background.z};
  for (size_t p = 0; p < n; ++p) {
    double sum[3] = {0, 0, 0}, through = 1.0;  // through: the share of the background seen
    for (size_t c = 0; c < overBlack.size(); ++c) {
      const uint8_t* b = &overBlack[c].pixels[p * step];
      double w = 0.0;
      for (int k = 0; k < 3; ++k) {
        sum[k] += b[k];
        if (white) w += double(overWhite[c].pixels[p * step + size_t(k)]) - b[k];
      }
      if (white) through *= std::clamp(w / (3.0 * 255.0), 0.0, 1.0);  // 1 - a
    }
    for (int k = 0; k < 3; ++k) {
      const double v = sum[k] + (white ? 255.0 * bg[k] * through : 0.0);
      out.pixels[p * step + size_t(k)] = uint8_t(std::lround(std::clamp(v, 0.0, 255.0)));
    }
    if (step == 4) out.pixels[p * step + 3] = 255;
  }
  return out;
}

}  // namespace ewa
