// Unit tests of the EWA footprint math against analytic values and numerical ray integration.
#include "core/ewa_footprint.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/camera.h"

namespace ewa {
namespace {

constexpr double kPi = 3.14159265358979323846;

Projection perspective(int w, int h, double angleDeg) {
  Camera cam;
  cam.viewAngleDeg = angleDeg;
  return cam.projection(w, h);
}

// 3D unit-integral Gaussian with covariance `cov` at offset `x`.
double gaussian3(const glm::dmat3& cov, const glm::dvec3& x) {
  const glm::dmat3 inv = glm::inverse(cov);
  return std::exp(-0.5 * glm::dot(x, inv * x)) /
         std::sqrt(std::pow(2.0 * kPi, 3) * glm::determinant(cov));
}

// Integral of the 3D Gaussian along the real perspective ray through `pixel`.
double rayIntegral(const glm::dvec3& center, const glm::dmat3& cov, const Projection& p,
                   const glm::dvec2& pixel) {
  const glm::dvec3 dir = glm::normalize(glm::dvec3(
      (pixel.x - p.principal.x) / p.focalPixels, (pixel.y - p.principal.y) / p.focalPixels, -1.0));
  const double tc = glm::dot(center, dir);
  const double sigma = std::sqrt(std::max({cov[0][0], cov[1][1], cov[2][2]}));
  double sum = 0.0;
  const int n = 4000;
  const double t0 = tc - 10 * sigma, dt = 20 * sigma / n;
  for (int i = 0; i < n; ++i) sum += gaussian3(cov, dir * (t0 + (i + 0.5) * dt) - center) * dt;
  return sum;
}

TEST(EwaFootprint, PeakDoesNotDependOnDistance) {
  const Projection p = perspective(256, 256, 30.0);
  FootprintParams params;
  params.filter = FilterMode::Plain;
  const glm::dmat3 cov = cameraCovariance(glm::dmat3(1.0), glm::dvec3(0.5));
  const double kept = windowIntegral(4.0) / 2.0;
  for (double d : {2.0, 10.0, 50.0}) {
    const Footprint fp = computeFootprint({0, 0, -d}, cov, p, params);
    ASSERT_TRUE(fp.visible);
    EXPECT_NEAR(fp.peak * kept, 1.0 / (2 * kPi * 0.25), 1e-9) << "depth " << d;
    EXPECT_NEAR(fp.jacobianDet, p.focalPixels * p.focalPixels / (d * d), 1e-9);
  }
}

TEST(EwaFootprint, MatchesNumericalRayIntegrationNearTheAxis) {
  const Projection p = perspective(200, 200, 40.0);
  FootprintParams params;
  params.filter = FilterMode::Plain;
  params.cutoff = 1e9;  // no truncation, so the peak is the plain Gaussian's
  // An anisotropic kernel, rotated, slightly off axis.
  const glm::dmat3 rot(glm::dvec3(0.8, 0.6, 0), glm::dvec3(-0.6, 0.8, 0), glm::dvec3(0, 0, 1));
  const glm::dmat3 cov = cameraCovariance(rot, glm::dvec3(0.3, 0.15, 0.2));
  const glm::dvec3 center(0.4, -0.3, -20.0);
  const Footprint fp = computeFootprint(center, cov, p, params);
  ASSERT_TRUE(fp.visible);
  double worst = 0.0;
  for (int dy = -3; dy <= 3; ++dy) {
    for (int dx = -3; dx <= 3; ++dx) {
      const glm::dvec2 px = fp.center + glm::dvec2(dx, dy) * 0.7;
      const double expected = rayIntegral(center, cov, p, px);
      const double got = footprintWeight(fp, px, params.cutoff);
      worst = std::max(worst, std::abs(got - expected) / (fp.peak));
    }
  }
  EXPECT_LT(worst, 0.01) << "footprint differs from ray integration by " << worst * 100
                         << "% of its peak";
}

// ---- Perspective off the axis -------------------------------------------------------------
// Near the axis every plausible Jacobian agrees; off it they do not. The cases below sit at
// |u|/d from 1.1 to 1.4 (a 100-degree view), with rotated anisotropic kernels, for the plain
// and the EWA filter, and hold the footprint to the 3D Gaussian integrated numerically along
// the real perspective ray through each pixel (for EWA, that image convolved with the unit
// pixel Gaussian). Two wrong Jacobians are built here as well, and must score far outside the
// tolerance, so the test keeps its power to catch them:
//   * weak perspective: J without its third column and |det J| without the |u|/d factor;
//   * transposed J: the 2x3 screen rows taken from the transpose of the 3x3 Jacobian.
// Measured (|footprint - reference| / reference peak, over the 48 cases; the test prints it):
//   correct J:        worst 0.0115 (the affine approximation's own error, sigma/d ~ 1%)
//   weak perspective: worst 1.42, best case 0.084
//   transposed J:     worst 2.27, best case 0.060
// so the tolerance 0.02 passes the correct J and fails each wrong one in every case.

enum class JacobianVariant { Correct, WeakPerspective, Transposed };

struct VariantFootprint {
  glm::dvec2 center;
  glm::dmat2 conic;
  double peak;
};

// The footprint of computeFootprint's formulas with the Jacobian chosen by `variant`, without
// the window (cutoff infinite) so it compares with the plain Gaussian's ray integral.
VariantFootprint variantFootprint(const glm::dvec3& u, const glm::dmat3& cov, const Projection& p,
                                  FilterMode filter, JacobianVariant variant) {
  const double d = -u.z, f = p.focalPixels, len = glm::length(u);
  glm::dvec3 j0(f / d, 0.0, f * u.x / (d * d)), j1(0.0, f / d, f * u.y / (d * d));
  double det = f * f * len / (d * d * d);
  if (variant == JacobianVariant::WeakPerspective) {
    j0.z = j1.z = 0.0;
    det = f * f / (d * d);
  } else if (variant == JacobianVariant::Transposed) {
    // J = [j0; j1; u/|u|]; rows of J^T are (J00, J10, J20), (J01, J11, J21).
    const glm::dvec3 r0(j0.x, j1.x, u.x / len), r1(j0.y, j1.y, u.y / len);
    j0 = r0;
    j1 = r1;
  }
  double a = glm::dot(j0, cov * j0), b = glm::dot(j0, cov * j1), c = glm::dot(j1, cov * j1);
  if (filter == FilterMode::Ewa) {
    a += 1.0;
    c += 1.0;
  }
  const double dt = a * c - b * b;
  VariantFootprint v;
  v.center = p.principal + glm::dvec2(u.x, u.y) * (f / d);
  v.conic = glm::dmat2(c / dt, -b / dt, -b / dt, a / dt);
  v.peak = det / (2.0 * kPi * std::sqrt(dt));
  return v;
}

double variantWeight(const VariantFootprint& v, const glm::dvec2& px) {
  const glm::dvec2 dx = px - v.center;
  return v.peak * std::exp(-0.5 * glm::dot(dx, v.conic * dx));
}

// The ray integral of a 3D Gaussian (precomputed inverse) along the perspective ray through
// `pixel`, by the midpoint rule over +-7 standard deviations of the kernel's largest axis.
struct RayIntegrator {
  glm::dvec3 center;
  glm::dmat3 inv;
  double norm, sigma;
  const Projection& p;
  RayIntegrator(const glm::dvec3& c, const glm::dmat3& cov, const Projection& proj)
      : center(c), inv(glm::inverse(cov)), p(proj) {
    norm = 1.0 / std::sqrt(std::pow(2.0 * kPi, 3) * glm::determinant(cov));
    sigma = std::sqrt(std::max({cov[0][0], cov[1][1], cov[2][2]}));
  }
  double operator()(const glm::dvec2& pixel) const {
    const glm::dvec3 dir =
        glm::normalize(glm::dvec3((pixel.x - p.principal.x) / p.focalPixels,
                                  (pixel.y - p.principal.y) / p.focalPixels, -1.0));
    const double tc = glm::dot(center, dir);
    const int n = 600;
    const double t0 = tc - 7 * sigma, dt = 14 * sigma / n;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
      const glm::dvec3 x = dir * (t0 + (i + 0.5) * dt) - center;
      sum += std::exp(-0.5 * glm::dot(x, inv * x));
    }
    return sum * norm * dt;
  }
};

// The reference image at `pixel`: the ray integral, for EWA convolved with the unit Gaussian
// low-pass filter (Gauss-Hermite, 10 nodes per axis: exact for the smooth integrand to 1e-6).
double referenceWeight(const RayIntegrator& ray, const glm::dvec2& pixel, FilterMode filter) {
  if (filter != FilterMode::Ewa) return ray(pixel);
  // Nodes and weights of the probabilists' Gauss-Hermite rule (weight exp(-x^2/2)/sqrt(2 pi)).
  static const double x[10] = {-4.859462828332312, -3.581823483551927, -2.484325841638955,
                               -1.465989094391158, -0.484935707515498, 0.484935707515498,
                               1.465989094391158,  2.484325841638955,  3.581823483551927,
                               4.859462828332312};
  static const double w[10] = {4.310652630718e-06, 7.580709343122e-04, 1.911158050077e-02,
                               1.354837029802e-01, 3.446423349320e-01, 3.446423349320e-01,
                               1.354837029802e-01, 1.911158050077e-02, 7.580709343122e-04,
                               4.310652630718e-06};
  double sum = 0.0;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) sum += w[i] * w[j] * ray(pixel + glm::dvec2(x[i], x[j]));
  return sum;
}

