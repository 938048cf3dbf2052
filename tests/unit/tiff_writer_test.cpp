// The TIFF writer (--save-volume NAME.tif): an OME-TIFF stack that loadVolume reads back as the
// volume written, with OME's sizes and units, and notes for what TIFF cannot keep.
#include "io/tiff_writer.h"

#include <gtest/gtest.h>
#include <tiffio.h>

#include <memory>
#include <string>
#include <vector>

#include "io/tiff_pages.h"
#include "io/volume_loader.h"
#include "io/volume_writer.h"
#include "loader_test_files.h"
#include "volume_round_trip.h"

namespace ewa {
namespace {

using testing::expectSameVolume;
using testing::rampVolumesOfEveryType;
using testing::TempDir;

// `v` at the origin on the world's axes, with `unit`: all a TIFF keeps.
Volume atOrigin(const Volume& v, const std::string& unit) {
  Volume out(v.dims(), v.spacing(), glm::dvec3(0.0), v.type(), std::vector<uint8_t>(v.bytes()));
  out.setUnit(unit);
  return out;
}

// The first page's description, the page count and a few tags of the file at `path`.
struct TiffFacts {
  std::string description;
  int pages = 0;
  uint16_t compression = 0, sampleFormat = 0, bits = 0, resolutionUnit = 0;
  float xResolution = 0.0f;
};

TiffFacts tiffFacts(const std::string& path) {
  std::unique_ptr<TIFF, TiffCloser> t(TIFFOpen(path.c_str(), "r"));
  TiffFacts f;
  if (!t) return f;
  char* text = nullptr;
  if (TIFFGetField(t.get(), TIFFTAG_IMAGEDESCRIPTION, &text) && text) f.description = text;
  TIFFGetField(t.get(), TIFFTAG_COMPRESSION, &f.compression);
  TIFFGetFieldDefaulted(t.get(), TIFFTAG_SAMPLEFORMAT, &f.sampleFormat);
  TIFFGetField(t.get(), TIFFTAG_BITSPERSAMPLE, &f.bits);
  TIFFGetField(t.get(), TIFFTAG_RESOLUTIONUNIT, &f.resolutionUnit);
  TIFFGetField(t.get(), TIFFTAG_XRESOLUTION, &f.xResolution);
  f.pages = TIFFNumberOfDirectories(t.get());
  return f;
}

TEST(TiffWriter, WhatIsReadBackIsTheVolumeWritten) {
  TempDir dir;
  const char* units[] = {"mm", "\xC2\xB5m", "", "nm"};
  int n = 0;
  for (const Volume& ramp : rampVolumesOfEveryType()) {
    const Volume v = atOrigin(ramp, units[n]);
    SCOPED_TRACE(scalarName(v.type()));
    const std::string path = dir.path("v" + std::to_string(n++) + ".tif");
    writeVolume(path, v);
    expectSameVolume(v, loadVolume(path), 0.0);
    EXPECT_TRUE(savedVolumeLosses(path, v).empty());
  }
  const TiffFacts um =
      tiffFacts(dir.path("v1.tif"));  // int16 in µm, 2 x 3 x 4, spacing 0.5, 1.25, 3
  EXPECT_EQ(um.pages, 4);
  EXPECT_EQ(um.compression, COMPRESSION_ADOBE_DEFLATE);
  EXPECT_EQ(um.sampleFormat, SAMPLEFORMAT_INT);
  EXPECT_EQ(um.bits, 16);
  EXPECT_EQ(um.resolutionUnit, RESUNIT_CENTIMETER);
  EXPECT_FLOAT_EQ(um.xResolution, 20000.0f);  // 0.5 µm: 20000 pixels a centimetre
  EXPECT_EQ(um.description.rfind("<?xml", 0), 0u);
  EXPECT_NE(um.description.find("Type=\"int16\" SizeX=\"2\" SizeY=\"3\" SizeZ=\"4\""),
            std::string::npos);
  EXPECT_NE(um.description.find("PhysicalSizeZ=\"3\" PhysicalSizeZUnit=\"\xC2\xB5m\""),
            std::string::npos);
  EXPECT_NE(um.description.find("<TiffData IFD=\"0\" PlaneCount=\"4\"/>"), std::string::npos);
  // No unit: OME's "reference frame", read back as none; float32 as OME's "float".
  const TiffFacts plain = tiffFacts(dir.path("v2.tif"));
  EXPECT_NE(plain.description.find("PhysicalSizeXUnit=\"reference frame\""), std::string::npos);
  EXPECT_EQ(plain.resolutionUnit, RESUNIT_NONE);
  EXPECT_EQ(tiffFacts(dir.path("v3.tif")).sampleFormat, SAMPLEFORMAT_IEEEFP);
}

// Pages larger than one strip, and a name needing XML escapes, read back the same.
TEST(TiffWriter, PagesOfManyStripsReadBack) {
  TempDir dir;
  std::vector<uint8_t> bytes(size_t(300) * 200 * 3 * 2);
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = uint8_t((i * 7919) >> 3);
  Volume v({300, 200, 3}, glm::dvec3(0.2, 0.2, 1.5), glm::dvec3(0.0), ScalarType::UInt16,
           std::move(bytes));
  v.setUnit("\xC2\xB5m");
  const std::string path = dir.path("a<b>&\"c\".ome.tiff");
  writeVolume(path, v);
  expectSameVolume(v, loadVolume(path), 0.0);
  EXPECT_NE(tiffFacts(path).description.find("Name=\"a&lt;b&gt;&amp;&quot;c&quot;.ome.tiff\""),
            std::string::npos);
}

// The origin is kept as each slice's OME Plane position, in the volume's unit.
TEST(TiffWriter, OriginIsThePlanePositions) {
  TempDir dir;
  for (const char* unit : {"mm", ""}) {
    SCOPED_TRACE(unit);
    Volume ramp = rampVolumesOfEveryType()[1];  // int16, origin (-10, 20.5, 7), spacing z 3
    ramp.setUnit(unit);
    const std::string path = dir.path(std::string("o") + unit + ".tif");
    writeVolume(path, ramp);
    EXPECT_TRUE(savedVolumeLosses(path, ramp).empty());
    expectSameVolume(ramp, loadVolume(path), 0.0);
    const std::string u = *unit ? unit : "reference frame";
    EXPECT_NE(tiffFacts(path).description.find(
                  "<Plane TheZ=\"3\" TheC=\"0\" TheT=\"0\" PositionX=\"-10\" PositionXUnit=\"" + u +
                  "\" PositionY=\"20.5\" PositionYUnit=\"" + u + "\" PositionZ=\"16\""),
              std::string::npos);
  }
  // At zero no Plane is written.
  writeVolume(dir.path("zero.tif"), atOrigin(rampVolumesOfEveryType()[1], "mm"));
  EXPECT_EQ(tiffFacts(dir.path("zero.tif")).description.find("<Plane"), std::string::npos);
}

// Sizes of 1 that the file gives are not "assumed": no note says so.
TEST(TiffWriter, UnitSizesReadBackWithoutAssumptions) {
  TempDir dir;
  Volume v({2, 2, 2}, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::UInt8,
           std::vector<uint8_t>{1, 2, 3, 4, 5, 6, 7, 8});
  v.setUnit("mm");
  writeVolume(dir.path("ones.tif"), v);
  const Volume back = loadVolume(dir.path("ones.tif"));
  expectSameVolume(v, back, 0.0);
  EXPECT_FALSE(testing::hasNoteWith(back, "assumed")) << ::testing::PrintToString(back.notes());
}

TEST(TiffWriter, SaysWhatATiffCannotKeep) {
  const Volume ramp = rampVolumesOfEveryType()[0];  // origin (-10, 20.5, 7): kept
  EXPECT_TRUE(savedVolumeLosses("v.tif", ramp).empty());
  Volume patient = atOrigin(ramp, "mm");
  patient.setDirection(glm::dmat3(1.0), true);
  std::vector<std::string> losses = savedVolumeLosses("v.TIFF", patient);
  ASSERT_EQ(losses.size(), 1u);
  EXPECT_NE(losses[0].find("patient axes"), std::string::npos);

  Volume turned = atOrigin(ramp, "inch");
  turned.setDirection(glm::dmat3(0, 1, 0, -1, 0, 0, 0, 0, 1), false);
  losses = savedVolumeLosses("v.tif", turned);
  ASSERT_EQ(losses.size(), 2u);
  EXPECT_NE(losses[0].find("axis directions"), std::string::npos);
  EXPECT_NE(losses[1].find("'inch'"), std::string::npos);
  // The file is still written, on the world's axes and without the unit.
  TempDir dir;
  EXPECT_EQ(writeVolumeAndLosses(dir.path("turned.tif"), turned), losses);
  const Volume back = loadVolume(dir.path("turned.tif"));
  EXPECT_EQ(back.bytes(), turned.bytes());
  EXPECT_EQ(back.direction(), glm::dmat3(1.0));
  EXPECT_EQ(back.unit(), "");
}

TEST(TiffWriter, AFolderThatIsMissingIsAOneLineError) {
  const Volume v = atOrigin(rampVolumesOfEveryType()[0], "");
  try {
    writeVolume("/no/such/folder/v.tif", v);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("/no/such/folder/v.tif: ", 0), 0u) << e.what();
  }
  EXPECT_EQ(savedVolumeFormat("v.tif"), SavedVolumeFormat::Tiff);
  EXPECT_EQ(savedVolumeExtension(SavedVolumeFormat::Tiff), ".tif");
  EXPECT_EQ(savedVolumeExtension(SavedVolumeFormat::Nifti), ".nii.gz");
}

}  // namespace
}  // namespace ewa
