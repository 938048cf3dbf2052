// RGB DICOM series: each channel opens as a volume (--channel), by pixel, by plane and
// compressed; channels that are not there and colour spaces that are not RGB fail in one line.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
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

void setPhotometric(const std::string& file, const std::string& pi) {
  ASSERT_TRUE(testing::editDicom(file, [&](gdcm::DataSet& ds) {
    gdcm::Attribute<0x0028, 0x0004> photometric;
    photometric.SetValue(pi);
    ds.Replace(photometric.GetAsDataElement());
  }));
}

// Full-range Y, Cb, Cr of an 8-bit RGB sample (JPEG's and DICOM's YBR_FULL), rounded.
std::array<uint8_t, 3> ybrOf(double r, double g, double b) {
  const double y = 0.299 * r + 0.587 * g + 0.114 * b;
  const double cb = 128.0 - 0.168736 * r - 0.331264 * g + 0.5 * b;
  const double cr = 128.0 + 0.5 * r - 0.418688 * g - 0.081312 * b;
  return {uint8_t(std::lround(y)), uint8_t(std::lround(cb)), uint8_t(std::lround(cr))};
}

Volume loadChannel(const std::string& path, int channel) {
  LoadOptions options;
  options.channel = channel;
  return loadVolume(path, options);
}

// Every voxel of channel `c` holds the written sample of its column, row and slice (within
// `tolerance`: YBR samples are rounded, JPEG's lossy).
void expectChannel(const Volume& v, int c, double tolerance = 0.0) {
  ASSERT_EQ(v.dims(), (std::array<int64_t, 3>{5, 4, 3}));
  EXPECT_EQ(v.type(), ScalarType::UInt8);
  EXPECT_EQ(v.spacing(), glm::dvec3(0.75, 0.5, 2.0));
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 5; ++i)
        ASSERT_NEAR(v.value(i, j, k), double(rgbTestSample(c, i, j, 2 * k)), tolerance)
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
      EXPECT_EQ(v.channel(), c);  // the window pages through them
      EXPECT_EQ(v.channelCount(), 3);
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

TEST(DicomColour, YbrFullSamplesAreConvertedToRgb) {
  // An RGB series rewritten as the Y, Cb, Cr of its samples: each channel opens as the RGB one
  // (within one level: the samples were rounded on the way there and back), by pixel and by
  // plane, uncompressed and in RLE.
  TempDir dir;
  for (bool planar : {false, true}) {
    SCOPED_TRACE(planar ? "by plane" : "by pixel");
    testing::DicomSliceSpec spec;
    spec.rgb = true;
    spec.planar = planar;
    const std::string folder = dicomSeries(dir, planar ? "planes" : "pixels", 3, spec);
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
      ASSERT_TRUE(testing::editDicom(entry.path().string(), [&](gdcm::DataSet& ds) {
        const gdcm::ByteValue* bv = ds.GetDataElement(gdcm::Tag(0x7fe0, 0x0010)).GetByteValue();
        std::vector<uint8_t> px(bv->GetPointer(), bv->GetPointer() + bv->GetLength());
        const size_t n = px.size() / 3;
        auto at = [&](size_t p, int c) -> uint8_t& { return px[planar ? c * n + p : 3 * p + c]; };
        for (size_t p = 0; p < n; ++p) {
          const auto ybr = ybrOf(at(p, 0), at(p, 1), at(p, 2));
          for (int c = 0; c < 3; ++c) at(p, c) = ybr[size_t(c)];
        }
        gdcm::DataElement pixels(gdcm::Tag(0x7fe0, 0x0010));
        pixels.SetVR(gdcm::VR::OB);
        pixels.SetByteValue(reinterpret_cast<const char*>(px.data()), uint32_t(px.size()));
        ds.Replace(pixels);
        gdcm::Attribute<0x0028, 0x0004> photometric;
        photometric.SetValue("YBR_FULL");
        ds.Replace(photometric.GetAsDataElement());
      }));
    }
    // RLE returns the samples it was given too.
    ASSERT_TRUE(testing::recompressDicom(folder + "/im1.dcm", gdcm::TransferSyntax::RLELossless));
    for (int c = 0; c < 3; ++c) {
      const Volume v = loadChannel(folder, c);
      expectChannel(v, c, 1.0);
      EXPECT_NE(
          allNotes(v).find("RGB (from YBR_FULL): 3 channels; showing channel " + std::to_string(c)),
          std::string::npos)
          << allNotes(v);
    }
  }
}

