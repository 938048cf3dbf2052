// Folders of DICOM files beside other files: a TIFF export beside the series, a multi-frame file
// in the series list.
#include <gtest/gtest.h>

#include <string>

#include "dicom_byte_files.h"
#include "io/volume_loader.h"
#include "medical_test_files.h"

namespace ewa {
namespace {

using namespace testing;

TEST(DicomFolders, ASeriesBesideTiffFilesOpensAsTheSeries) {
  TempDir dir;
  const std::string series = dicomSeries(dir, "s", 3);
  const Volume alone = loadVolume(series);
  // A viewer's TIFF export beside the slices, of another size.
  ASSERT_TRUE(writeTiff<uint8_t>(series + "/export.tif", 7, 6, {std::vector<uint8_t>(42, 9)}, 1));
  const Volume v = loadVolume(series);
  EXPECT_EQ(v.dims(), alone.dims());
  EXPECT_EQ(v.bytes(), alone.bytes());
  // A folder of TIFF files alone is still a TIFF stack.
  ASSERT_TRUE(writeTiff<uint8_t>(dir.path("t.tif"), 7, 6, {std::vector<uint8_t>(42, 9)}, 1));
  std::filesystem::create_directories(dir.path("tiffs"));
  std::filesystem::copy_file(dir.path("t.tif"), dir.path("tiffs/a.tif"));
  std::filesystem::copy_file(dir.path("t.tif"), dir.path("tiffs/b.tif"));
  EXPECT_EQ(loadVolume(dir.path("tiffs")).dims(), (std::array<int64_t, 3>{7, 6, 2}));
}

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
