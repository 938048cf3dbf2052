// The EWA splat footprint (Zwicker et al. 2001, sections 4 and 6) as plain C++.
// shaders/ewa_footprint.glsl mirrors these formulas line for line; tests hold them equal.
#pragma once

#include <glm/mat2x2.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/camera.h"

namespace ewa {

enum class FilterMode { Ewa = 0, Plain = 1, Swan = 2 };

const char* filterModeName(FilterMode mode);
// Parses "ewa", "plain" or "swan"; returns false for anything else.
bool parseFilterMode(const std::string& text, FilterMode* mode);
std::vector<std::string> filterModeNames();  // every name parseFilterMode accepts

struct FootprintParams {
  FilterMode filter = FilterMode::Ewa;
  double cutoff = 4.0;      // r = dx^T Q dx is cut off above this
  double minSpacing = 1.0;  // smallest voxel spacing (the near cull and slab units)
  // Swan's s: the smallest kernel standard deviation, kernel width x smallest spacing. Kernels
  // stretch once a pixel is wider than it, so a narrower kernel is stretched to the same screen
  // size a wider one is (at width 1 the voxel spacing, Swan's rule).
  double swanSpacing = 1.0;
  double cullDepth = 1e-3;  // voxels at or closer than this to the eye plane are culled
  // EWA's low-pass filter: its variance in pixels^2 of the image drawn into. One output pixel;
  // 1/s^2 on a slab image s times coarser (slab_image_scale.h), the same filter in the picture.
  double lowPass = 1.0;
};

struct Footprint {
  bool visible = false;
  glm::dvec2 center{0.0};      // pixel coordinates (y up, pixel centers at +0.5)
  glm::dmat2 covariance{1.0};  // screen covariance in pixels^2, low-pass included for EWA
  glm::dmat2 conic{1.0};       // inverse of covariance
  double jacobianDet = 0.0;    // |det J|: pixels^2 per world unit^2 across the ray
  double peak = 0.0;           // weight at the center for unit mass g (window normalized)
  double radius = 0.0;         // half extent in pixels of the ellipse r <= cutoff
  double depth = 0.0;          // distance in front of the eye plane
  double stretch = 1.0;        // Swan's d/k (1 for the other filters)
  // The kernel along the ray through pixel center + dx, as a 1D Gaussian in camera depth (the
  // conditional of the 3D Gaussian in (pixel x, pixel y, depth) given the pixel, low-pass
  // included): mean depth + dot(depthSlope, dx), standard deviation depthSigma.
  glm::dvec2 depthSlope{0.0};
  double depthSigma = 0.0;
};

// Standard deviations of a volume kernel per axis: sigma = kernelWidth * spacing (the paper's
// kernel is kernelWidth 1). Voxels stay at their lattice positions and keep their mass
// tau * sx * sy * sz: a lattice of unit-integral kernels sums to 1 / (sx sy sz) whatever their
// width, up to the ripple of narrow ones (core/kernel_lattice.h).
glm::dvec3 kernelSigma(const glm::dvec3& spacing, double kernelWidth);

// Camera-space covariance W V'' W^T of a kernel with V'' = diag(spacing^2) (pass kernelSigma).
glm::dmat3 cameraCovariance(const glm::dmat3& rotation, const glm::dvec3& spacing);

// Camera-space covariance of a surface splat (EWA paper, section 5): the kernel
// diag(spacing^2) flattened along the unit world normal n in the limit s -> infinity,
// V'' = P diag(spacing^2) P with P = I - n n^T, a 2D Gaussian in the tangent plane.
glm::dmat3 surfaceCovariance(const glm::dmat3& rotation, const glm::dvec3& spacing,
                             const glm::dvec3& normal);

// Mass g of a surface splat so that a layer of them has optical depth `tauSurface` seen along
// its normal: the voxels of an iso-surface's boundary layer (>= iso with a 6-neighbour below)
// have areal density max_i(|n_i| h_i) / (hx hy hz), and each tangent Gaussian integrates to 1.
double surfaceSplatMass(const glm::dvec3& spacing, const glm::dvec3& normal, double tauSurface);

// erf by Abramowitz and Stegun 7.1.28 (|error| < 3e-7; a polynomial, no exp: 7.1.26's exp
// makes frames longer on llvmpipe): the GLSL has no erf, and the C++ uses the same formula so
// the two agree to float rounding.
double erfApprox(double x);
// A kernel's depth profile along a pixel's ray, which splits its ray integral between slabs:
// the Gaussian cut at sqrt(depthCutoff) standard deviations and scaled back to its whole mass.
// Cut where the slab partition stops listing the kernel (KernelReach::depthCutoff), a slab the
// kernel enters or leaves as the view turns holds none of it, so no mass jumps between slabs;
// uncut (an infinite depthCutoff), the first and last slab listed take the Gaussian's tails.
struct DepthProfile {
  double erfReach = 1e30;  // the cut in erf's argument: sqrt(depthCutoff / 2)
  double scale = 1.0;      // 1 / profileErf(erfReach): the cut profile keeps the kernel's mass
};
DepthProfile depthProfile(double depthCutoff);
// Up to this cut in erf's argument (depth cutoffs up to 2 * 0.75^2 = 1.125, the default 1 among
// them) profileErf takes erfSeries, else erfApprox.
constexpr double kErfSeriesReach = 0.75;
// erf on [-kErfSeriesReach, kErfSeriesReach] as an odd polynomial of degree 9 (least-squares
// minimax, |error| < 5e-8 there): five multiply-adds and no division, where erfApprox takes
// ten and a division. The slab split's erf was most of the splat shader's arithmetic.
double erfSeries(double x);
// True where the profile's cut lies within kErfSeriesReach: profileErf takes erfSeries, and the
// splat shaders are compiled with SPLAT_ERF_SERIES.
bool usesErfSeries(const DepthProfile& profile);
// erf of `t` clamped to the profile's cut: the profile's cumulative, unscaled.
double profileErf(double t, const DepthProfile& profile);
// Fraction of a 1D Gaussian (mean mu, standard deviation sigma), cut as `profile` says, between
// depths zNear and zFar; infinite bounds give the open tails. The per-slab share of a kernel's
// ray integral.
double slabFraction(double mu, double sigma, double zNear, double zFar,
                    const DepthProfile& profile = {});
// True when a kernel whose mean depth lies within [mu - spread, mu + spread] over its footprint
// (depth standard deviation sigma, cut as `profile` says) has no share at all between depths
// zNear and zFar (infinite: open tails): slabFraction is exactly 0 at every mean in that range,
// with a margin for the GPU's float rounding. Never with the uncut profile. A slab's two splat
// passes (its front quarters, then its back ones) skip such kernels.
bool depthProfileMisses(double mu, double spread, double sigma, double zNear, double zFar,
                        const DepthProfile& profile);

// True when a kernel of world bounding radius `radius` centred at camera-space point `u` lies
// wholly outside the view (or at or behind the eye): tested before the Jacobian is formed.
bool cullKernel(const glm::dvec3& u, double radius, const Projection& proj,
                const FootprintParams& params);

// The footprint of a kernel centred at camera-space point `u` with camera-space covariance `cov`.
Footprint computeFootprint(const glm::dvec3& u, const glm::dmat3& cov, const Projection& proj,
                           const FootprintParams& params);

// The footprint's radial profile: a Gaussian exp(-r/2) windowed by (1 - r/c)^2, so it falls
// smoothly to zero at the cutoff r = c. A hard cut at c = 4 leaves a step of exp(-2) = 13.5% of
// the peak, which pixel sampling turns into 7% mass errors and 11% ripple in a lattice of
// one-pixel splats; the window brings both under 1% (see docs/rendering.md, "Footprint window").
double windowedGaussian(double r, double cutoff);
// Integral over [0, c] of windowedGaussian(r, c) dr: the footprint's 2D integral is
// pi * sqrt(det covariance) * windowIntegral(c). It tends to 2 (the plain Gaussian) as c grows.
double windowIntegral(double cutoff);

// Side in pixels of a point sprite that holds the ellipse r <= cutoff: twice the larger
// half extent of its bounding box, plus kPointSpriteMargin. GL rasterizes a point as the
// pixels whose centres lie in a square of exactly that side (core profile, no rounding to
// whole pixels); the margin covers a point-size granularity of up to 1/4 pixel. Every pixel
// of the sprite costs a fragment, so the margin is kept small: 0.5 before 2026-11-26, which
// drew about 6% more fragments at the default window view for the same picture.
constexpr double kPointSpriteMargin = 0.125;
double pointSpriteSize(const Footprint& fp, double cutoff);

// Optical depth per unit mass g at pixel position `pixel` (0 outside the cutoff).
double footprintWeight(const Footprint& fp, const glm::dvec2& pixel, double cutoff);

}  // namespace ewa
