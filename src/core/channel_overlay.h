// Channels overlaid as fluorescence is seen: each drawn alone in its colour, the pictures added.
#pragma once

#include <glm/vec3.hpp>
#include <vector>

#include "core/image8.h"
#include "core/transfer_function.h"

namespace ewa {

// The colour channel `channel` of `count` is shown in: magenta and green for two (napari's
// pair, which colour-blind eyes tell apart), else Fiji's composite colours in turn: red,
// green, blue (so RGB data shows its own colours), grey, cyan, magenta, yellow.
glm::dvec3 channelColor(int channel, int count);

// `tf` with every colour point replaced by one point of `rgb`: its opacities say how much of
// the channel's colour each value gives off.
TransferFunction inChannelColor(TransferFunction tf, const glm::dvec3& rgb);

// The overlay of channel pictures drawn alone: each over black (`overBlack`, its premultiplied
// colour C) and, for a background that is not black, over white too (`overWhite`, giving its
// opacity a = 1 - (W - C), the mean of the three components); the colours add, as the light
// of several dyes does, and the background shows through what all of them leave:
// clamp(sum C + background * prod(1 - a)). `overWhite` empty: over black. Throws
// std::invalid_argument when the pictures differ in size or none is given.
Image8 overlayChannels(const std::vector<Image8>& overBlack, const std::vector<Image8>& overWhite,
                       const glm::dvec3& background);

}  // namespace ewa
