// Conversions between 8-bit PNG images and float images for metrics.
#pragma once

#include "core/image_metrics.h"
#include "io/png_io.h"

namespace ewa {

// Values scaled to [0, 1]; channels kept (3 or 4).
FloatImage toFloatImage(const Image8& image);
// Values clamped to [0, 1] and rounded; 1 channel becomes gray RGB, 4 stay RGBA.
Image8 toImage8(const FloatImage& image);

}  // namespace ewa
