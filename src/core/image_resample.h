// Gaussian low-pass and decimation of a supersampled image: the benchmark's reference maker.
#pragma once

#include "core/image_metrics.h"

namespace ewa {

// Decimates `fine` (factor x factor samples per output pixel) to an image `factor` times
// smaller after a Gaussian low-pass of standard deviation `sigma` output pixels. Output pixel
// (x, y) is centred on fine coordinate factor * (x + 0.5) (fine pixel i covers [i, i + 1]),
// so the filter is evaluated exactly at output pixel centres. Taps reach 4 sigma; near the
// border the weights inside the image are renormalised. Throws std::invalid_argument when the
// size is not a multiple of `factor` or factor < 1 or sigma <= 0.
FloatImage gaussianDecimate(const FloatImage& fine, int factor, double sigma);

// The central width x height pixels of `image` (offset margin, margin).
FloatImage cropImage(const FloatImage& image, int margin, int width, int height);

}  // namespace ewa
