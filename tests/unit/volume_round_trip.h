// Helpers for the volume writers' tests: small volumes of every type, and comparing what a
// writer's file reads back as with what was written.
#pragma once

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "core/volume.h"

namespace ewa::testing {

// A 2x3x4 volume of type T holding offset + scale * n at voxel n, spacing (0.5, 1.25, 3),
// origin (-10, 20.5, 7).
template <typename T>
Volume rampVolume(ScalarType type, double scale, double offset) {
  std::vector<uint8_t> bytes(24 * sizeof(T));
  for (int n = 0; n < 24; ++n) {
    const T v = T(offset + scale * n);
    std::memcpy(&bytes[size_t(n) * sizeof(T)], &v, sizeof(T));
  }
  return Volume({2, 3, 4}, glm::dvec3(0.5, 1.25, 3.0), glm::dvec3(-10.0, 20.5, 7.0), type,
                std::move(bytes));
}

// One ramp of each type the viewer keeps: uint8, int16, uint16, float32.
inline std::vector<Volume> rampVolumesOfEveryType() {
  std::vector<Volume> volumes;
  volumes.push_back(rampVolume<uint8_t>(ScalarType::UInt8, 10, 3));
  volumes.push_back(rampVolume<int16_t>(ScalarType::Int16, -1000, 500));
  volumes.push_back(rampVolume<uint16_t>(ScalarType::UInt16, 2000, 7));
  volumes.push_back(rampVolume<float>(ScalarType::Float32, 0.1, -1.3));
  return volumes;
}

// `b` (read back) holds `a`'s voxels, type and unit, and its placement within `tolerance`
// (a format storing float32 rounds it). With `frame`, the patient frame too.
inline void expectSameVolume(const Volume& a, const Volume& b, double tolerance,
                             bool frame = true) {
  EXPECT_EQ(b.dims(), a.dims());
  EXPECT_EQ(b.type(), a.type());
  EXPECT_EQ(b.bytes(), a.bytes());
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(b.spacing()[c], a.spacing()[c], tolerance) << "axis " << c;
    EXPECT_NEAR(b.origin()[c], a.origin()[c], tolerance) << "axis " << c;
    for (int r = 0; r < 3; ++r)
      EXPECT_NEAR(b.direction()[c][r], a.direction()[c][r], tolerance) << c << "," << r;
  }
  if (frame) {
    EXPECT_EQ(b.patientFrame(), a.patientFrame());
  }
  EXPECT_EQ(b.unit(), a.unit());
}

}  // namespace ewa::testing