TEST(DicomColour, JpegYbrFull422IsDecodedAndConvertedToRgb) {
  // GDCM's JPEG encoder stores an RGB image as YCbCr (and leaves the header saying RGB); said
  // YBR_FULL_422, as colour JPEG DICOM files say, it decodes to Y, Cb, Cr that become RGB again.
  TempDir dir;
  testing::DicomSliceSpec spec;
  spec.rgb = true;
  spec.rows = 16;
  spec.columns = 16;
  const std::string folder = dicomSeries(dir, "jpeg", 3, spec);
  for (int k = 0; k < 3; ++k) {
    const std::string file = folder + "/im" + std::to_string(k) + ".dcm";
    ASSERT_TRUE(testing::recompressDicom(file, gdcm::TransferSyntax::JPEGBaselineProcess1));
    setPhotometric(file, "YBR_FULL_422");
  }
  for (int c = 0; c < 3; ++c) {
    const Volume v = loadChannel(folder, c);
    ASSERT_EQ(v.dims(), (std::array<int64_t, 3>{16, 16, 3}));
    double worst = 0.0;
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 16; ++j)
        for (int i = 0; i < 16; ++i)
          worst = std::max(worst, std::abs(v.value(i, j, k) - rgbTestSample(c, i, j, 2 * k)));
    EXPECT_LE(worst, 4.0) << "channel " << c;  // lossy JPEG of a smooth ramp
  }
}

TEST(DicomColour, UncompressedYbrFull422IsUpsampledAndConvertedToRgb) {
  // Each two pixels of a row stored Y1 Y2 Cb Cr (PS3.5 8.2.1), as uncompressed ultrasound is:
  // the pair's chroma (here the first pixel's) shared, each channel back within one level of
  // the RGB written (the test slices' chroma is the same at every pixel).
  TempDir dir;
  testing::DicomSliceSpec spec;
  spec.rgb = true;
  spec.columns = 6;
  const std::string folder = dicomSeries(dir, "ybr422", 3, spec);
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    ASSERT_TRUE(testing::editDicom(entry.path().string(), [&](gdcm::DataSet& ds) {
      const gdcm::ByteValue* bv = ds.GetDataElement(gdcm::Tag(0x7fe0, 0x0010)).GetByteValue();
      const std::vector<uint8_t> rgb(bv->GetPointer(), bv->GetPointer() + bv->GetLength());
      std::vector<uint8_t> packed;
      for (size_t p = 0; p + 1 < rgb.size() / 3; p += 2) {
        const auto a = ybrOf(rgb[3 * p], rgb[3 * p + 1], rgb[3 * p + 2]);
        const auto b = ybrOf(rgb[3 * p + 3], rgb[3 * p + 4], rgb[3 * p + 5]);
        packed.insert(packed.end(), {a[0], b[0], a[1], a[2]});
      }
      gdcm::DataElement pixels(gdcm::Tag(0x7fe0, 0x0010));
      pixels.SetVR(gdcm::VR::OB);
      pixels.SetByteValue(reinterpret_cast<const char*>(packed.data()), uint32_t(packed.size()));
      ds.Replace(pixels);
    }));
    setPhotometric(entry.path().string(), "YBR_FULL_422");
  }
  for (int c = 0; c < 3; ++c) {
    const Volume v = loadChannel(folder, c);
    ASSERT_EQ(v.dims(), (std::array<int64_t, 3>{6, 4, 3}));
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 6; ++i)
          ASSERT_NEAR(v.value(i, j, k), double(rgbTestSample(c, i, j, 2 * k)), 1.0)
              << "channel " << c << " at " << i << "," << j << "," << k;
    EXPECT_NE(allNotes(v).find("RGB (from YBR_FULL_422)"), std::string::npos) << allNotes(v);
  }
  // Cut short: one line, not a read past the end.
  ASSERT_TRUE(testing::editDicom(folder + "/im1.dcm", [](gdcm::DataSet& ds) {
    gdcm::DataElement pixels(gdcm::Tag(0x7fe0, 0x0010));
    pixels.SetVR(gdcm::VR::OB);
    pixels.SetByteValue("\x10\x20\x80\x80", 4);
    ds.Replace(pixels);
  }));
  expectLoadError([&] { loadVolume(folder + "/im1.dcm"); }, folder + "/im1.dcm",
                  "pixel data cannot hold");
}

