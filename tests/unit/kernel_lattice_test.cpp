// The ripple of a lattice of windowed kernels as a function of kernel width and cutoff: the
// measurement behind --kernel-width's range and default (docs/rendering.md, "Kernel width").
#include "core/kernel_lattice.h"

#include <gtest/gtest.h>

#include "core/ewa_footprint.h"

namespace ewa {
namespace {

TEST(KernelLattice, WideKernelsSumToAFlatUnitMedium) {
  for (double cutoff : {4.0, 6.0, 9.0}) {
    const LatticeRipple r = latticeRipple(1.0, cutoff);
    EXPECT_NEAR(r.mean, 1.0, 1e-3) << "cutoff " << cutoff;
    EXPECT_LT(r.ripple, 0.01) << "cutoff " << cutoff;
  }
}

TEST(KernelLattice, NarrowKernelsShowTheGrid) {
  // sigma = half a voxel leaves the voxels as separate blobs: tens of percent.
  EXPECT_GT(latticeRipple(0.5, 4.0).ripple, 0.5);
  EXPECT_GT(latticeRipple(0.6, 4.0).ripple, 0.1);
  // A wider cutoff keeps more of the Gaussian: less ripple at the same width.
  EXPECT_LT(latticeRipple(0.6, 9.0).ripple, latticeRipple(0.6, 4.0).ripple);
}

TEST(KernelLattice, LowPassFilterSmoothsTheLattice) {
  // Minified (one voxel per pixel or less) the EWA filter adds a variance of a pixel.
  EXPECT_LT(latticeRipple(0.6, 4.0, 1.0).ripple, 0.01);
}

TEST(KernelLattice, TheLowPassFilterKeepsTheOnePixelLatticeSmooth) {
  // Minified kernels (width 0 in pixels) are the low-pass filter alone: at cutoff 5 the
  // paper's variance 1 keeps the one-pixel lattice's ripple under 0.2% (measured 0.12%), 0.5
  // under 1% (0.16%), 0.45 not (1.7%).
  EXPECT_LT(latticeRipple(0.0, 5.0, 1.0).ripple, 0.002);
  EXPECT_LT(latticeRipple(0.0, 5.0, 0.5).ripple, 0.01);
  EXPECT_GT(latticeRipple(0.0, 5.0, 0.45).ripple, 0.01);
  EXPECT_GT(latticeRipple(0.0, 5.0, 0.4).ripple, 0.05);
}

TEST(KernelLattice, NarrowestWidthUnderOnePercent) {
  // Measured: the ripple oscillates with the window's cut; these are the widths from which on
  // it stays under 1%.
  EXPECT_NEAR(narrowestSmoothWidth(4.0, 0.01), 0.85, 0.026);
  EXPECT_NEAR(narrowestSmoothWidth(6.0, 0.01), 0.70, 0.026);
  EXPECT_LT(narrowestSmoothWidth(9.0, 0.01), 0.75);
  EXPECT_GT(latticeRipple(0.80, 4.0).ripple, 0.01);  // just under 0.85 the grid shows
}

}  // namespace
}  // namespace ewa
