// Warp of the intermediate image to the output, and compositing over the background.
#include "core/intermediate_image.h"

#include <algorithm>
#include <cmath>
#include <thread>

namespace ewa {

namespace {

// Texel (u, v), transparent outside the image.
glm::vec4 texel(const IntermediateImage& img, int u, int v) {
  if (u < 0 || v < 0 || u >= img.width || v >= img.height) return glm::vec4(0.0f);
  return img.pixels[size_t(v) * img.width + u];
}

void warpRows(const IntermediateImage& img, const glm::dmat3& inv, FloatImage& out, int first,
              int step) {
  // Projective: along a row the homogeneous (u w, v w, w) advances by the inverse's first
  // column; w is 1 for the affine warps of parallel views.
  const glm::dvec3 along = inv[0];
  for (int row = first; row < out.height; row += step) {
    const double y = out.height - 1 - row + 0.5;  // row 0 is the top
    const glm::dvec3 start = inv * glm::dvec3(0.5, y, 1.0);
    float* dst = &out.at(0, row, 0);
    for (int x = 0; x < out.width; ++x, dst += 4) {
      const glm::dvec3 h = start + along * double(x);
      if (!(h.z > 0.0)) continue;  // behind the eye, or a zero warp: nothing
      const double uu = h.x / h.z, vv = h.y / h.z;
      const double fu = std::floor(uu), fv = std::floor(vv);
      if (!(fu >= -1.0 && fv >= -1.0 && fu < img.width && fv < img.height)) continue;
      const int u = int(fu), v = int(fv);
      const float wu = float(uu - fu), wv = float(vv - fv);
      glm::vec4 c;
      if (u >= 0 && v >= 0 && u + 1 < img.width && v + 1 < img.height) {
        const glm::vec4* p = &img.pixels[size_t(v) * img.width + u];
        c = (p[0] * (1.0f - wu) + p[1] * wu) * (1.0f - wv) +
            (p[img.width] * (1.0f - wu) + p[img.width + 1] * wu) * wv;
      } else {
        c = (texel(img, u, v) * (1.0f - wu) + texel(img, u + 1, v) * wu) * (1.0f - wv) +
            (texel(img, u, v + 1) * (1.0f - wu) + texel(img, u + 1, v + 1) * wu) * wv;
      }
      dst[0] = c.r;
      dst[1] = c.g;
      dst[2] = c.b;
      dst[3] = c.a;
    }
  }
}

}  // namespace

FloatImage warpImage(const IntermediateImage& image, const glm::dmat3& inverseWarp, int width,
                     int height, int threads) {
  FloatImage out(width, height, 4, 0.0f);
  if (image.width == 0 || image.height == 0) return out;
  threads = std::max(1, threads);
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t)
    pool.emplace_back(warpRows, std::cref(image), std::cref(inverseWarp), std::ref(out), t,
                      threads);
  warpRows(image, inverseWarp, out, 0, threads);
  for (std::thread& th : pool) th.join();
  return out;
}

FloatImage overBackground(const FloatImage& rgba, const glm::dvec3& background) {
  FloatImage out(rgba.width, rgba.height, 3);
  for (int y = 0; y < rgba.height; ++y)
    for (int x = 0; x < rgba.width; ++x) {
      const float a = rgba.at(x, y, 3);
      for (int c = 0; c < 3; ++c)
        out.at(x, y, c) = rgba.at(x, y, c) + (1.0f - a) * float(background[c]);
    }
  return out;
}

}  // namespace ewa
