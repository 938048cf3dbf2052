// The NIfTI writer (--save-volume NAME.nii / .nii.gz): what loadVolume reads back is the
// volume written, through the sform and through the qform alone, and NIfTI-2 where NIfTI-1
// cannot hold it.
#include "io/nifti_writer.h"

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
using testing::rampVolume;
using testing::rampVolumesOfEveryType;
using testing::TempDir;

// NIfTI-1 stores the placement as float32.
constexpr double kFloatTolerance = 1e-5;

glm::dmat3 rotation(double angle, glm::dvec3 axis) {
  return glm::dmat3(glm::rotate(glm::dmat4(1.0), angle, glm::normalize(axis)));
}

TEST(NiftiWriter, WhatIsReadBackIsTheVolumeWritten) {
  TempDir dir;
  std::vector<Volume> volumes = rampVolumesOfEveryType();
  for (Volume& v : volumes) v.setDirection(rotation(0.3, {1, 2, 3}), true);
  volumes[1].setUnit("mm");
  volumes[2].setUnit("\xC2\xB5m");
  volumes[3].setUnit("m");
  int n = 0;
  for (const Volume& v : volumes) {
    SCOPED_TRACE(scalarName(v.type()));
    for (const char* extension : {".nii", ".nii.gz"}) {
      const std::string path = dir.path("v" + std::to_string(n++) + extension);
      writeVolume(path, v);
      expectSameVolume(v, loadVolume(path), kFloatTolerance);
    }
  }
  // Compressed, the file starts with gzip's magic; plain, with the header's size 348.
  const std::string plain = readTextFile(dir.path("v0.nii"));
  const std::string packed = readTextFile(dir.path("v1.nii.gz"));
  EXPECT_EQ(uint8_t(packed[0]), 0x1f);
  EXPECT_EQ(uint8_t(packed[1]), 0x8b);
  EXPECT_EQ(uint8_t(plain[0]) | uint8_t(plain[1]) << 8, 348);
  EXPECT_EQ(plain.size(), 352u + 24u);  // header, extension flag, 24 bytes of voxels
}

// A volume at the origin on the identity axes with no patient frame is written without a
// transform (pixdim only) and reads back as it was; one placed elsewhere keeps its world
// positions through the sform, read back as patient axes (NIfTI has no other world).
TEST(NiftiWriter, PlainVolumesKeepTheirPlaces) {
  TempDir dir;
  Volume plain({2, 3, 4}, glm::dvec3(0.5, 1.25, 3.0), glm::dvec3(0.0), ScalarType::UInt8,
               std::vector<uint8_t>(24, 9));
  plain.setUnit("\xC2\xB5m");
  writeVolume(dir.path("plain.nii"), plain);
  expectSameVolume(plain, loadVolume(dir.path("plain.nii")), kFloatTolerance);

  const Volume moved = rampVolume<uint8_t>(ScalarType::UInt8, 1, 0);
  writeVolume(dir.path("moved.nii"), moved);
  const Volume back = loadVolume(dir.path("moved.nii"));
  expectSameVolume(moved, back, kFloatTolerance, false);
  EXPECT_TRUE(back.patientFrame());
}

// Readers that use the qform alone (sform_code 0) find the placement the sform gives: rotations
// of every branch of the quaternion's formula (trace large, and half turns about x, y and z),
// with and without a reflection (qfac -1; the loader reverses such a file's slices, whichever
// transform it reads).
TEST(NiftiWriter, TheQformAloneGivesTheSamePlacement) {
  TempDir dir;
  const std::vector<glm::dmat3> rotations = {
      rotation(0.3, {1, 2, 3}), rotation(M_PI, {1, 0.1, 0.2}), rotation(M_PI, {0.1, 1, 0.2}),
      rotation(M_PI, {0.1, 0.2, 1}), glm::dmat3(1.0)};
  int n = 0;
  for (const glm::dmat3& r : rotations)
    for (const bool mirrored : {false, true}) {
      const std::string name = "v" + std::to_string(n++);
      SCOPED_TRACE(name + (mirrored ? " mirrored" : ""));
      Volume v = rampVolume<int16_t>(ScalarType::Int16, 3, -20);
      glm::dmat3 axes = r;
      if (mirrored) axes[1] = -axes[1];
      v.setDirection(axes, true);
      std::string bytes = encodeNifti(v);
      const Volume bySform = loadVolume(dir.write(name + "s.nii", bytes));
      ASSERT_EQ(bytes[252], 1);     // qform_code
      bytes[254] = bytes[255] = 0;  // sform_code
      const Volume byQform = loadVolume(dir.write(name + "q.nii", bytes));
      expectSameVolume(bySform, byQform, kFloatTolerance);
      if (!mirrored) expectSameVolume(v, byQform, kFloatTolerance);
    }
}