struct OffAxisScore {
  double correct = 0.0, weak = 0.0, transposed = 0.0;
};

// Worst error over a 7x7 grid spanning +-2 standard deviations of the true footprint, relative
// to the reference's peak, for the real computeFootprint and the two wrong Jacobians.
OffAxisScore scoreOffAxis(const glm::dvec3& u, const glm::dmat3& cov, const Projection& p,
                          FilterMode filter) {
  FootprintParams params;
  params.filter = filter;
  params.cutoff = 1e9;  // no window, so the peak is the plain Gaussian's
  const Footprint fp = computeFootprint(u, cov, p, params);
  EXPECT_TRUE(fp.visible);
  const VariantFootprint weak =
      variantFootprint(u, cov, p, filter, JacobianVariant::WeakPerspective);
  const VariantFootprint transposed =
      variantFootprint(u, cov, p, filter, JacobianVariant::Transposed);
  const RayIntegrator ray(u, cov, p);
  const double sx = std::sqrt(fp.covariance[0][0]), sy = std::sqrt(fp.covariance[1][1]);
  const double peak = referenceWeight(ray, fp.center, filter);
  OffAxisScore s;
  for (int iy = -3; iy <= 3; ++iy) {
    for (int ix = -3; ix <= 3; ++ix) {
      const glm::dvec2 px = fp.center + glm::dvec2(ix * sx, iy * sy) * (2.0 / 3.0);
      const double ref = referenceWeight(ray, px, filter);
      s.correct =
          std::max(s.correct, std::abs(footprintWeight(fp, px, params.cutoff) - ref) / peak);
      s.weak = std::max(s.weak, std::abs(variantWeight(weak, px) - ref) / peak);
      s.transposed = std::max(s.transposed, std::abs(variantWeight(transposed, px) - ref) / peak);
    }
  }
  return s;
}

