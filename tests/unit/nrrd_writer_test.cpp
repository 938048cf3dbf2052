// The NRRD writer (--save-volume): what loadVolume reads back is the volume written, for every
// scalar type, with its spacing, direction, origin, patient frame and unit.
#include "io/nrrd_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

#include "io/volume_loader.h"
#include "loader_test_files.h"

namespace ewa {
namespace {

using testing::TempDir;

template <typename T>
Volume ramp(ScalarType type, double scale, double offset) {
  std::vector<uint8_t> bytes(24 * sizeof(T));
  for (int n = 0; n < 24; ++n) {
    const T v = T(offset + scale * n);
    std::memcpy(&bytes[size_t(n) * sizeof(T)], &v, sizeof(T));
  }
  return Volume({2, 3, 4}, glm::dvec3(0.5, 1.25, 3.0), glm::dvec3(-10.0, 20.5, 7.0), type,
                std::move(bytes));
}

void expectSame(const Volume& a, const Volume& b) {
  EXPECT_EQ(b.dims(), a.dims());
  EXPECT_EQ(b.type(), a.type());
  EXPECT_EQ(b.bytes(), a.bytes());
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(b.spacing()[c], a.spacing()[c], 1e-12);
    EXPECT_NEAR(b.origin()[c], a.origin()[c], 1e-12);
    for (int r = 0; r < 3; ++r) EXPECT_NEAR(b.direction()[c][r], a.direction()[c][r], 1e-12);
  }
  EXPECT_EQ(b.patientFrame(), a.patientFrame());
  EXPECT_EQ(b.unit(), a.unit());
}

TEST(NrrdWriter, WhatIsReadBackIsTheVolumeWritten) {
  TempDir dir;
  std::vector<Volume> volumes;
  volumes.push_back(ramp<uint8_t>(ScalarType::UInt8, 10, 3));
  volumes.push_back(ramp<int16_t>(ScalarType::Int16, -1000, 500));
  volumes.push_back(ramp<uint16_t>(ScalarType::UInt16, 2000, 7));
  volumes.push_back(ramp<float>(ScalarType::Float32, 0.1, -1.3));
  // A rotated patient volume with a unit, and a plain one with another.
  volumes[1].setDirection(
      glm::dmat3(glm::rotate(glm::dmat4(1.0), 0.3, glm::normalize(glm::dvec3(1, 2, 3)))), true);
  volumes[1].setUnit("mm");
  volumes[3].setUnit("\xC2\xB5m");
  volumes[3].addNote("a note\nof two lines");
  int n = 0;
  for (const Volume& v : volumes) {
    SCOPED_TRACE(scalarName(v.type()));
    const std::string path = dir.path("v" + std::to_string(n++) + ".nrrd");
    writeNrrd(path, v);
    expectSame(v, loadVolume(path));
  }
}

TEST(NrrdWriter, AnUnwritablePathFailsNamingIt) {
  const Volume v = ramp<uint8_t>(ScalarType::UInt8, 1, 0);
  try {
    writeNrrd("/no/such/folder/v.nrrd", v);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/no/such/folder/v.nrrd"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ewa
