// SlabImageScale: how coarse a slab's image may be. A slab's sums are a sum of the kernels'
// footprints, each a Gaussian at least as wide as its kernel seen from the slab's farthest
// centre; where that is several pixels wide the sums are band-limited far below the pixel grid,
// so the slab is splatted into an image up to 4 times coarser (in steps of a quarter: 1.5 times
// coarser draws 1/2.25 of the fragments) and the slab pass reads it back bilinearly, classifying
// at full resolution.
#pragma once

#include "core/camera.h"
#include "core/kernel_reach.h"
#include "core/slab_rect.h"

namespace ewa {

// The coarsest scale a slab image takes (pixels a texel a side), and the steps between scales:
// a slab image is 1, 1.25, 1.5, ... or 4 pixels a texel. A step keeps the number of distinct
// projections a frame sets up small.
constexpr double kMaxSlabImageScale = 4.0;
constexpr double kSlabImageScaleStep = 0.25;
// A coarser slab image keeps every kernel at least this many texels wide (its smallest screen
// standard deviation, low-pass filter left out): the linear read-back of a Gaussian that wide
// is within 1/(8 sigma^2) = 3.1% of its peak along an axis (an isolated kernel; the sums of
// neighbouring kernels are smoother) and its sampling does not alias. Measured against full
// resolution (docs/rendering.md, "Slab image scale"): 1.5 left lines of up to 22 levels along
// aneurism's silhouettes, where a slab's mean value changes fastest; 2 keeps them near 10.
constexpr double kMinSigmaTexels = 2.0;

// A bilinear read-back between texels blurs, on average over where a pixel falls between them,
// like a tent a texel wide along each axis: variance 1/6 texel^2. A kernel splatted into a
// coarser image that much narrower (its low-pass variance less this; the rule above keeps the
// footprint at least 4 texel^2) comes back at its own width: about two thirds of the worst
// error of the read-back and half its mean square (unit test).
constexpr double kBilinearReadVariance = 1.0 / 6.0;

// The smallest screen standard deviation, in pixels, of a kernel whose smallest world standard
// deviation is `minSigma`, centred at camera depth `depth`: perspective projection only widens
// a kernel off the view axis, so sigma * focal / depth bounds it (sigma * ppu orthographic).
double minFootprintSigma(const KernelReach& reach, double minSigma, double depth);

// The scale of one slab's image: the largest multiple of kSlabImageScaleStep up to
// kMaxSlabImageScale that keeps the footprints of kernels centred no deeper than
// `farthestCenter` at least kMinSigmaTexels texels wide; 1 when none above 1 does.
double slabImageScale(const KernelReach& reach, double minSigma, double farthestCenter);

// `proj` seen on an image `scale` times coarser: focal length, pixels per unit and principal
// point divided by the scale, with a border of one texel all round (the bilinear read of the
// picture's edge pixels takes texels beyond it), so picture pixel centre x lies at texel
// coordinate (x / scale + 1) and the image is ceil(width / scale) + 2 texels wide.
Projection scaledProjection(const Projection& proj, double scale);
// Texel coordinate (texel centres at i + 0.5) of picture coordinate `pixel` on that image.
double scaledCoordinate(double pixel, double scale);
// The texels of that image the bilinear reads of `rect`'s pixels take (rounded outwards).
PixelRect scaledRect(const PixelRect& rect, double scale);

// The source (texels of that image) and destination (picture pixels) rectangles of a blit that
// maps picture coordinate x to scaledCoordinate(x, scale), covering a `width` x `height`
// picture (it may reach beyond it). A blit maps its rectangles' integer ends linearly, so the
// destination spans a multiple of the scale's numerator (scale = num / den, a multiple of
// kSlabImageScaleStep) from pixel 0, the source the matching texels from texel 1.
struct BlitRects {
  PixelRect source, destination;
};
BlitRects coarseToPictureBlit(int width, int height, double scale);

}  // namespace ewa