TEST(EwaFootprint, MatchesNumericalRayIntegrationOffTheAxis) {
  const Projection p = perspective(1600, 1600, 100.0);
  const double tolerance = 0.02;
  const glm::dmat3 rotations[3] = {
      glm::dmat3(1.0),
      // 30 degrees about z, then 40 about x: the kernel's axes tilted against the ray.
      glm::dmat3(glm::dvec3(0.866, 0.383, 0.321), glm::dvec3(-0.5, 0.663, 0.557),
                 glm::dvec3(0.0, -0.643, 0.766)),
      // 60 degrees about y, then 20 about z.
      glm::dmat3(glm::dvec3(0.470, 0.171, -0.866), glm::dvec3(-0.342, 0.940, 0.0),
                 glm::dvec3(0.814, 0.296, 0.5))};
  const glm::dvec3 spacings[2] = {{0.6, 0.25, 0.4}, {0.3, 0.5, 1.0}};
  OffAxisScore worst;
  double bestWeak = 1e9, bestTransposed = 1e9;
  int cases = 0;
  for (double ratio : {1.1, 1.2, 1.3, 1.4}) {
    const double d = 80.0, lateral = d * std::sqrt(ratio * ratio - 1.0);
    for (int r = 0; r < 3; ++r) {
      for (int sp = 0; sp < 2; ++sp) {
        for (FilterMode filter : {FilterMode::Plain, FilterMode::Ewa}) {
          // Off the axis in a different direction for each case (not only along x or y).
          const double phi = 0.7 + 1.3 * cases;
          const glm::dvec3 u(lateral * std::cos(phi), lateral * std::sin(phi), -d);
          ASSERT_NEAR(glm::length(u) / d, ratio, 1e-12);
          // Orthonormalize the rounded rotation so V'' stays a covariance of the given spacing.
          glm::dmat3 rot = rotations[r];
          rot[0] = glm::normalize(rot[0]);
          rot[1] = glm::normalize(rot[1] - glm::dot(rot[1], rot[0]) * rot[0]);
          rot[2] = glm::cross(rot[0], rot[1]);
          const glm::dmat3 cov = cameraCovariance(rot, spacings[sp]);
          const OffAxisScore s = scoreOffAxis(u, cov, p, filter);
          EXPECT_LT(s.correct, tolerance) << "|u|/d " << ratio << " rotation " << r << " spacing "
                                          << sp << " filter " << filterModeName(filter);
          // ...and each wrong Jacobian fails it in every case, not just on average.
          EXPECT_GT(s.weak, 2.0 * tolerance) << "|u|/d " << ratio;
          EXPECT_GT(s.transposed, 2.0 * tolerance) << "|u|/d " << ratio;
          worst.correct = std::max(worst.correct, s.correct);
          worst.weak = std::max(worst.weak, s.weak);
          worst.transposed = std::max(worst.transposed, s.transposed);
          bestWeak = std::min(bestWeak, s.weak);
          bestTransposed = std::min(bestTransposed, s.transposed);
          ++cases;
        }
      }
    }
  }
  std::printf(
      "off-axis footprint error / peak, worst over %d cases: correct %.4f, weak "
      "perspective %.4f (best case %.4f), transposed J %.4f (best case %.4f)\n",
      cases, worst.correct, worst.weak, bestWeak, worst.transposed, bestTransposed);
  // The wrong Jacobians must fail the same tolerance by a wide margin.
  EXPECT_GT(worst.weak, 5.0 * tolerance);
  EXPECT_GT(worst.transposed, 5.0 * tolerance);
}

