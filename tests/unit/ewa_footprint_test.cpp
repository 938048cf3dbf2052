// Unit tests of the EWA footprint math against analytic values and numerical ray integration.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/camera.h"
#include "core/ewa_footprint.h"

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
  const glm::dvec3 dir = glm::normalize(glm::dvec3((pixel.x - p.principal.x) / p.focalPixels,
                                                   (pixel.y - p.principal.y) / p.focalPixels, -1.0));
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
  swan.minSpacing = 1.0;
  const double k = swan.minSpacing * p.focalPixels;  // k = s D / p
  const glm::dmat3 cov = cameraCovariance(glm::dmat3(1.0), glm::dvec3(1.0));
  const Footprint near = computeFootprint({0, 0, -0.5 * k}, cov, p, swan);
  const Footprint atK = computeFootprint({0, 0, -k}, cov, p, swan);
  const Footprint far = computeFootprint({0, 0, -4.0 * k}, cov, p, swan);
  EXPECT_DOUBLE_EQ(near.stretch, 1.0);
  EXPECT_NEAR(far.stretch, 4.0, 1e-9);
  // Beyond k the footprint keeps the size it has at k, its energy scaled by (k/d)^2.
  EXPECT_NEAR(far.covariance[0][0], atK.covariance[0][0], 1e-9);
  EXPECT_NEAR(far.peak / atK.peak, 1.0 / 16.0, 1e-9);
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

}  // namespace
}  // namespace ewa
