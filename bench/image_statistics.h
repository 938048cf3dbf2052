// Region statistics for the filter-quality benchmark: flicker, contrast and signal gain.
#pragma once

#include <vector>

#include "core/image_metrics.h"

namespace ewa {

// A pixel mask, one byte a pixel (nonzero = in the region), row-major, top row first.
using PixelMask = std::vector<unsigned char>;

size_t maskCount(const PixelMask& mask);

// Mean over the masked pixels (and all channels) of |a - b|. 0 for an empty mask.
// Throws std::invalid_argument when sizes differ.
double meanAbsoluteDifference(const FloatImage& a, const FloatImage& b, const PixelMask& mask);

// RMS contrast: the standard deviation of the luminance over the masked pixels.
double rmsContrast(const FloatImage& image, const PixelMask& mask);

// How much of the reference's luminance variation `image` keeps over the region: the
// least-squares slope of image against reference, cov(image, ref) / var(ref). 1 when the
// image follows the reference, below 1 when it is blurred (flattened); noise uncorrelated with
// the reference (aliasing) does not raise it, unlike the RMS contrast. 0 when var(ref) is 0.
double signalGain(const FloatImage& image, const FloatImage& reference, const PixelMask& mask);

}  // namespace ewa
