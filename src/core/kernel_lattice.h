// Ripple of a lattice of windowed Gaussian kernels: how narrow kernels may get before a
// homogeneous medium shows the voxel grid.
#pragma once

namespace ewa {

// The narrowest and widest kernel widths the renderer accepts (sigma = width * spacing).
constexpr double kMinKernelWidth = 0.3;
constexpr double kMaxKernelWidth = 2.0;

struct LatticeRipple {
  double ripple = 0.0;  // (max - min) / mean of the lattice sum
  double mean = 0.0;    // 1 for kernels of unit integral on a unit lattice
};

// The sum over a square lattice of unit spacing of 2D footprints exp(-r/2)(1 - r/c)^2, r =
// |x - m|^2 / (width^2 + lowPass), normalized to unit integral as the renderer normalizes them,
// sampled on a (samples+1)^2 grid over one lattice cell (voxel centres and the points between
// them). A medium seen head-on along a lattice axis is this sum: the depth direction is
// integrated exactly (slab shares of the 1D Gaussian), and oblique views project the 3D
// lattice onto a denser 2D one, so this is the worst case. `lowPass` is the EWA filter's
// variance in voxels^2 (0 for a magnified view, the close-up case).
LatticeRipple latticeRipple(double width, double cutoff, double lowPass = 0.0, int samples = 32);

// The narrowest width in [kMinKernelWidth, kMaxKernelWidth], on a grid of `step`, from which on
// the ripple stays below `limit` for every wider width on the grid (the ripple is not
// monotonic: the window's cut makes it oscillate). kMaxKernelWidth when none is.
double narrowestSmoothWidth(double cutoff, double limit, double step = 0.05);

}  // namespace ewa
