// RGB DICOM series: each channel opens as a volume (--channel), by pixel, by plane and
// compressed; channels that are not there and colour spaces that are not RGB fail in one line.
#include <gtest/gtest.h>

#include <string>

#include "io/volume_loader.h"
#include "medical_test_files.h"

namespace ewa {
namespace {

using testing::allNotes;
using testing::dicomSeries;
using testing::expectLoadError;
using testing::rgbTestSample;
using testing::TempDir;

Volume loadChannel(const std::string& path, int channel) {
  LoadOptions options;
  options.channel = channel;
  return loadVolume(path, options);
}

// Every voxel of channel `c` holds the written sample of its column, row and slice.
void expectChannel(const Volume& v, int c) {
  ASSERT_EQ(v.dims(), (std::array<int64_t, 3>{5, 4, 3}));
  EXPECT_EQ(v.type(), ScalarType::UInt8);
  EXPECT_EQ(v.spacing(), glm::dvec3(0.75, 0.5, 2.0));
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 5; ++i)
        ASSERT_EQ(v.value(i, j, k), double(rgbTestSample(c, i, j, 2 * k)))
            << "channel " << c << " at " << i << "," << j << "," << k;
}

TEST(DicomColour, EachChannelOfAnRgbSeriesByPixelAndByPlane) {
  TempDir dir;
  for (bool planar : {false, true}) {
    testing::DicomSliceSpec spec;
    spec.rgb = true;
    spec.planar = planar;
    const std::string folder = dicomSeries(dir, planar ? "planes" : "pixels", 3, spec);
    for (int c = 0; c < 3; ++c) {
      SCOPED_TRACE(planar ? "by plane" : "by pixel");
      const Volume v = loadChannel(folder, c);
      expectChannel(v, c);
      EXPECT_NE(allNotes(v).find("RGB: 3 channels; showing channel " + std::to_string(c) +
                                 " (--channel N picks another)"),
                std::string::npos)
          << allNotes(v);
    }
  }
}

TEST(DicomColour, CompressedRgbSlicesLoadLikeTheOthers) {
  TempDir dir;
  testing::DicomSliceSpec spec;
  spec.rgb = true;
  const std::string folder = dicomSeries(dir, "c", 3, spec);
  ASSERT_TRUE(testing::recompressDicom(folder + "/im1.dcm", gdcm::TransferSyntax::RLELossless));
  ASSERT_TRUE(
      testing::recompressDicom(folder + "/im2.dcm", gdcm::TransferSyntax::JPEGLosslessProcess14_1));
  EXPECT_NE(std::filesystem::file_size(folder + "/im1.dcm"),
            std::filesystem::file_size(folder + "/im0.dcm"));
  for (int c = 0; c < 3; ++c) expectChannel(loadChannel(folder, c), c);
}

TEST(DicomColour, MissingChannelsAndOtherColourSpacesFailWithOneLine) {
  TempDir dir;
  testing::DicomSliceSpec spec;
  spec.rgb = true;
  const std::string rgb = dicomSeries(dir, "rgb", 2, spec);
  expectLoadError([&] { loadChannel(rgb, 3); }, rgb, "--channel 3 is out of range (3 channels)");
  const std::string grey = dicomSeries(dir, "grey", 2);
  expectLoadError([&] { loadChannel(grey, 1); }, grey, "--channel 1 is out of range (1 channel)");
  // The same samples declared YBR_FULL: not converted, refused.
  const std::string ybr = dicomSeries(dir, "ybr", 1, spec);
  ASSERT_TRUE(testing::editDicom(ybr + "/im0.dcm", [](gdcm::DataSet& ds) {
    gdcm::Attribute<0x0028, 0x0004> photometric;
    photometric.SetValue("YBR_FULL");
    ds.Replace(photometric.GetAsDataElement());
  }));
  expectLoadError([&] { loadVolume(ybr); }, ybr,
                  "im0.dcm: PhotometricInterpretation 'YBR_FULL' with 3 samples a pixel");
  // A PlanarConfiguration other than 0 or 1 (GDCM's reader asserts on it, whatever the samples
  // a pixel; found by fuzzing): refused before GDCM decodes, for colour and grey alike.
  for (const bool colour : {true, false}) {
    testing::DicomSliceSpec planarSpec;
    planarSpec.rgb = colour;
    const std::string bad = dicomSeries(dir, colour ? "planar_rgb" : "planar_grey", 1, planarSpec);
    ASSERT_TRUE(testing::editDicom(bad + "/im0.dcm", [](gdcm::DataSet& ds) {
      gdcm::Attribute<0x0028, 0x0006> planar;
      planar.SetValue(388);
      ds.Replace(planar.GetAsDataElement());
    }));
    expectLoadError([&] { loadVolume(bad); }, bad, "im0.dcm: bad PlanarConfiguration 388 (0 or 1)");
  }
  // Eight bits allocated with fewer stored: GDCM's raw decoder asserts on it (found by fuzzing).
  const std::string seven = dicomSeries(dir, "seven", 1, spec);
  ASSERT_TRUE(testing::editDicom(seven + "/im0.dcm", [](gdcm::DataSet& ds) {
    gdcm::Attribute<0x0028, 0x0101> stored;
    stored.SetValue(7);
    ds.Replace(stored.GetAsDataElement());
    gdcm::Attribute<0x0028, 0x0102> high;
    high.SetValue(6);
    ds.Replace(high.GetAsDataElement());
  }));
  expectLoadError([&] { loadVolume(seven); }, seven,
                  "im0.dcm: BitsStored 7 with BitsAllocated 8 is not read (8 bits stored only)");
}

}  // namespace
}  // namespace ewa
