// The quality reference's CPU ray integration against closed forms: a uniform sheet has optical
// depth tau * thickness / cos(theta) along a ray at angle theta to its normal.
#include "bench/sheet_ray_image.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <stdexcept>

namespace ewa {
namespace {

// A uniform n x n x 1 uint8 sheet of value 1 with the given spacing.
Volume uniformSheet(int n, const glm::dvec3& spacing) {
  return Volume({n, n, 1}, spacing, glm::dvec3(0.0), ScalarType::UInt8,
                std::vector<uint8_t>(size_t(n) * n, 1));
}

TransferFunction flatTf(double alpha, const glm::dvec3& rgb) {
  TransferFunction tf;
  tf.opacity = {{0.0, 0.0}, {1.0, alpha}};
  tf.color = {{0.0, rgb}, {1.0, rgb}};
  return tf;
}

// The colour at the centre pixel of a 3 x 3 image looking at the sheet's middle along `dir`.
glm::dvec3 centreColour(const Volume& sheet, const TransferFunction& tf, const glm::dvec3& dir,
                        const glm::dvec3& background, double kernelWidth = 1.0) {
  Camera cam;
  cam.focalPoint = 0.5 * (sheet.boundsMin() + sheet.boundsMax());
  cam.focalPoint.z = 0.0;
  cam.position = cam.focalPoint - 40.0 * glm::normalize(dir);
  cam.viewUp = glm::dvec3(0.0, 1.0, 0.0);
  cam.viewAngleDeg = 1.0;
  const FloatImage img = sheetRayImage(sheet, tf, cam, 3, 3, background, kernelWidth, 1);
  return {img.at(1, 1, 0), img.at(1, 1, 1), img.at(1, 1, 2)};
}

TEST(SheetRayImage, UniformSheetHasTheSlabsOpticalDepth) {
  const glm::dvec3 rgb(0.9, 0.5, 0.2), background(0.1, 0.2, 0.3);
  const double alpha = 0.4, tau = -std::log(1.0 - alpha);
  for (const glm::dvec3 spacing : {glm::dvec3(1.0), glm::dvec3(0.5, 1.0, 2.0)}) {
    const Volume sheet = uniformSheet(160, spacing);
    // Narrower or wider kernels keep each voxel's mass: the medium is the same (down to 0.8,
    // where a lattice of Gaussians still sums to a constant within 1e-5).
    for (double width : {1.0, 0.8, 1.4})
      for (double thetaDeg : {0.0, 30.0, 60.0}) {
        const double theta = thetaDeg * 3.14159265358979 / 180.0;
        const glm::dvec3 dir(std::sin(theta), 0.3 * std::sin(theta), -std::cos(theta));
        const double cosine = std::cos(theta) / glm::length(dir);
        const double depth = tau * spacing.z / cosine;
        const glm::dvec3 expected = rgb * (1.0 - std::exp(-depth)) + background * std::exp(-depth);
        const glm::dvec3 got = centreColour(sheet, flatTf(alpha, rgb), dir, background, width);
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(got[c], expected[c], 2e-4) << "theta " << thetaDeg << " spacing " << spacing.x
                                                 << "," << spacing.z << " width " << width;
      }
  }
}

// One voxel seen head-on: its kernel of standard deviations S * spacing puts optical depth
// tau * sx * sy * sz / (2 pi * S sx * S sy) on the ray through its centre.
TEST(SheetRayImage, OneVoxelsPeakFollowsTheKernelWidth) {
  const glm::dvec3 spacing(0.8, 1.2, 1.5), white(1.0), black(0.0);
  std::vector<uint8_t> values(81, 0);
  values[40] = 1;  // the middle of 9 x 9
  const Volume sheet({9, 9, 1}, spacing, glm::dvec3(0.0), ScalarType::UInt8, values);
  const double alpha = 0.5, tau = -std::log(1.0 - alpha);
  for (double width : {0.5, 0.7, 1.0, 1.6}) {
    const double depth = tau * spacing.z / (2.0 * 3.14159265358979 * width * width);
    const glm::dvec3 got = centreColour(sheet, flatTf(alpha, white), {0, 0, -1}, black, width);
    EXPECT_NEAR(got.x, 1.0 - std::exp(-depth), 2e-4) << "width " << width;
  }
}

TEST(SheetRayImage, RejectsThickVolumesAndParallelCameras) {
  const Volume thick({4, 4, 2}, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::UInt8,
                     std::vector<uint8_t>(32, 1));
  Camera cam;
  EXPECT_THROW(sheetRayImage(thick, flatTf(0.5, glm::dvec3(1.0)), cam, 4, 4, glm::dvec3(0.0)),
               std::invalid_argument);
  EXPECT_THROW(sheetRayImage(uniformSheet(4, glm::dvec3(1.0)), flatTf(0.5, glm::dvec3(1.0)), cam, 4,
                             4, glm::dvec3(0.0), 0.0),
               std::invalid_argument);
  cam.orthographic = true;
  EXPECT_THROW(sheetRayImage(uniformSheet(4, glm::dvec3(1.0)), flatTf(0.5, glm::dvec3(1.0)), cam, 4,
                             4, glm::dvec3(0.0)),
               std::invalid_argument);
}

}  // namespace
}  // namespace ewa
