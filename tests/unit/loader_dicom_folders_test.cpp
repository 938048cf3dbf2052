// Folders of DICOM files: a multi-frame file in the series list.
#include <gtest/gtest.h>

#include <string>

#include "dicom_byte_files.h"
#include "io/volume_loader.h"
#include "medical_test_files.h"

namespace ewa {
namespace {

using namespace testing;

TEST(DicomFolders, TheSeriesListGivesAMultiFrameFilesFrames) {
  TempDir dir;
  const std::string series = dicomSeries(dir, "s", 3);
  ByteImageSpec spec;
  spec.frames = 6;
  spec.seriesUid = "1.2.826.0.1.3680043.2.1125.78";
  dir.write("s/cine.dcm", part10(imageDataSet(spec), kExplicitLittle));
  const Volume v = loadVolume(series);
  EXPECT_EQ(v.dims(), (std::array<int64_t, 3>{5, 4, 3}));
  ASSERT_EQ(v.seriesChoices().size(), 2u);
  EXPECT_EQ(v.seriesChoices()[0].label, "3 slices");
  EXPECT_EQ(v.seriesChoices()[1].label, "6 frames");
  EXPECT_TRUE(hasNoteWith(v, "series 1.2.826.0.1.3680043.2.1125.78: 6 frames (--series UID"))
      << allNotes(v);
}

}  // namespace
}  // namespace ewa
