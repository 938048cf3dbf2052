// Unit tests of the slab split (erf, conditional depth Gaussian), surface-splat kernels,
// per-splat attributes, gradients and surface classification.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>
#include <random>
#include <vector>

#include "core/camera.h"
#include "core/ewa_footprint.h"
#include "core/shading.h"
#include "core/splat_attributes.h"

namespace ewa {
namespace {

TEST(SlabMath, ErfApproximationIsWithinItsBound) {
  // A&S 7.1.28's bound is 3e-7; over this grid the largest error is 2.6e-7, near x = 0.2.
  double worst = 0.0;
  for (double x = -6.0; x <= 6.0; x += 0.001) {
    EXPECT_NEAR(erfApprox(x), std::erf(x), 3e-7) << x;
    worst = std::max(worst, std::abs(erfApprox(x) - std::erf(x)));
  }
  EXPECT_GT(worst, 1e-7);  // the approximation, not std::erf, is what is tested
  EXPECT_EQ(erfApprox(0.0), 0.0);
  EXPECT_EQ(erfApprox(40.0), 1.0);
  EXPECT_EQ(erfApprox(-1e30), -1.0);
}

TEST(SlabMath, ErfSeriesIsWithinItsBoundInsideItsReach) {
  double worst = 0.0;
  for (double x = -kErfSeriesReach; x <= kErfSeriesReach; x += 1e-4) {
    EXPECT_NEAR(erfSeries(x), std::erf(x), 5e-8) << x;
    EXPECT_EQ(erfSeries(-x), -erfSeries(x));  // odd: shares either side of a kernel agree
    worst = std::max(worst, std::abs(erfSeries(x) - std::erf(x)));
  }
  EXPECT_GT(worst, 1e-9);  // the polynomial, not std::erf, is what is tested
  // Beyond its reach the series leaves erf quickly: profileErf takes erfApprox there.
  EXPECT_GT(std::abs(erfSeries(2.0) - std::erf(2.0)), 1e-3);
  const DepthProfile wide = depthProfile(4.0), narrow = depthProfile(1.0);
  EXPECT_FALSE(usesErfSeries(wide));
  EXPECT_TRUE(usesErfSeries(narrow));
  EXPECT_EQ(profileErf(0.3, wide), erfApprox(0.3));
  EXPECT_EQ(profileErf(0.3, narrow), erfSeries(0.3));
  EXPECT_EQ(profileErf(5.0, narrow), erfSeries(narrow.erfReach));  // clamped to the cut
  EXPECT_DOUBLE_EQ(profileErf(narrow.erfReach, narrow) * narrow.scale, 1.0);
}

TEST(SlabMath, SlabSharesOfAKernelSumToOne) {
  const double mu = 3.3, sigma = 0.7;
  double sum = slabFraction(mu, sigma, -INFINITY, 1.0) + slabFraction(mu, sigma, 5.0, INFINITY);
  for (double z = 1.0; z < 5.0; z += 0.25) sum += slabFraction(mu, sigma, z, z + 0.25);
  EXPECT_NEAR(sum, 1.0, 1e-12);
  // One sigma either side holds 68.27%.
  EXPECT_NEAR(slabFraction(mu, sigma, mu - sigma, mu + sigma), 0.682689, 1e-6);
}

// Each slab's share of one kernel as the slab partition lists it: slabs of `thickness` from 0,
// the kernel in every slab its depth reach sqrt(depthCutoff) * sigma overlaps (at most
// `listCutoff`, the footprint's cutoff), the first and last taking the open tails.
std::vector<double> listedShares(double mu, double sigma, double thickness, double depthCutoff,
                                 double listCutoff, int slabs) {
  const double reach = std::sqrt(std::min(depthCutoff, listCutoff)) * sigma;
  const int first = int(std::floor((mu - reach) / thickness));
  const int last = int(std::floor((mu + reach) / thickness));
  const DepthProfile profile = depthProfile(depthCutoff);
  std::vector<double> shares(size_t(slabs), 0.0);
  for (int b = first; b <= last; ++b) {
    const double zNear = b == first ? -INFINITY : b * thickness;
    const double zFar = b == last ? INFINITY : (b + 1) * thickness;
    shares[size_t(b)] = slabFraction(mu, sigma, zNear, zFar, profile);
  }
  return shares;
}

TEST(SlabMath, CutDepthProfileKeepsTheMassInsideItsCut) {
  const double mu = 3.3, sigma = 0.7;
  for (double cutoff : {0.5, 1.0, 2.25, 4.0}) {
    const DepthProfile p = depthProfile(cutoff);
    const double r = std::sqrt(cutoff) * sigma;
    EXPECT_NEAR(slabFraction(mu, sigma, mu - r, mu + r, p), 1.0, 1e-12) << cutoff;
    EXPECT_NEAR(slabFraction(mu, sigma, mu + r, mu + r + 5.0, p), 0.0, 1e-12) << cutoff;
    EXPECT_NEAR(slabFraction(mu, sigma, -INFINITY, mu - r, p), 0.0, 1e-12) << cutoff;
    // Inside the cut it is the Gaussian scaled by 1 / erf(sqrt(cutoff / 2)).
    EXPECT_NEAR(slabFraction(mu, sigma, mu - 0.2, mu + 0.1, p),
                slabFraction(mu, sigma, mu - 0.2, mu + 0.1) / std::erf(std::sqrt(0.5 * cutoff)),
                1e-6);
    double sum = 0.0;
    for (double share : listedShares(mu, sigma, 0.5, cutoff, 4.0, 20)) sum += share;
    EXPECT_NEAR(sum, 1.0, 1e-12) << cutoff;
  }
  // Uncut: the Gaussian itself, as before the cut existed.
  const DepthProfile uncut = depthProfile(INFINITY);
  EXPECT_EQ(slabFraction(mu, sigma, 2.0, 4.0, uncut), slabFraction(mu, sigma, 2.0, 4.0));
  EXPECT_NEAR(slabFraction(mu, sigma, mu - sigma, mu + sigma, uncut), 0.682689, 1e-6);
}

// No popping: as a kernel moves in depth its slab shares change continuously when the profile
// is cut where the partition stops listing it. Uncut, the tail beyond the listed slabs jumps
// to the next slab when the listing changes (2.3% of the kernel at the cutoff 4).
TEST(SlabMath, CutDepthProfileMovesNoMassInJumps) {
  const double sigma = 1.0, thickness = 2.0, step = 1e-4;
  auto largestJump = [&](double depthCutoff) {
    double worst = 0.0;
    std::vector<double> prev = listedShares(5.0, sigma, thickness, depthCutoff, 4.0, 12);
    for (double mu = 5.0 + step; mu < 9.0; mu += step) {
      const std::vector<double> now = listedShares(mu, sigma, thickness, depthCutoff, 4.0, 12);
      for (size_t b = 0; b < now.size(); ++b) worst = std::max(worst, std::abs(now[b] - prev[b]));
      prev = now;
    }
    return worst;
  };
  for (double cutoff : {1.0, 2.25, 4.0}) EXPECT_LT(largestJump(cutoff), 1e-3) << cutoff;
  EXPECT_NEAR(largestJump(INFINITY), 0.5 * std::erfc(std::sqrt(2.0)), 1e-3);
}

// The footprint's depth Gaussian is the conditional of the 3D kernel along the ray: checked
// against numerical moments of the kernel along orthographic rays (plain filter: no low-pass).
TEST(SlabMath, DepthGaussianIsTheKernelAlongTheRay) {
  Camera cam;
  cam.position = {3.0, -2.0, 7.0};
  cam.focalPoint = {0.0, 0.0, 0.0};
  cam.orthographic = true;
  const Projection proj = cam.projection(64, 64);
  FootprintParams params;
  params.filter = FilterMode::Plain;
  const glm::dvec3 spacing(1.0, 0.5, 2.0);
  const glm::dmat3 cov = cameraCovariance(cam.rotation(), spacing);
  const glm::dvec3 u(0.3, -0.2, -8.0);
  const Footprint fp = computeFootprint(u, cov, proj, params);
  ASSERT_TRUE(fp.visible);
  const glm::dmat3 inv = glm::inverse(cov);
  for (const glm::dvec2 dx : {glm::dvec2(0, 0), glm::dvec2(3, -2), glm::dvec2(-4, 1)}) {
    // Camera-space ray through pixel center + dx: (x, y) fixed, depth varying.
    const glm::dvec2 xy = glm::dvec2(u.x, u.y) + dx / proj.pixelsPerUnit;
    double m0 = 0, m1 = 0, m2 = 0;
    for (int i = 0; i < 20000; ++i) {
      const double depth = 8.0 - 10.0 + 20.0 * (i + 0.5) / 20000;
      const glm::dvec3 p = glm::dvec3(xy, -depth) - u;
      const double w = std::exp(-0.5 * glm::dot(p, inv * p));
      m0 += w;
      m1 += w * depth;
      m2 += w * depth * depth;
    }
    const double mean = m1 / m0, sd = std::sqrt(m2 / m0 - mean * mean);
    EXPECT_NEAR(fp.depth + glm::dot(fp.depthSlope, dx), mean, 1e-6);
    EXPECT_NEAR(fp.depthSigma, sd, 1e-5);
  }
}

TEST(SlabMath, SurfaceCovarianceIsFlatAlongTheNormal) {
  const glm::dmat3 rot =
      glm::dmat3(glm::lookAt(glm::dvec3(1, 2, 3), glm::dvec3(0), glm::dvec3(0, 0, 1)));
  const glm::dvec3 n = glm::normalize(glm::dvec3(1, -2, 0.5));
  const glm::dmat3 cov = surfaceCovariance(rot, glm::dvec3(1.0), n);
  EXPECT_NEAR(glm::length(cov * (rot * n)), 0.0, 1e-12);  // no spread along the normal
  const glm::dvec3 t = glm::normalize(glm::cross(n, glm::dvec3(0, 0, 1)));
  EXPECT_NEAR(glm::dot(rot * t, cov * (rot * t)), 1.0, 1e-12);  // unit variance across it
  // A layer seen along its normal: mass times areal density is the optical depth.
  EXPECT_NEAR(surfaceSplatMass(glm::dvec3(2.0), glm::dvec3(0, 0, 1), 1.5), 1.5 * 4.0, 1e-12);
}

TEST(SplatAttributes, PackingRoundTrips) {
  const glm::dvec3 n = glm::normalize(glm::dvec3(0.3, -0.8, 0.2));
  const UnpackedAttributes s = unpackAttributes(packAttributes(n, true, -0.37));
  EXPECT_TRUE(s.surface);
  EXPECT_NEAR(s.offset, -0.37, 2e-3);
  EXPECT_NEAR(glm::length(s.normal - n), 0.0, 2e-3);
  const UnpackedAttributes v = unpackAttributes(packAttributes(n, false, 0.5));
  EXPECT_FALSE(v.surface);
  EXPECT_EQ(v.offset, 0.0);
}

// A float volume from f(world position).
Volume fieldVolume(int n, glm::dvec3 spacing, double (*f)(glm::dvec3)) {
  std::vector<uint8_t> bytes(size_t(n) * n * n * 4);
  float* v = reinterpret_cast<float*>(bytes.data());
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        v[i + n * (j + size_t(n) * k)] = float(f(glm::dvec3(i, j, k) * spacing));
  return Volume({n, n, n}, spacing, glm::dvec3(0.0), ScalarType::Float32, std::move(bytes));
}

TEST(SplatAttributes, GradientsOfALinearFieldAreExact) {
  const Volume vol = fieldVolume(8, glm::dvec3(1.0, 0.5, 2.0),
                                 [](glm::dvec3 p) { return 2.0 * p.x - 3.0 * p.y + 0.5 * p.z; });
  for (GradientMode mode : {GradientMode::Central, GradientMode::Smooth}) {
    const glm::dvec3 g = volumeGradient(vol, 3, 4, 5, mode);
    EXPECT_NEAR(g.x, 2.0, 1e-5);
    EXPECT_NEAR(g.y, -3.0, 1e-5);
    EXPECT_NEAR(g.z, 0.5, 1e-5);
  }
}

double ballField(glm::dvec3 p) {
  return 0.5 - (glm::length(p - glm::dvec3(7.5)) - 5.0) / 3.0;
}

TEST(SplatAttributes, SurfaceSplatsSitOnTheIsoSurfaceWithOutwardNormals) {
  const Volume vol = fieldVolume(16, glm::dvec3(1.0), ballField);
  TransferFunction clear;  // fully transparent: only surface splats are kept
  clear.opacity = {{-10.0, 0.0}, {10.0, 0.0}};
  Classification c;
  c.surface = SurfaceCriterion::Value;
  c.threshold = 0.5;  // the sphere of radius 5 about (7.5, 7.5, 7.5)
  const ClassifiedSplats cs = classifySplats(vol, clear, c);
  ASSERT_GT(cs.surfaceCount, 100u);
  EXPECT_EQ(cs.surfaceCount, cs.splats.size());
  for (size_t m = 0; m < cs.splats.size(); ++m) {
    const PackedSplat& s = cs.splats.splats()[m];
    const UnpackedAttributes a = unpackAttributes(cs.attributes[m]);
    ASSERT_TRUE(a.surface);
    const glm::dvec3 p(SplatSet::i(s), SplatSet::j(s), SplatSet::k(s));
    const glm::dvec3 radial = glm::normalize(p - glm::dvec3(7.5));
    EXPECT_GT(glm::dot(a.normal, radial), 0.99);  // outward, along the analytic normal
    EXPECT_NEAR(glm::length(p + a.offset * a.normal - glm::dvec3(7.5)), 5.0, 0.02);
  }
}

TEST(SplatAttributes, OpacityCriterionFindsTheSameShellAndHonoursTheGradientFloor) {
  const Volume vol = fieldVolume(16, glm::dvec3(1.0), ballField);
  TransferFunction tf;  // opacity 0.8 above value 0.5, so it crosses where the value does
  tf.opacity = {{0.49, 0.0}, {0.5, 0.8}, {10.0, 0.8}};
  Classification c;
  c.surface = SurfaceCriterion::Opacity;
  c.threshold = 0.5;
  const ClassifiedSplats cs = classifySplats(vol, tf, c);
  ASSERT_GT(cs.surfaceCount, 100u);
  for (size_t m = 0; m < cs.splats.size(); ++m) {
    if (!unpackAttributes(cs.attributes[m]).surface) continue;
    const PackedSplat& s = cs.splats.splats()[m];
    const double r =
        glm::length(glm::dvec3(SplatSet::i(s), SplatSet::j(s), SplatSet::k(s)) - glm::dvec3(7.5));
    EXPECT_GT(r, 3.9);  // the boundary layer just inside radius 5 (within one voxel diagonal)
    EXPECT_LE(r, 5.0 + 1e-9);
  }
  // The field changes by 1/3 per voxel, under 0.9 of its range: no voxel qualifies.
  c.minGradient = 0.9;
  EXPECT_EQ(classifySplats(vol, tf, c).surfaceCount, 0u);
}

TEST(Shading, HeadLightPhong) {
  Lighting light;
  light.enabled = true;
  const glm::dvec3 rgb(0.5, 1.0, 0.25), n = glm::normalize(glm::dvec3(0, 0.6, -0.8));
  const glm::dvec3 c = headlightShade(rgb, n, glm::dvec3(0, 0, 1), light);
  const double ndl = 0.8;  // two-sided
  EXPECT_NEAR(c.x, 0.5 * (0.3 + 0.7 * ndl) + 0.25 * std::pow(ndl, 24.0), 1e-12);
  EXPECT_EQ(headlightShade(rgb, glm::dvec3(0.0), glm::dvec3(0, 0, 1), light), rgb);  // no normal
  light.enabled = false;
  EXPECT_EQ(headlightShade(rgb, n, glm::dvec3(0, 0, 1), light), rgb);
}

// A slab's two splat passes skip kernels whose cut depth profile misses the pass's half
// (depthProfileMisses): every share such a kernel would give there, at any mean depth its
// footprint spans, is exactly 0; kernels that reach the half are never skipped; the uncut
// Gaussian reaches everywhere.
TEST(SlabMath, DepthProfileMissesOnlyWhereEveryShareIsZero) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (double cutoff : {0.5, 1.0, 2.25}) {
    const DepthProfile profile = depthProfile(cutoff);
    int misses = 0, reaches = 0;
    for (int n = 0; n < 4000; ++n) {
      const double mu = 200.0 + 8.0 * unit(rng), spread = 0.6 * unit(rng);
      const double sigma = 0.3 + 0.8 * unit(rng);
      double zNear = 200.0 + 8.0 * unit(rng), zFar = zNear + 0.25 + 2.0 * unit(rng);
      if (unit(rng) < 0.15) zNear = -INFINITY;  // open tails
      if (unit(rng) < 0.15) zFar = INFINITY;
      const bool missed = depthProfileMisses(mu, spread, sigma, zNear, zFar, profile);
      double largest = 0.0;
      for (int k = 0; k <= 16; ++k) {
        const double m = mu - spread + 2.0 * spread * k / 16.0;
        largest = std::max(largest, slabFraction(m, sigma, zNear, zFar, profile));
      }
      if (missed) {
        EXPECT_EQ(largest, 0.0) << "cut " << cutoff << ", case " << n;
        ++misses;
      } else {
        reaches += largest > 0.0;
      }
    }
    // Both outcomes are exercised, and the margin leaves few kernels drawn for nothing.
    EXPECT_GT(misses, 1000) << cutoff;
    EXPECT_GT(reaches, 1000) << cutoff;
    EXPECT_GT(misses + reaches, 3900) << cutoff;
  }
  // The cut reach: sqrt(cutoff) * sigma beyond the spread, not less.
  const DepthProfile cut = depthProfile(1.0);
  EXPECT_TRUE(depthProfileMisses(10.0, 0.5, 1.0, 11.6, 12.0, cut));
  EXPECT_FALSE(depthProfileMisses(10.0, 0.5, 1.0, 11.4, 12.0, cut));
  EXPECT_TRUE(depthProfileMisses(10.0, 0.5, 1.0, 7.0, 8.4, cut));
  EXPECT_FALSE(depthProfileMisses(10.0, 0.5, 1.0, 7.0, 8.6, cut));
  EXPECT_FALSE(depthProfileMisses(10.0, 0.0, 1.0, 40.0, 41.0, depthProfile(INFINITY)));
}

}  // namespace
}  // namespace ewa
