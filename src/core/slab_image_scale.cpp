// SlabImageScale: the coarsest slab image a slab's kernels allow (see slab_image_scale.h).
#include "core/slab_image_scale.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace ewa {

double minFootprintSigma(const KernelReach& reach, double minSigma, double depth) {
  if (reach.orthographic) return minSigma * reach.pixelsPerUnit;
  return depth > 0.0 ? minSigma * reach.focalPixels / depth : INFINITY;
}

double slabImageScale(const KernelReach& reach, double minSigma, double farthestCenter) {
  const double sigma = minFootprintSigma(reach, minSigma, farthestCenter);
  if (!(sigma >= kMinSigmaTexels * (1.0 + kSlabImageScaleStep))) return 1.0;  // NaN too
  const double steps = std::floor(sigma / kMinSigmaTexels / kSlabImageScaleStep);
  return std::min(kMaxSlabImageScale, steps * kSlabImageScaleStep);
}

Projection scaledProjection(const Projection& proj, double scale) {
  if (scale <= 1.0) return proj;
  const double s = scale;
  Projection p = proj;
  p.focalPixels = proj.focalPixels / s;
  p.pixelsPerUnit = proj.pixelsPerUnit / s;
  p.principal = proj.principal / s + 1.0;
  p.width = int(std::ceil(double(proj.width) / s)) + 2;
  p.height = int(std::ceil(double(proj.height) / s)) + 2;
  return p;
}

double scaledCoordinate(double pixel, double scale) {
  return scale <= 1.0 ? pixel : pixel / scale + 1.0;
}

PixelRect scaledRect(const PixelRect& rect, double scale) {
  if (rect.empty() || scale <= 1.0) return rect;
  // Pixel centres x0 + 0.5 .. x1 - 0.5 read texels from floor(coordinate - 0.5) to one beyond.
  const auto lo = [&](int v) { return int(std::floor(scaledCoordinate(v + 0.5, scale) - 0.5)); };
  const auto hi = [&](int v) {
    return int(std::floor(scaledCoordinate(v - 0.5, scale) - 0.5)) + 2;
  };
  return {lo(rect.x0), lo(rect.y0), hi(rect.x1), hi(rect.y1)};
}

BlitRects coarseToPictureBlit(int width, int height, double scale) {
  const int steps = int(std::lround(1.0 / kSlabImageScaleStep));
  const int quarters = int(std::lround(scale * steps));
  const int divisor = std::gcd(quarters, steps);
  const int num = quarters / divisor, den = steps / divisor;  // scale = num / den
  const auto span = [&](int pixels) { return (pixels + num - 1) / num * num; };
  const int dx = span(width), dy = span(height);
  return {{1, 1, 1 + dx / num * den, 1 + dy / num * den}, {0, 0, dx, dy}};
}

}  // namespace ewa
