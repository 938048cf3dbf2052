// The shear-warp intermediate image and its warp to the output image.
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/vec4.hpp>
#include <vector>

#include "core/image_metrics.h"

namespace ewa {

// Premultiplied RGBA, row-major, row v at v * width.
struct IntermediateImage {
  int width = 0;
  int height = 0;
  std::vector<glm::vec4> pixels;

  void reset(int w, int h) {
    width = w;
    height = h;
    pixels.assign(size_t(w) * size_t(h), glm::vec4(0.0f));
  }
};

// Backward warp with bilinear interpolation: output pixel (x, y) (y up, centre at +0.5) reads
// the intermediate image at (u, v) where inverseWarp * (x + 0.5, y + 0.5, 1) = (u w, v w, w)
// (projective for perspective views; w = 1 for affine ones); outside it, or where w <= 0 (behind
// the eye), it is transparent.
// Returns premultiplied RGBA, top row first, width x height. Uses `threads` threads.
FloatImage warpImage(const IntermediateImage& image, const glm::dmat3& inverseWarp, int width,
                     int height, int threads);

// Premultiplied RGBA over an opaque background: RGB, top row first.
FloatImage overBackground(const FloatImage& rgba, const glm::dvec3& background);

}  // namespace ewa
