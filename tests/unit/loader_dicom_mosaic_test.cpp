// Siemens mosaics: the slices of one image's tiles (CSA NumberOfImagesInMosaic), placed as
// dcm2niix places them.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "dicom_byte_files.h"
#include "io/dicom_csa.h"
#include "io/volume_loader.h"
#include "medical_test_files.h"

namespace ewa {
namespace {

using namespace testing;

// A CSA image header in syngo's SV10 format, elements of IS or FD values.
std::string csaHeader(const std::vector<std::pair<std::string, std::vector<std::string>>>& all) {
  std::string out = std::string("SV10") + "\4\3\2\1" + uintBytes(all.size(), 4) + uintBytes(77, 4);
  for (const auto& [name, values] : all) {
    std::string field = name;
    field.resize(64, '\0');
    out += field + uintBytes(values.size(), 4) + std::string("IS\0\0", 4) + uintBytes(6, 4) +
           uintBytes(values.size(), 4) + uintBytes(77, 4);
    for (const std::string& v : values) {
      const std::string text = v + '\0';
      out += uintBytes(text.size(), 4) + uintBytes(text.size(), 4) + uintBytes(77, 4) +
             uintBytes(text.size(), 4) + text + std::string((4 - text.size() % 4) % 4, '\0');
    }
  }
  return out;
}

// A mosaic of `count` 4 x 3 slices (slice k's pixels 1000 k + i + 10 j) in ceil(sqrt(count))
// tiles a row, 3 mm apart, with the given slice normal in its CSA header (and `countText`, when
// given, as its NumberOfImagesInMosaic).
ByteImageSpec mosaicSpec(int count, const std::string& normalZ, int instance = 1,
                         const std::string& countText = "") {
  int perRow = 1;
  while (perRow * perRow < count) ++perRow;
  ByteImageSpec spec;
  spec.columns = 4 * perRow;
  spec.rows = 3 * perRow;
  spec.pixels.assign(size_t(spec.columns * spec.rows), 0);
  for (int k = 0; k < count; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i)
        spec.pixels[size_t((k / perRow * 3 + j) * spec.columns + k % perRow * 4 + i)] =
            uint16_t(1000 * k + i + 10 * j);
  spec.modality = "MR";
  spec.sopInstance += "." + std::to_string(instance);
  spec.beforeSopClass =
      explicitElement(0x0008, 0x0008, "CS", evenText("ORIGINAL\\PRIMARY\\M\\MOSAIC"));
  spec.beforeSeries = explicitElement(0x0018, 0x0088, "DS", evenText("3"));
  spec.beforePosition = explicitElement(0x0020, 0x0013, "IS", evenText(std::to_string(instance)));
  spec.beforePixels =
      explicitElement(0x0029, 0x0010, "LO", evenText("SIEMENS CSA HEADER")) +
      explicitElement(0x0029, 0x1010, "OB",
                      csaHeader({{"EchoLinePosition", {"32"}},
                                 {"NumberOfImagesInMosaic",
                                  {countText.empty() ? std::to_string(count) : countText}},
                                 {"SliceNormalVector", {"0", "0", normalZ}}}));
  return spec;
}

TEST(DicomMosaic, TheCsaHeaderIsReadAsSv10) {
  const std::string csa = csaHeader({{"A", {"1"}}, {"NumberOfImagesInMosaic", {"36 "}}});
  const auto* bytes = reinterpret_cast<const uint8_t*>(csa.data());
  EXPECT_EQ(csaValues(bytes, csa.size(), "NumberOfImagesInMosaic"), std::vector<std::string>{"36"});
  EXPECT_TRUE(csaValues(bytes, csa.size(), "Missing").empty());
  // Cut anywhere, or counts past its bytes: nothing, never a read past the end.
  for (size_t n = 0; n < csa.size(); ++n)
    EXPECT_TRUE(csaValues(bytes, n, "NumberOfImagesInMosaic").empty()) << n;
  std::string lying = csa;
  lying.replace(8, 4, uintBytes(0xffffffffu, 4));
  EXPECT_TRUE(csaValues(reinterpret_cast<const uint8_t*>(lying.data()), lying.size(), "A").empty());
}

TEST(DicomMosaic, AMosaicOpensAsItsSlices) {
  TempDir dir;
  // 5 slices in 3 x 3 tiles of 4 x 3: the volume 4 x 3 x 5, 3 mm apart, its first voxel moved
  // from the image's corner to the first tile's (half the tiles' spare width and height).
  const Volume v = loadVolume(
      dir.write("mosaic.dcm", part10(imageDataSet(mosaicSpec(5, "1")), kExplicitLittle)));
  EXPECT_EQ(v.dims(), (std::array<int64_t, 3>{4, 3, 5}));
  EXPECT_EQ(v.spacing(), glm::dvec3(0.5, 0.5, 3.0));
  EXPECT_EQ(v.origin(), glm::dvec3(0.5 * 8 / 2, 0.5 * 6 / 2, 0.0));
  for (int k = 0; k < 5; ++k) EXPECT_EQ(v.value(3, 2, k), 1000 * k + 3 + 20) << k;
  EXPECT_TRUE(hasNoteWith(v, "Siemens mosaic: 5 slices of 4 x 3")) << allNotes(v);
  // In the implicit syntax, as syngo writes them.
  std::filesystem::create_directories(dir.path("implicit"));
  std::filesystem::copy_file(dir.path("mosaic.dcm"), dir.path("implicit/mosaic.dcm"));
  ASSERT_TRUE(recompressDicom(dir.path("implicit/mosaic.dcm"),
                              gdcm::TransferSyntax::ImplicitVRLittleEndian));
  const Volume implicit = loadVolume(dir.path("implicit/mosaic.dcm"));
  EXPECT_EQ(implicit.dims(), v.dims());
  EXPECT_EQ(implicit.origin(), v.origin());
  EXPECT_EQ(implicit.bytes(), v.bytes());
  // Slices stored against row x column (the CSA SliceNormalVector): put in order along it.
  const Volume down =
      loadVolume(dir.write("down.dcm", part10(imageDataSet(mosaicSpec(5, "-1")), kExplicitLittle)));
  EXPECT_EQ(down.origin(), glm::dvec3(2.0, 1.5, -12.0));
  EXPECT_EQ(down.direction()[2], glm::dvec3(0, 0, 1));
  for (int z = 0; z < 5; ++z) EXPECT_EQ(down.value(0, 0, z), 1000 * (4 - z)) << z;
}

TEST(DicomMosaic, ASeriesOfMosaicsIsOneVolumeAFile) {
  TempDir dir;
  std::filesystem::create_directories(dir.path("fmri"));
  for (const int instance : {2, 1}) {
    ByteImageSpec spec = mosaicSpec(4, "1", instance);
    for (uint16_t& p : spec.pixels) p = uint16_t(p + 100 * instance);
    dir.write("fmri/t" + std::to_string(instance) + ".dcm",
              part10(imageDataSet(spec), kExplicitLittle));
  }
  const Volume first = loadVolume(dir.path("fmri"));
  EXPECT_EQ(first.dims(), (std::array<int64_t, 3>{4, 3, 4}));
  EXPECT_EQ(first.frameCount(), 2);
  EXPECT_EQ(first.value(0, 0, 1), 1000 + 100);
  const Volume second = loadVolume(dir.path("fmri"), {"", 1, 0, {}});
  EXPECT_EQ(second.value(0, 0, 1), 1000 + 200);
  expectLoadError(
      [&] {
        loadVolume(dir.path("fmri"), {"", 2, 0, {}});
      },
      dir.path("fmri"), "--frame 2 is out of range");
}

TEST(DicomMosaic, TilesThatDoNotFitAreRefusedInOneLine) {
  TempDir dir;
  ByteImageSpec spec = mosaicSpec(5, "1");
  spec.columns = 13;  // not 3 tiles across
  spec.pixels.assign(size_t(spec.columns * spec.rows), 0);
  expectVolumeLoadError(dir.write("odd.dcm", part10(imageDataSet(spec), kExplicitLittle)),
                        "a Siemens mosaic of 5 images (3 x 3 tiles) that its 13 x 9 pixels do "
                        "not hold");
  // A count no image holds (never squared: it would overflow).
  expectVolumeLoadError(
      dir.write("huge.dcm", part10(imageDataSet(mosaicSpec(4, "1", 1, "9223372036854775807")),
                                   kExplicitLittle)),
      "a Siemens mosaic of 9223372036854775807 images that its 8 x 6 pixels do not hold");
}

}  // namespace
}  // namespace ewa