TEST(EwaFootprint, MagnifiedKernelsKeepTheReconstructionFootprint) {
  const Projection p = perspective(512, 512, 30.0);
  const glm::dmat3 cov = cameraCovariance(glm::dmat3(1.0), glm::dvec3(1.0));
  FootprintParams ewa, plain;
  plain.filter = FilterMode::Plain;
  const Footprint a = computeFootprint({0, 0, -5}, cov, p, ewa);
  const Footprint b = computeFootprint({0, 0, -5}, cov, p, plain);
  // About 190 pixels per unit: the low-pass filter adds 1 px^2 to ~36000 px^2.
  EXPECT_NEAR(a.covariance[0][0] / b.covariance[0][0], 1.0, 1e-4);
  EXPECT_NEAR(a.peak / b.peak, 1.0, 1e-4);
}

TEST(EwaFootprint, MinifiedKernelsNeverShrinkBelowTheLowPassFilter) {
  const Projection p = perspective(512, 512, 30.0);
  const glm::dmat3 cov = cameraCovariance(glm::dmat3(1.0), glm::dvec3(0.01));
  FootprintParams ewa, plain;
  plain.filter = FilterMode::Plain;
  const Footprint a = computeFootprint({0, 0, -500}, cov, p, ewa);
  const Footprint b = computeFootprint({0, 0, -500}, cov, p, plain);
  EXPECT_NEAR(a.covariance[0][0], 1.0, 1e-3);
  EXPECT_NEAR(a.covariance[1][1], 1.0, 1e-3);
  EXPECT_LT(b.covariance[0][0], 1e-3);
  EXPECT_GE(a.radius, 2.0 - 1e-9);  // sqrt(cutoff * 1)
}

TEST(EwaFootprint, AnisotropicSpacingGivesAnEllipse) {
  Camera cam;
  cam.orthographic = true;
  cam.position = {0, 0, 10};
  const Projection p = cam.projection(100, 100);
  FootprintParams plain;
  plain.filter = FilterMode::Plain;
  const glm::dmat3 cov = cameraCovariance(cam.rotation(), glm::dvec3(2.0, 1.0, 3.0));
  const Footprint fp = computeFootprint({0, 0, -10}, cov, p, plain);
  const double s = p.pixelsPerUnit;
  EXPECT_NEAR(fp.covariance[0][0], 4.0 * s * s, 1e-9);
  EXPECT_NEAR(fp.covariance[1][1], 1.0 * s * s, 1e-9);
  EXPECT_NEAR(fp.covariance[0][1], 0.0, 1e-9);
  EXPECT_NEAR(fp.jacobianDet, s * s, 1e-12);
}

