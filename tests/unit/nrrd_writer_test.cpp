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
#include "io/volume_writer.h"
#include "loader_test_files.h"
#include "volume_round_trip.h"

namespace ewa {
namespace {

using testing::expectSameVolume;
using testing::rampVolume;
using testing::rampVolumesOfEveryType;
using testing::TempDir;

TEST(NrrdWriter, WhatIsReadBackIsTheVolumeWritten) {
  TempDir dir;
  std::vector<Volume> volumes = rampVolumesOfEveryType();
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
    writeVolume(path, v);
    expectSameVolume(v, loadVolume(path), 1e-12);
  }
}

TEST(NrrdWriter, AnUnwritablePathFailsNamingIt) {
  const Volume v = rampVolume<uint8_t>(ScalarType::UInt8, 1, 0);
  try {
    writeVolume("/no/such/folder/v.nrrd", v);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/no/such/folder/v.nrrd"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ewa
