// KernelReach (src/core/kernel_reach.h) on values worked by hand; tests/render/kernel_reach_test
// holds the GLSL mirror equal to it.
#include "core/kernel_reach.h"

#include <gtest/gtest.h>

namespace ewa {
namespace {

// The C++ reach itself, on values worked by hand: what the slab partition and the culling use.
TEST(KernelReach, WorkedValues) {
  Projection proj;
  proj.focalPixels = 200.0;
  proj.width = 300;
  proj.height = 400;
  const KernelReach ewa = kernelReach(proj, FilterMode::Ewa, 4.0, glm::dvec3(0.5, 1.0, 2.0));
  EXPECT_DOUBLE_EQ(ewa.maxSigma, 2.0);
  EXPECT_DOUBLE_EQ(ewa.swanSpacing, 0.5);
  // Narrower kernels reach less: sigma = kernel width * spacing.
  EXPECT_DOUBLE_EQ(
      kernelReach(proj, FilterMode::Ewa, 4.0, glm::dvec3(0.5, 1.0, 2.0), 0.55).maxSigma, 1.1);
  EXPECT_DOUBLE_EQ(
      kernelReach(proj, FilterMode::Ewa, 4.0, glm::dvec3(0.5, 1.0, 2.0), 0.55).swanSpacing, 0.275);
  // At depth 100 a pixel spans 0.5: reach 2 * (2 * 1 + 0.5) = 5; depth reach 2 * sqrt(2.25).
  EXPECT_DOUBLE_EQ(worldReach(ewa, 100.0), 5.0);
  EXPECT_DOUBLE_EQ(depthReach(ewa, 2.25, 100.0), 3.0);
  // Pixel bound: 5 world units at 2 px a unit, times 1 + (300^2 + 400^2) / (4 * 200^2).
  EXPECT_DOUBLE_EQ(pixelReach(ewa, proj, 100.0), 10.0 * (1.0 + 250000.0 / 160000.0));
  // Swan stretches once a pixel (depth / 200) is wider than s = 0.5: by 2 at depth 200.
  const KernelReach swan = kernelReach(proj, FilterMode::Swan, 4.0, glm::dvec3(0.5, 1.0, 2.0));
  EXPECT_DOUBLE_EQ(reachStretch(swan, 50.0), 1.0);
  EXPECT_DOUBLE_EQ(reachStretch(swan, 200.0), 2.0);
  EXPECT_DOUBLE_EQ(worldReach(swan, 200.0), 2.0 * (2.0 * 2.0 + 1.0));
  EXPECT_DOUBLE_EQ(depthReach(swan, 2.25, 200.0), 6.0);
  // A depth cutoff of 1 lists a kernel one sigma either side: depth reach sqrt(2.25); it never
  // reaches beyond the footprint's cutoff.
  const KernelReach cut =
      kernelReach(proj, FilterMode::Ewa, 4.0, glm::dvec3(0.5, 1.0, 2.0), 1.0, 1.0);
  EXPECT_DOUBLE_EQ(depthReach(cut, 2.25, 100.0), 1.5);
  EXPECT_DOUBLE_EQ(worldReach(cut, 100.0), 5.0);  // across the view: unchanged
  EXPECT_DOUBLE_EQ(kernelReach(proj, FilterMode::Ewa, 4.0, glm::dvec3(1.0), 1.0, 9.0).depthCutoff,
                   4.0);
}

}  // namespace
}  // namespace ewa
