// SlabImageScale: how coarse a slab's image may be. A slab's sums are a sum of the kernels'
// footprints, each a Gaussian at least as wide as its kernel seen from the slab's farthest
// centre; where that is several pixels wide the sums are band-limited far below the pixel grid,
// so the slab is splatted into an image 2 or 4 times coarser (a quarter or a sixteenth of the
// fragments) and the slab pass reads it back bilinearly, classifying at full resolution.
#pragma once

#include "core/camera.h"
#include "core/kernel_reach.h"
#include "core/slab_rect.h"

namespace ewa {

// The coarsest scale a slab image takes (1, 2 or 4 pixels a texel a side).
constexpr int kMaxSlabImageScale = 4;
// A coarser slab image keeps every kernel at least this many texels wide (its smallest screen
// standard deviation, low-pass filter left out): the linear read-back of a Gaussian that wide
// is within 1/(8 sigma^2) = 3.1% of its peak along an axis (an isolated kernel; the sums of
// neighbouring kernels are smoother) and its sampling does not alias. Measured against full
// resolution (README, "Slab image scale"): 1.5 left lines of up to 22 levels along aneurism's
// silhouettes, where a slab's mean value changes fastest; 2 keeps them near 10.
constexpr double kMinSigmaTexels = 2.0;

// The smallest screen standard deviation, in pixels, of a kernel whose smallest world standard
// deviation is `minSigma`, centred at camera depth `depth`: perspective projection only widens
// a kernel off the view axis, so sigma * focal / depth bounds it (sigma * ppu orthographic).
double minFootprintSigma(const KernelReach& reach, double minSigma, double depth);

// The scale of one slab's image: the largest power of two up to kMaxSlabImageScale that keeps
// the footprints of kernels centred no deeper than `farthestCenter` at least kMinSigmaTexels
// texels wide; 1 when none does.
int slabImageScale(const KernelReach& reach, double minSigma, double farthestCenter);

// `proj` seen on an image `scale` times coarser: focal length, pixels per unit and principal
// point divided by the scale, with a border of one texel all round (the bilinear read of the
// picture's edge pixels takes texels beyond it), so picture pixel centre x lies at texel
// coordinate (x / scale + 1) and the image is ceil(width / scale) + 2 texels wide.
Projection scaledProjection(const Projection& proj, int scale);
// Texel coordinate (texel centres at i + 0.5) of picture coordinate `pixel` on that image.
double scaledCoordinate(double pixel, int scale);
// The texels of that image the bilinear reads of `rect`'s pixels take (rounded outwards).
PixelRect scaledRect(const PixelRect& rect, int scale);

}  // namespace ewa
