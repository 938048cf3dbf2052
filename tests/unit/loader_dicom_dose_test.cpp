// RT Dose grids: the z spacing from GridFrameOffsetVector (3004,000C), the values scaled by
// DoseGridScaling (3004,000E).
#include <gtest/gtest.h>

#include <string>

#include "dicom_byte_files.h"
#include "io/volume_loader.h"
#include "medical_test_files.h"

namespace ewa {
namespace {

using namespace testing;

// A dose grid of `offsets.size()` frames (frame f's values i + 10 j + 1000 f) with those offsets
// and a scaling.
std::string doseFile(const TempDir& dir, const std::string& name, const std::string& offsets,
                     int frames, const std::string& scaling = "") {
  ByteImageSpec spec;
  spec.sopClass = "1.2.840.10008.5.1.4.1.1.481.2";
  spec.modality = "RTDOSE";
  spec.frames = frames;
  spec.z = 0.0;
  spec.beforePixels =
      explicitElement(0x3004, 0x000c, "DS", evenText(offsets)) +
      (scaling.empty() ? std::string() : explicitElement(0x3004, 0x000e, "DS", evenText(scaling)));
  return dir.write(name, part10(imageDataSet(spec), kExplicitLittle, spec.sopClass));
}

TEST(DicomDose, GridFrameOffsetsGiveTheSliceSpacing) {
  TempDir dir;
  // Relative offsets (from 0) and absolute ones (the frames' z) alike: 5 apart.
  for (const char* offsets : {"0\\5\\10\\15", "-20\\-15\\-10\\-5"}) {
    const Volume v = loadVolume(doseFile(dir, "dose.dcm", offsets, 4));
    EXPECT_EQ(v.dims(), (std::array<int64_t, 3>{4, 3, 4}));
    EXPECT_DOUBLE_EQ(v.spacing().z, 5.0) << offsets;
    EXPECT_EQ(v.origin(), glm::dvec3(0.0));
    EXPECT_EQ(v.value(1, 2, 3), 1 + 20 + 3000);
    EXPECT_FALSE(hasNoteWith(v, "slice spacing 1 assumed")) << allNotes(v);
    EXPECT_TRUE(hasNoteWith(v, "GridFrameOffsetVector")) << allNotes(v);
  }
  // Offsets running the other way: the frames are put in order along the normal.
  const Volume down = loadVolume(doseFile(dir, "down.dcm", "0\\-5\\-10", 3));
  EXPECT_DOUBLE_EQ(down.spacing().z, 5.0);
  EXPECT_EQ(down.origin(), glm::dvec3(0, 0, -10));
  EXPECT_EQ(down.value(0, 0, 0), 2000);
  // Uneven offsets: treated as a series' uneven gaps are (a missing plane filled in, warned).
  const Volume gap = loadVolume(doseFile(dir, "gap.dcm", "0\\5\\15\\20", 4));
  EXPECT_EQ(gap.dims()[2], 5);
  EXPECT_DOUBLE_EQ(gap.spacing().z, 5.0);
  EXPECT_TRUE(hasNoteWith(gap, "warning: 1 missing slice")) << allNotes(gap);
  // Offsets that do not cover the frames: kept in stored order, with the note saying so.
  const Volume wrong = loadVolume(doseFile(dir, "wrong.dcm", "0\\5", 3));
  EXPECT_DOUBLE_EQ(wrong.spacing().z, 1.0);
  EXPECT_TRUE(hasNoteWith(wrong, "slice spacing 1 assumed")) << allNotes(wrong);
}

TEST(DicomDose, DoseGridScalingScalesTheValues) {
  TempDir dir;
  const Volume v = loadVolume(doseFile(dir, "scaled.dcm", "0\\2.5", 2, "0.5"));
  EXPECT_DOUBLE_EQ(v.spacing().z, 2.5);
  EXPECT_DOUBLE_EQ(v.value(1, 2, 1), 0.5 * (1 + 20 + 1000));
  EXPECT_DOUBLE_EQ(v.maxValue(), 0.5 * (3 + 20 + 1000));
}

TEST(DicomDose, HeadersGdcmAbortsOnAreRefusedInOneLine) {
  TempDir dir;
  // GDCM's reader takes the spacing from two offsets, sized by NumberOfFrames, and asserts
  // when either is missing: a one-frame grid, offsets that are not numbers, no frame count.
  expectVolumeLoadError(doseFile(dir, "one.dcm", "0", 1),
                        "an RT Dose GridFrameOffsetVector (3004,000C) without NumberOfFrames");
  expectVolumeLoadError(doseFile(dir, "nan.dcm", "nan\\5", 2),
                        "an RT Dose GridFrameOffsetVector (3004,000C) of fewer than two numbers");
  expectVolumeLoadError(doseFile(dir, "single.dcm", "0", 2),
                        "an RT Dose GridFrameOffsetVector (3004,000C) of fewer than two numbers");
  // Deflated too.
  ByteImageSpec spec;
  spec.sopClass = "1.2.840.10008.5.1.4.1.1.481.2";
  spec.beforePixels = explicitElement(0x3004, 0x000c, "DS", evenText("0\\5"));
  expectVolumeLoadError(
      dir.write("deflated.dcm", part10(rawDeflate(imageDataSet(spec)), kDeflated, spec.sopClass)),
      "without NumberOfFrames");
  // No offsets, or an empty element: GDCM leaves the spacing alone, and so do we.
  EXPECT_EQ(loadVolume(doseFile(dir, "none.dcm", "", 2)).dims()[2], 2);
}

}  // namespace
}  // namespace ewa
