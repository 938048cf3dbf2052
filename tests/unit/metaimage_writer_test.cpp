// The MetaImage writer (--save-volume NAME.mha): what loadVolume reads back is the volume
// written, with ITK's fields, and a file ITK wrote keeps its placement written again.
#include "io/metaimage_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

#include "io/atomic_file.h"
#include "io/volume_loader.h"
#include "io/volume_writer.h"
#include "loader_test_files.h"
#include "volume_round_trip.h"

namespace ewa {
namespace {

using testing::expectSameVolume;
using testing::rampVolumesOfEveryType;
using testing::TempDir;

// The header's line for `key` ("Key = value"), or "" when it has none.
std::string headerLine(const std::string& file, const std::string& key) {
  const size_t at = file.find("\n" + key + " = ");
  if (at == std::string::npos) return "";
  return file.substr(at + 1, file.find('\n', at + 1) - at - 1);
}

TEST(MetaImageWriter, WhatIsReadBackIsTheVolumeWritten) {
  TempDir dir;
  std::vector<Volume> volumes = rampVolumesOfEveryType();
  // Rotated patient volumes and plain ones; MetaImage has no unit to keep.
  volumes[1].setDirection(
      glm::dmat3(glm::rotate(glm::dmat4(1.0), 0.3, glm::normalize(glm::dvec3(1, 2, 3)))), true);
  volumes[2].setDirection(glm::dmat3(1.0), true);
  int n = 0;
  for (const Volume& v : volumes) {
    SCOPED_TRACE(scalarName(v.type()));
    const std::string path = dir.path("v" + std::to_string(n++) + ".mha");
    writeVolume(path, v);
    expectSameVolume(v, loadVolume(path), 1e-12);
  }
  const std::string plain = readTextFile(dir.path("v0.mha"));
  EXPECT_EQ(plain.rfind("ObjectType = Image\nNDims = 3\n", 0), 0u);
  EXPECT_EQ(headerLine(plain, "ElementType"), "ElementType = MET_UCHAR");
  EXPECT_EQ(headerLine(plain, "DimSize"), "DimSize = 2 3 4");
  EXPECT_EQ(headerLine(plain, "Offset"), "Offset = -10 20.5 7");
  EXPECT_EQ(headerLine(plain, "AnatomicalOrientation"), "");  // no patient axes
  EXPECT_EQ(headerLine(readTextFile(dir.path("v2.mha")), "AnatomicalOrientation"),
            "AnatomicalOrientation = RAI");
  EXPECT_EQ(headerLine(readTextFile(dir.path("v3.mha")), "ElementType"), "ElementType = MET_FLOAT");
}

TEST(MetaImageWriter, AxesAt45DegreesNameEachPatientAxisOnce) {
  // The y and z axes halfway between the patient's y and z (found by fuzzing a NIfTI file):
  // each takes its own patient axis, so the volume reads back in the patient's frame.
  TempDir dir;
  Volume v = rampVolumesOfEveryType()[1];
  const double h = std::sqrt(0.5);
  v.setDirection(glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, -h, h), glm::dvec3(0, -h, -h)),
                 true);
  const std::string path = dir.path("tilted.mha");
  writeVolume(path, v);
  EXPECT_EQ(headerLine(readTextFile(path), "AnatomicalOrientation"), "AnatomicalOrientation = RPS");
  const Volume back = loadVolume(path);
  EXPECT_TRUE(back.patientFrame());
  expectSameVolume(v, back, 1e-12);
}

// A header (.mhd) and its raw data beside it read back as the volume written; the data are
// the voxels as they are, little-endian, and the header names them.
TEST(MetaImageWriter, AHeaderAndItsDataBesideItReadBack) {
  TempDir dir;
  std::vector<Volume> volumes = rampVolumesOfEveryType();
  volumes[3].setDirection(
      glm::dmat3(glm::rotate(glm::dmat4(1.0), -0.7, glm::normalize(glm::dvec3(3, 1, 2)))), true);
  int n = 0;
  for (const Volume& v : volumes) {
    SCOPED_TRACE(scalarName(v.type()));
    const std::string path = dir.path("v" + std::to_string(n++) + ".mhd");
    writeVolume(path, v);
    expectSameVolume(v, loadVolume(path), 1e-12);
    const std::string header = readTextFile(path);
    EXPECT_EQ(header.size(), header.find("ElementDataFile = ") + 18 + 7)  // "vN.raw\n" ends it
        << header;
    EXPECT_EQ(headerLine(header, "CompressedData"), "CompressedData = False");
    EXPECT_EQ(readTextFile(metaImageDataFileOf(path)),
              std::string(v.bytes().begin(), v.bytes().end()));  // a little-endian host
  }
  EXPECT_EQ(metaImageDataPath("/a/ct.scan.mhd"), "/a/ct.scan.raw");
  EXPECT_EQ(headerLine(readTextFile(dir.path("v0.mhd")), "ElementDataFile"),
            "ElementDataFile = v0.raw");
}

// LIDC2.mha, written by ITK (axes +x, -y, -z: "RPS"), written again names the same axes and
// reads back the same.
TEST(MetaImageWriter, AFileItkWroteKeepsItsPlacement) {
  const std::string source = std::string(EWA_SHARED_DATA) + "/lidc2/LIDC2.mha";
  if (!std::filesystem::exists(source)) GTEST_SKIP() << source << " is absent";
  TempDir dir;
  const Volume v = loadVolume(source);
  writeVolume(dir.path("lidc2.mha"), v);
  expectSameVolume(v, loadVolume(dir.path("lidc2.mha")), 1e-12);
  const std::string written = readTextFile(dir.path("lidc2.mha"));
  EXPECT_EQ(headerLine(written, "AnatomicalOrientation"), "AnatomicalOrientation = RPS");
  EXPECT_EQ(headerLine(written, "DimSize"), "DimSize = 256 256 133");
}

}  // namespace
}  // namespace ewa
