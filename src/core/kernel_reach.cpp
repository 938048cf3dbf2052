// KernelReach: the one formula for how far a kernel reaches (see kernel_reach.h).
#include "core/kernel_reach.h"

#include <algorithm>
#include <cmath>

namespace ewa {

KernelReach kernelReach(const Projection& proj, FilterMode filter, double cutoff,
                        const glm::dvec3& spacing, double kernelWidth, double depthCutoff) {
  KernelReach k;
  k.cutoff = cutoff;
  k.depthCutoff = std::min(cutoff, depthCutoff);
  k.maxSigma = kernelWidth * std::max({spacing.x, spacing.y, spacing.z});
  k.swanSpacing = kernelWidth * std::min({spacing.x, spacing.y, spacing.z});
  k.swan = filter == FilterMode::Swan;
  k.orthographic = proj.orthographic;
  k.focalPixels = proj.focalPixels;
  k.pixelsPerUnit = proj.pixelsPerUnit;
  return k;
}

double worldPerPixel(const KernelReach& k, double depth) {
  return k.orthographic ? 1.0 / k.pixelsPerUnit : std::max(depth, 0.0) / k.focalPixels;
}

double reachStretch(const KernelReach& k, double depth) {
  return k.swan ? std::max(1.0, worldPerPixel(k, depth) / k.swanSpacing) : 1.0;
}

double worldReach(const KernelReach& k, double depth) {
  return std::sqrt(k.cutoff) * (k.maxSigma * reachStretch(k, depth) + worldPerPixel(k, depth));
}

double depthReach(const KernelReach& k, double depthVariance, double depth) {
  return std::sqrt(k.depthCutoff * depthVariance) * reachStretch(k, depth);
}

double pixelReach(const KernelReach& k, const Projection& proj, double depth) {
  if (k.orthographic) return worldReach(k, depth) * k.pixelsPerUnit;
  const double t2 = (double(proj.width) * proj.width + double(proj.height) * proj.height) /
                    (4.0 * k.focalPixels * k.focalPixels);
  const double d = std::max(depth, 1e-9);
  return worldReach(k, d) * k.focalPixels / d * (1.0 + t2);
}

}  // namespace ewa