TEST(EwaFootprint, SwanStretchesBeyondK) {
  const Projection p = perspective(512, 512, 30.0);
  FootprintParams swan;
  swan.filter = FilterMode::Swan;
  swan.swanSpacing = 1.0;
  const double k = swan.swanSpacing * p.focalPixels;  // k = s D / p
  const glm::dmat3 cov = cameraCovariance(glm::dmat3(1.0), glm::dvec3(1.0));
  const Footprint near = computeFootprint({0, 0, -0.5 * k}, cov, p, swan);
  const Footprint atK = computeFootprint({0, 0, -k}, cov, p, swan);
  const Footprint far = computeFootprint({0, 0, -4.0 * k}, cov, p, swan);
  EXPECT_DOUBLE_EQ(near.stretch, 1.0);
  EXPECT_NEAR(far.stretch, 4.0, 1e-9);
  // Beyond k the footprint keeps the size it has at k, its energy scaled by (k/d)^2.
  EXPECT_NEAR(far.covariance[0][0], atK.covariance[0][0], 1e-9);
  EXPECT_NEAR(far.peak / atK.peak, 1.0 / 16.0, 1e-9);
  // Kernels half as wide (s = 0.5 * spacing) stretch from half the distance on, to the same
  // screen size: twice the stretch.
  FootprintParams narrow = swan;
  narrow.swanSpacing = 0.5;
  const glm::dmat3 half = cameraCovariance(glm::dmat3(1.0), glm::dvec3(0.5));
  const Footprint farNarrow = computeFootprint({0, 0, -4.0 * k}, half, p, narrow);
  EXPECT_NEAR(farNarrow.stretch, 8.0, 1e-9);
  EXPECT_NEAR(farNarrow.covariance[0][0], far.covariance[0][0], 1e-9);
}

TEST(EwaFootprint, WindowIntegralMatchesQuadrature) {
  for (double c : {1.0, 4.0, 9.0, 16.0}) {
    double sum = 0.0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) sum += windowedGaussian((i + 0.5) * c / n, c) * c / n;
    EXPECT_NEAR(windowIntegral(c), sum, 1e-8) << "cutoff " << c;
  }
  EXPECT_NEAR(windowIntegral(1e6), 2.0, 1e-4);
  EXPECT_EQ(windowedGaussian(4.01, 4.0), 0.0);
}

// Sum over pixel centres of one splat: its image integral.
double imageSum(const Footprint& fp, double cutoff) {
  double sum = 0.0;
  const int r = int(std::ceil(fp.radius)) + 1;
  for (int y = int(fp.center.y) - r; y <= int(fp.center.y) + r; ++y)
    for (int x = int(fp.center.x) - r; x <= int(fp.center.x) + r; ++x)
      sum += footprintWeight(fp, {x + 0.5, y + 0.5}, cutoff);
  return sum;
}

TEST(EwaFootprint, MassIsKeptForEveryFilterAndSize) {
  const Projection p = perspective(512, 512, 30.0);
  const glm::dmat3 cov = cameraCovariance(glm::dmat3(1.0), glm::dvec3(1.0));
  for (FilterMode mode : {FilterMode::Ewa, FilterMode::Swan, FilterMode::Plain}) {
    FootprintParams params;
    params.filter = mode;
    for (double d : {3.0, 30.0, 300.0, 3000.0}) {
      const Footprint fp = computeFootprint({0.01, -0.02, -d}, cov, p, params);
      const double sigmaPx = std::sqrt(fp.covariance[0][0]);
      if (sigmaPx < 0.7) continue;  // a sub-pixel plain splat aliases: that is the point of EWA
      EXPECT_NEAR(imageSum(fp, params.cutoff) / fp.jacobianDet, 1.0, 0.01)
          << filterModeName(mode) << " at depth " << d;
    }
  }
}

