// The EWA splat footprint: Jacobian of the projection, screen covariance, filters, normalization.
#include "core/ewa_footprint.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/footprint_formulas.h"
#include "core/named_values.h"

namespace ewa {

namespace {
constexpr double kPi = 3.14159265358979323846;
// Smallest screen covariance determinant allowed, so a vanishing plain splat cannot divide by 0.
constexpr double kMinDet = 1e-10;
// Smallest conditional depth variance, relative to the kernel's: keeps erf's argument finite.
constexpr double kMinDepthVariance = 1e-4;
}  // namespace

double windowIntegral(double c) {
  // A0 - 2 A1 / c + A2 / c^2 with An = integral of r^n exp(-r/2) over [0, c].
  const double e = std::exp(-0.5 * c);
  const double a0 = 2.0 * (1.0 - e);
  const double a1 = 4.0 - e * (2.0 * c + 4.0);
  const double a2 = 16.0 - e * (2.0 * c * c + 8.0 * c + 16.0);
  return a0 - 2.0 * a1 / c + a2 / (c * c);
}

double windowedGaussian(double r, double cutoff) {
  return windowedGaussianOf(r, cutoff);
}

namespace {
constexpr NamedValue<FilterMode> kFilterModeNames[] = {
    {FilterMode::Ewa, "ewa"}, {FilterMode::Plain, "plain"}, {FilterMode::Swan, "swan"}};
}  // namespace

const char* filterModeName(FilterMode mode) {
  return nameIn(kFilterModeNames, mode);
}

bool parseFilterMode(const std::string& text, FilterMode* mode) {
  return parseIn(kFilterModeNames, text, mode);
}

std::vector<std::string> filterModeNames() {
  return namesIn(kFilterModeNames);
}

glm::dvec3 kernelSigma(const glm::dvec3& spacing, double kernelWidth) {
  return spacing * kernelWidth;
}

glm::dmat3 cameraCovariance(const glm::dmat3& rotation, const glm::dvec3& spacing) {
  const glm::dmat3 v(glm::dvec3(spacing.x * spacing.x, 0, 0),
                     glm::dvec3(0, spacing.y * spacing.y, 0),
                     glm::dvec3(0, 0, spacing.z * spacing.z));
  return rotation * v * glm::transpose(rotation);
}

glm::dmat3 surfaceCovariance(const glm::dmat3& rotation, const glm::dvec3& spacing,
                             const glm::dvec3& n) {
  const glm::dmat3 p = glm::dmat3(1.0) - glm::outerProduct(n, n);
  const glm::dmat3 v(glm::dvec3(spacing.x * spacing.x, 0, 0),
                     glm::dvec3(0, spacing.y * spacing.y, 0),
                     glm::dvec3(0, 0, spacing.z * spacing.z));
  return rotation * (p * v * p) * glm::transpose(rotation);
}

double surfaceSplatMass(const glm::dvec3& h, const glm::dvec3& n, double tauSurface) {
  const double layer = std::max({std::abs(n.x) * h.x, std::abs(n.y) * h.y, std::abs(n.z) * h.z});
  return tauSurface * h.x * h.y * h.z / std::max(layer, 1e-6 * std::min({h.x, h.y, h.z}));
}

double erfApprox(double x) {
  return erfApproxOf(x);
}

double erfSeries(double x) {
  return erfSeriesOf(x);
}

bool usesErfSeries(const DepthProfile& profile) {
  return profile.erfReach <= kErfSeriesReach;
}

double profileErf(double t, const DepthProfile& profile) {
  return profileErfOf(t, profile.erfReach, usesErfSeries(profile));
}

DepthProfile depthProfile(double depthCutoff) {
  DepthProfile p;
  if (!(depthCutoff > 0.0) || std::isinf(depthCutoff)) return p;  // uncut
  p.erfReach = std::sqrt(0.5 * depthCutoff);
  p.scale = 1.0 / profileErf(p.erfReach, p);
  return p;
}

double slabFraction(double mu, double sigma, double zNear, double zFar,
                    const DepthProfile& profile) {
  const double s = 1.0 / (std::sqrt(2.0) * sigma);
  // Infinite bounds clamp to the cut: the open tails.
  return 0.5 * profile.scale *
         (profileErf((zFar - mu) * s, profile) - profileErf((zNear - mu) * s, profile));
}

bool depthProfileMisses(double mu, double spread, double sigma, double zNear, double zFar,
                        const DepthProfile& profile) {
  if (!(profile.erfReach < 1e20)) return false;  // uncut: a Gaussian reaches every depth
  // profileErf clamps beyond +-erfReach, so bounds both beyond the reach on one side give equal
  // values. The margin covers float32 depths of a few thousand units and sigma's rounding.
  const double reach = profile.erfReach * std::sqrt(2.0) * sigma * 1.0001;
  const double margin = 1e-5 * (std::abs(mu) + spread + reach) + 1e-4 * sigma;
  return mu - spread - reach >= zFar + margin || mu + spread + reach <= zNear - margin;
}

bool cullKernel(const glm::dvec3& u, double radius, const Projection& proj,
                const FootprintParams& params) {
  const double depth = -u.z;
  if (depth <= params.cullDepth) return true;
  const double hw = proj.width * 0.5, hh = proj.height * 0.5;
  if (proj.orthographic) {
    const double s = proj.pixelsPerUnit;
    return std::abs(u.x) * s - hw > radius * s || std::abs(u.y) * s - hh > radius * s;
  }
  // Side planes of the view frustum through the eye; outward normals (±f, 0, hw) etc.
  const double f = proj.focalPixels;
  const double nx = 1.0 / std::sqrt(f * f + hw * hw), ny = 1.0 / std::sqrt(f * f + hh * hh);
  return (f * std::abs(u.x) + hw * u.z) * nx > radius ||
         (f * std::abs(u.y) + hh * u.z) * ny > radius;
}

Footprint computeFootprint(const glm::dvec3& u, const glm::dmat3& covIn, const Projection& proj,
                           const FootprintParams& params) {
  Footprint fp;
  fp.depth = -u.z;
  if (!(fp.depth > params.cullDepth)) return fp;
  const double d = fp.depth;
  // Pixels per world unit across the ray at this depth: Swan's sampling rate test.
  const double ppu = proj.orthographic ? proj.pixelsPerUnit : proj.focalPixels / d;
  fp.stretch =
      params.filter == FilterMode::Swan ? std::max(1.0, 1.0 / (ppu * params.swanSpacing)) : 1.0;
  const glm::dmat3 cov = covIn * (fp.stretch * fp.stretch);

  // First two rows of the Jacobian J of camera space -> (pixel x, pixel y, distance along ray).
  glm::dvec3 j0, j1;
  if (proj.orthographic) {
    j0 = glm::dvec3(ppu, 0.0, 0.0);
    j1 = glm::dvec3(0.0, ppu, 0.0);
    fp.jacobianDet = ppu * ppu;
    fp.center = proj.principal + glm::dvec2(u.x, u.y) * ppu;
  } else {
    const double f = proj.focalPixels;
    j0 = glm::dvec3(f / d, 0.0, f * u.x / (d * d));
    j1 = glm::dvec3(0.0, f / d, f * u.y / (d * d));
    // The third row is u/|u|; expanding the determinant gives f^2 |u| / d^3.
    fp.jacobianDet = f * f * glm::length(u) / (d * d * d);
    fp.center = proj.principal + glm::dvec2(u.x, u.y) * (f / d);
  }
  // V^ = upper 2x2 of J V J^T.
  const glm::dvec3 c0 = cov * j0, c1 = cov * j1;
  double a = glm::dot(j0, c0), b = glm::dot(j0, c1), c = glm::dot(j1, c1);
  if (params.filter == FilterMode::Ewa) {
    a += params.lowPass;  // the one-pixel Gaussian low-pass filter
    c += params.lowPass;
  }
  const double det = std::max(a * c - b * b, kMinDet);
  fp.covariance = glm::dmat2(a, b, b, c);
  fp.conic = glm::dmat2(c / det, -b / det, -b / det, a / det);
  fp.peak = fp.jacobianDet / (kPi * std::sqrt(det) * windowIntegral(params.cutoff));
  const double lambdaMax = 0.5 * (a + c) + std::sqrt(0.25 * (a - c) * (a - c) + b * b);
  fp.radius = std::sqrt(params.cutoff * lambdaMax);
  // Depth is -u.z, so its row of the Jacobian is (0, 0, -1): covariances with the screen axes
  // are -c0.z and -c1.z, and the depth variance is cov[2][2]. Conditioning on the pixel offset
  // shifts the mean by conic * v and leaves the variance cov22 - v . conic v (floored, for the
  // flat kernels of surface splats).
  const glm::dvec2 v(-c0.z, -c1.z);
  fp.depthSlope = fp.conic * v;
  const double var = cov[2][2] - glm::dot(v, fp.depthSlope);
  fp.depthSigma = std::sqrt(std::max(var, kMinDepthVariance * cov[2][2] + 1e-20));
  fp.visible = std::isfinite(fp.peak) && std::isfinite(fp.radius);
  return fp;
}

double pointSpriteSize(const Footprint& fp, double cutoff) {
  const double extent = std::max(fp.covariance[0][0], fp.covariance[1][1]);
  return 2.0 * std::sqrt(cutoff * extent) + kPointSpriteMargin;
}

double footprintWeight(const Footprint& fp, const glm::dvec2& pixel, double cutoff) {
  if (!fp.visible) return 0.0;
  const glm::dvec2 dx = pixel - fp.center;
  const double r = glm::dot(dx, fp.conic * dx);
  return fp.peak * windowedGaussian(r, cutoff);
}

}  // namespace ewa
