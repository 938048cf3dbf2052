// KernelReach: how far a splat kernel reaches from its centre, across the view and in depth.
// The culling, the slab partition, the occlusion box and the quad-pass decision all ask it;
// shaders/kernel_reach.glsl mirrors it line for line and a render test holds the two equal.
#pragma once

#include <cmath>
#include <glm/vec3.hpp>

#include "core/camera.h"
#include "core/ewa_footprint.h"

namespace ewa {

struct KernelReach {
  double cutoff = 4.0;  // footprint cutoff r = dx^T Q dx: the ellipsoid r <= cutoff
  // Depth extent in squared standard deviations: the slab partition lists a kernel in the slabs
  // within sqrt(depthCutoff) sigma of its centre (at most the cutoff; see DepthProfile).
  double depthCutoff = 4.0;
  double maxSigma = 1.0;     // largest standard deviation of a kernel: kernel width * spacing
  double swanSpacing = 1.0;  // Swan's s (FootprintParams::swanSpacing): kernel width * spacing
  bool swan = false;
  bool orthographic = false;
  double focalPixels = 1.0;    // perspective: pixels per world unit at depth 1
  double pixelsPerUnit = 1.0;  // orthographic: pixels per world unit
};

// The reach of every kernel of a volume with this spacing under `filter`, `cutoff` and
// `kernelWidth` (kernelSigma), seen through `proj`; in depth min(cutoff, depthCutoff).
KernelReach kernelReach(const Projection& proj, FilterMode filter, double cutoff,
                        const glm::dvec3& spacing, double kernelWidth = 1.0,
                        double depthCutoff = INFINITY);

// World units one pixel spans at camera depth `depth` (along the view axis).
double worldPerPixel(const KernelReach& k, double depth);
// Swan's stretch of a kernel at `depth`: pixel size over s once above 1 (1 for other filters).
double reachStretch(const KernelReach& k, double depth);
// World radius around a kernel centred at `depth` beyond which it draws no pixel: the cutoff
// ellipsoid (stretched by Swan's filter) grown by the low-pass filter's cutoff radius.
double worldReach(const KernelReach& k, double depth);
// Half extent in camera depth of a kernel at `depth` whose depth variance (camera-space
// covariance zz) is `depthVariance`: sqrt(depthCutoff * variance), stretched by Swan's filter.
double depthReach(const KernelReach& k, double depthVariance, double depth);
// A bound on the pixel radius of the footprint of a kernel centred at `depth` anywhere in the
// view of `proj`: off-axis kernels stretch by up to 1 + tan^2 of the half-diagonal angle.
double pixelReach(const KernelReach& k, const Projection& proj, double depth);

}  // namespace ewa