TEST(EwaFootprint, CullsBehindTheEyeAndOutsideTheView) {
  const Projection p = perspective(100, 100, 30.0);
  FootprintParams params;
  EXPECT_TRUE(cullKernel({0, 0, 1}, 0.5, p, params));
  EXPECT_TRUE(cullKernel({0, 0, 0}, 0.5, p, params));
  EXPECT_FALSE(cullKernel({0, 0, -5}, 0.5, p, params));
  EXPECT_TRUE(cullKernel({100, 0, -5}, 0.5, p, params));
  EXPECT_FALSE(cullKernel({1.5, 0, -5}, 0.5, p, params));  // edge at 5 tan(15deg) = 1.34
  EXPECT_TRUE(cullKernel({0, -3, -5}, 0.5, p, params));
  const Footprint fp = computeFootprint({0, 0, 0}, glm::dmat3(1.0), p, params);
  EXPECT_FALSE(fp.visible);
}

TEST(Camera, OrthographicShowsThePerspectiveHeightAtTheFocalPoint) {
  Camera cam;
  cam.position = {0, 0, 10};
  cam.viewAngleDeg = 30.0;
  cam.orthographic = true;
  const Projection p = cam.projection(200, 100);
  EXPECT_NEAR(p.pixelsPerUnit, 100.0 / (2 * 10 * std::tan(15.0 * kPi / 180.0)), 1e-9);
  cam.orthographic = false;
  const Projection q = cam.projection(200, 100);
  // A point at the focal distance maps with the same scale in both.
  EXPECT_NEAR(q.focalPixels / 10.0, p.pixelsPerUnit, 1e-9);
}

TEST(Camera, FrameFitsTheBoundingSphereAndOrbitKeepsDistance) {
  Camera cam;
  cam.frame({0, 0, 0}, {10, 20, 30}, {0, 0, 1}, {0, 1, 0}, 1.0);
  EXPECT_NEAR(cam.focalPoint.y, 10.0, 1e-12);
  const double r = 0.5 * std::sqrt(100.0 + 400.0 + 900.0);
  EXPECT_NEAR(cam.distance(), r / std::sin(15.0 * kPi / 180.0), 1e-9);
  const double d = cam.distance();
  cam.orbit(37.0, 20.0);
  EXPECT_NEAR(cam.distance(), d, 1e-9);
  EXPECT_NEAR(glm::dot(cam.direction(), glm::normalize(cam.viewUp)), 0.0, 1e-9);
}

// The point sprite holds every pixel centre the ellipse r <= cutoff holds, with the margin to
// spare, and is no larger than the ellipse's bounding square and the margin: round, elongated
// and turned footprints, magnified and minified, at sub-pixel centre offsets.
TEST(EwaFootprint, PointSpriteHoldsTheEllipseWithASmallMargin) {
  for (double cutoff : {2.0, 5.0, 9.0})
    for (double a : {0.3, 1.0, 7.5, 40.0})
      for (double ratio : {1.0, 0.2})
        for (double turn : {0.0, 0.6, 1.3}) {
          // Covariance R diag(a, a * ratio) R^T.
          const double c0 = std::cos(turn), s0 = std::sin(turn), b = a * ratio;
          Footprint fp;
          fp.visible = true;
          fp.covariance = glm::dmat2(c0 * c0 * a + s0 * s0 * b, c0 * s0 * (a - b),
                                     c0 * s0 * (a - b), s0 * s0 * a + c0 * c0 * b);
          fp.conic = glm::inverse(fp.covariance);
          const double size = pointSpriteSize(fp, cutoff);
          const double bound = 2.0 * std::sqrt(cutoff * std::max(a, b));
          EXPECT_LE(size, bound + kPointSpriteMargin + 1e-12);
          for (double ox : {0.0, 0.25, 0.5, 0.93})
            for (double oy : {0.0, 0.4, 0.77}) {
              fp.center = glm::dvec2(100.0 + ox, 100.0 + oy);
              const int reach = int(std::ceil(bound)) + 2;
              double widest = 0.0;  // the largest |dx| or |dy| of a centre inside the ellipse
              for (int y = 100 - reach; y <= 100 + reach; ++y)
                for (int x = 100 - reach; x <= 100 + reach; ++x) {
                  const glm::dvec2 d = glm::dvec2(x + 0.5, y + 0.5) - fp.center;
                  if (glm::dot(d, fp.conic * d) <= cutoff)
                    widest = std::max({widest, std::abs(d.x), std::abs(d.y)});
                }
              EXPECT_LE(widest, 0.5 * (size - kPointSpriteMargin) + 1e-9)
                  << "cutoff " << cutoff << " a " << a << " ratio " << ratio << " turn " << turn;
            }
        }
}

}  // namespace
}  // namespace ewa
