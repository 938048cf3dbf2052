// A DICOM series of several volumes at the same positions, short of files: volumes told apart.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "io/volume_loader.h"
#include "loader_test_files.h"
#include "medical_test_files.h"

namespace ewa {
namespace {

using testing::allNotes;
using testing::TempDir;

// Three volumes at four positions 2 mm apart, InstanceNumbers one volume after another (as
// scanners number a time series), file names against that order; volume v's values 1000 v +
// 10 z. `skip(v, z)`: that file is not written.
template <typename Skip>
void writeVolumes(TempDir& dir, const std::string& name, Skip skip) {
  std::filesystem::create_directories(dir.path(name));
  testing::DicomSliceSpec spec;
  for (int v = 0; v < 3; ++v)
    for (int z = 0; z < 4; ++z) {
      if (skip(v, z)) continue;
      spec.position = {0.0, 0.0, 2.0 * z};
      spec.values.assign(spec.rows * spec.columns, int16_t(1000 * v + 10 * z));
      const std::string file = dir.path(name + "/f" + std::to_string(20 - (4 * v + z)) + ".dcm");
      ASSERT_TRUE(testing::writeDicomSlice(file, spec));
      ASSERT_TRUE(testing::editDicom(file, [&](gdcm::DataSet& ds) {
        gdcm::Attribute<0x0020, 0x0013> instance;
        instance.SetValue(4 * v + z + 1);
        ds.Replace(instance.GetAsDataElement());
      }));
    }
}

// Volume 1 lacks its third slice (a missing file), volume 2 its last two (a scan cut short):
// positions hold 1 to 3 slices. Each volume opens with its own slices, and a note names the
// short ones; volume 1's gap is filled in, with a warning.
TEST(DicomShortVolumes, VolumesShortOfFilesOpenOneByOne) {
  TempDir dir;
  writeVolumes(dir, "fmri", [](int v, int z) { return (v == 1 && z == 2) || (v == 2 && z >= 2); });
  const Volume first = loadVolume(dir.path("fmri"));
  ASSERT_EQ(first.dims()[2], 4);
  EXPECT_DOUBLE_EQ(first.spacing().z, 2.0);
  for (int z = 0; z < 4; ++z) EXPECT_EQ(first.value(0, 0, z), 10 * z) << z;
  const std::string notes = allNotes(first);
  EXPECT_NE(notes.find("3 volumes at the same 4 positions (diffusion directions, echoes or time "
                       "points): volume 0 open (--frame N opens another, 0 to 2); volumes short "
                       "of slices, by InstanceNumber (an interrupted scan? a missing file?), with "
                       "the positions each holds: 1 (3), 2 (2)"),
            std::string::npos)
      << notes;
  EXPECT_EQ(notes.find("warning"), std::string::npos) << notes;

  const Volume second = loadVolume(dir.path("fmri"), {"", 1, 0, {}});
  ASSERT_EQ(second.dims()[2], 4);
  EXPECT_DOUBLE_EQ(second.spacing().z, 2.0);
  EXPECT_EQ(second.value(2, 1, 0), 1000);
  EXPECT_EQ(second.value(2, 1, 1), 1010);
  EXPECT_EQ(second.value(2, 1, 2), 1020);  // the slice at 4 mm is missing: filled in
  EXPECT_EQ(second.value(2, 1, 3), 1030);
  EXPECT_NE(allNotes(second).find("warning: 1 missing slice"), std::string::npos)
      << allNotes(second);

  const Volume third = loadVolume(dir.path("fmri"), {"", 2, 0, {}});
  ASSERT_EQ(third.dims()[2], 2);
  EXPECT_DOUBLE_EQ(third.spacing().z, 2.0);
  EXPECT_EQ(third.value(1, 1, 0), 2000);
  EXPECT_EQ(third.value(1, 1, 1), 2010);
  testing::expectLoadError(
      [&] {
        loadVolume(dir.path("fmri"), {"", 3, 0, {}});
      },
      dir.path("fmri"), "--frame 3 is out of range (the series has 3 volumes at its positions)");
}

// The first file of all missing: InstanceNumbers start at 2, and volume 0 is the short one
// (volume 1's first slice, at the lowest position, follows volume 0's last: a new volume).
TEST(DicomShortVolumes, TheFirstFileMissing) {
  TempDir dir;
  writeVolumes(dir, "s", [](int v, int z) { return v == 0 && z == 0; });
  const Volume first = loadVolume(dir.path("s"));
  ASSERT_EQ(first.dims()[2], 3);
  EXPECT_EQ(first.value(0, 0, 0), 10);
  EXPECT_NE(allNotes(first).find("with the positions each holds: 0 (3)"), std::string::npos)
      << allNotes(first);
  const Volume last = loadVolume(dir.path("s"), {"", 2, 0, {}});
  ASSERT_EQ(last.dims()[2], 4);
  for (int z = 0; z < 4; ++z) EXPECT_EQ(last.value(0, 0, z), 2000 + 10 * z) << z;
}

// An enhanced file of two volumes whose second is a frame short: its frames' indices number
// one volume after another, so both open, the second with two slices.
TEST(DicomShortVolumes, AnEnhancedFileAFrameShort) {
  TempDir dir;
  testing::EnhancedDicomSpec enhanced;
  enhanced.frameZ = {0.0, 2.0, 4.0, 0.0, 2.0};
  ASSERT_TRUE(testing::writeEnhancedDicom(dir.path("two.dcm"), enhanced));
  const Volume first = loadVolume(dir.path("two.dcm"));
  EXPECT_EQ(first.dims()[2], 3);
  EXPECT_NE(allNotes(first).find("2 volumes at the same 3 positions"), std::string::npos)
      << allNotes(first);
  EXPECT_NE(allNotes(first).find("with the positions each holds: 1 (2)"), std::string::npos)
      << allNotes(first);
  const Volume second = loadVolume(dir.path("two.dcm"), {"", 1, 0, {}});
  ASSERT_EQ(second.dims()[2], 2);
  EXPECT_DOUBLE_EQ(second.spacing().z, 2.0);
  EXPECT_EQ(second.value(1, 1, 1), 1 + 10 + 200);
}

// Numbers that do not tell the volumes apart (two images numbered alike): one line naming the
// folder, as positions holding unequal numbers always were before.
TEST(DicomShortVolumes, VolumesTheNumbersCannotTellApartFailInOneLine) {
  TempDir dir;
  writeVolumes(dir, "s", [](int v, int z) { return v == 2 && z == 3; });
  ASSERT_TRUE(testing::editDicom(dir.path("s/f20.dcm"), [](gdcm::DataSet& ds) {
    gdcm::Attribute<0x0020, 0x0013> instance;  // volume 0 at 0 mm numbered as volume 0 at 2 mm
    instance.SetValue(2);
    ds.Replace(instance.GetAsDataElement());
  }));
  testing::expectVolumeLoadError(dir.path("s"), "4 slice positions holding 2 to 3 slices each (");
  testing::expectVolumeLoadError(dir.path("s"),
                                 "share one position): several volumes in the series, unevenly, "
                                 "and their InstanceNumbers do not tell them apart");
}

}  // namespace
}  // namespace ewa