// An axis over 32767 voxels, or a spacing or origin beyond float32, goes to NIfTI-2 (64-bit
// dims and doubles), with a note; what reads back is the volume written, to the last digit.
TEST(NiftiWriter, WhatNifti1CannotHoldIsWrittenAsNifti2) {
  TempDir dir;
  std::vector<uint8_t> ramp(40000);
  for (size_t i = 0; i < ramp.size(); ++i) ramp[i] = uint8_t(i * 7);
  Volume wide({40000, 1, 1}, glm::dvec3(0.1, 0.2, 0.3), glm::dvec3(1.0, 2.0, 3.0),
              ScalarType::UInt8, ramp);
  wide.setUnit("mm");
  Volume huge({2, 2, 2}, glm::dvec3(1.0, 1e39, 1e-40), glm::dvec3(-1e300, 0.0, 0.0),
              ScalarType::UInt8, std::vector<uint8_t>{1, 2, 3, 4, 5, 6, 7, 8});
  huge.setDirection(rotation(0.3, {1, 2, 3}), true);
  for (const Volume* v : {&wide, &huge}) {
    EXPECT_TRUE(needsNifti2(*v));
    for (const char* name : {"v.nii", "v.nii.gz"}) {
      SCOPED_TRACE(std::to_string(v->dims()[0]) + " " + name);
      const std::string path = dir.path(name);
      const std::vector<std::string> notes = writeVolumeAndLosses(path, *v);
      ASSERT_EQ(notes.size(), 1u);
      EXPECT_NE(notes[0].find("NIfTI-2"), std::string::npos) << notes[0];
      const Volume back = loadVolume(path);
      EXPECT_EQ(back.dims(), v->dims());
      EXPECT_EQ(back.bytes(), v->bytes());
      EXPECT_EQ(back.unit(), v->unit());
      for (int a = 0; a < 3; ++a) {
        EXPECT_DOUBLE_EQ(back.spacing()[a], v->spacing()[a]) << a;
        EXPECT_DOUBLE_EQ(back.origin()[a], v->origin()[a]) << a;
        for (int b = 0; b < 3; ++b)
          EXPECT_NEAR(back.direction()[a][b], v->direction()[a][b], 1e-12);
      }
    }
  }
  const std::string header = encodeNifti(wide).substr(0, 12);
  EXPECT_EQ(header.substr(0, 4), testing::uintBytes(540, 4));
  EXPECT_EQ(header.substr(4, 8), std::string("n+2\0\r\n\032\n", 8));
  // What NIfTI-1 holds stays NIfTI-1, with no note.
  Volume small = rampVolume<int16_t>(ScalarType::Int16, 3, -20);
  EXPECT_FALSE(needsNifti2(small));
  EXPECT_EQ(encodeNifti(small).substr(0, 4), testing::uintBytes(348, 4));
  EXPECT_TRUE(writeVolumeAndLosses(dir.path("small.nii"), small).empty());
  // A name of no format it writes.
  EXPECT_FALSE(savedVolumeFormat("v.vti"));
  EXPECT_FALSE(savedVolumeFormat(".nii"));
  EXPECT_EQ(savedVolumeFormat("dir.nii/V.NII.GZ"), SavedVolumeFormat::NiftiGzip);
  EXPECT_THROW(writeVolume(dir.path("v.vti"), wide), std::runtime_error);
  EXPECT_FALSE(std::filesystem::exists(dir.path("v.vti")));
}

// A real file (big-endian int16 with a qform) written again as .nii.gz reads back the same.
TEST(NiftiWriter, ASharedFileReadsBackTheSame) {
  const std::string source = std::string(EWA_SHARED_DATA) + "/nifti/anatomical.nii";
  if (!std::filesystem::exists(source)) GTEST_SKIP() << source << " is absent";
  TempDir dir;
  const Volume v = loadVolume(source);
  writeVolume(dir.path("anatomical.nii.gz"), v);
  expectSameVolume(v, loadVolume(dir.path("anatomical.nii.gz")), kFloatTolerance);
}

}  // namespace
}  // namespace ewa