TEST(DicomColour, YbrColourSpacesOutsideTheirCodecsAreRefused) {
  // JPEG 2000's YBR_ICT and YBR_RCT outside JPEG 2000 (GDCM's raw decoder asserts on them),
  // YBR_FULL_422 in RLE or an odd number of columns: one line, no abort.
  TempDir dir;
  testing::DicomSliceSpec spec;
  spec.rgb = true;
  for (const std::string pi : {"YBR_ICT", "YBR_RCT"}) {
    const std::string folder = dicomSeries(dir, pi, 1, spec);
    setPhotometric(folder + "/im0.dcm", pi);
    expectLoadError([&] { loadVolume(folder); }, folder,
                    "im0.dcm: PhotometricInterpretation '" + pi +
                        "' uncompressed is not read (JPEG 2000 only)");
  }
  const std::string odd = dicomSeries(dir, "odd422", 1, spec);  // 5 columns
  setPhotometric(odd + "/im0.dcm", "YBR_FULL_422");
  expectLoadError([&] { loadVolume(odd); }, odd,
                  "im0.dcm: YBR_FULL_422 with 5 columns (its pixels come in pairs");
  const std::string rle = dicomSeries(dir, "rle422", 1, spec);
  ASSERT_TRUE(testing::recompressDicom(rle + "/im0.dcm", gdcm::TransferSyntax::RLELossless));
  setPhotometric(rle + "/im0.dcm", "YBR_FULL_422");
  expectLoadError([&] { loadVolume(rle); }, rle,
                  "im0.dcm: PhotometricInterpretation 'YBR_FULL_422' in transfer syntax "
                  "'1.2.840.10008.1.2.5' is not read (JPEG or uncompressed only)");
  // In JPEG 2000 the codec's inverse transform returns RGB: read as RGB, exactly (lossless).
  spec.rows = 16;  // OpenJPEG's encoder needs more than 4 rows for its resolution levels
  spec.columns = 16;
  const std::string j2k = dicomSeries(dir, "j2k", 3, spec);
  for (int k = 0; k < 3; ++k) {
    const std::string file = j2k + "/im" + std::to_string(k) + ".dcm";
    ASSERT_TRUE(testing::recompressDicom(file, gdcm::TransferSyntax::JPEG2000Lossless));
    setPhotometric(file, k == 1 ? "YBR_RCT" : "YBR_ICT");
  }
  for (int c = 0; c < 3; ++c) {
    const Volume v = loadChannel(j2k, c);
    ASSERT_EQ(v.dims(), (std::array<int64_t, 3>{16, 16, 3}));
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 16; ++j)
        for (int i = 0; i < 16; ++i)
          ASSERT_EQ(v.value(i, j, k), rgbTestSample(c, i, j, 2 * k)) << i << "," << j << "," << k;
  }
}

TEST(DicomColour, MissingChannelsAndOtherColourSpacesFailWithOneLine) {
  TempDir dir;
  testing::DicomSliceSpec spec;
  spec.rgb = true;
  const std::string rgb = dicomSeries(dir, "rgb", 2, spec);
  expectLoadError([&] { loadChannel(rgb, 3); }, rgb, "--channel 3 is out of range (3 channels)");
  const std::string grey = dicomSeries(dir, "grey", 2);
  expectLoadError([&] { loadChannel(grey, 1); }, grey, "--channel 1 is out of range (1 channel)");
  // Colour spaces that are neither RGB nor YBR: refused.
  const std::string other = dicomSeries(dir, "other", 1, spec);
  setPhotometric(other + "/im0.dcm", "HSV");
  expectLoadError([&] { loadVolume(other); }, other,
                  "im0.dcm: PhotometricInterpretation 'HSV' with 3 samples a pixel (MONOCHROME1 "
                  "or MONOCHROME2 with 1; RGB, YBR_FULL, YBR_FULL_422, YBR_RCT or YBR_ICT with 3)");
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
