// Hostile DICOM files the pre-check (dicom_guard) must stop before GDCM crashes, allocates or
// aborts on them: nesting bombs, deflated data sets that lie or explode; and legal padding it
// must let through.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "dicom_byte_files.h"
#include "io/dicom_guard.h"
#include "io/dicom_inflate.h"
#include "io/volume_loader.h"
#include "medical_test_files.h"

namespace ewa {
namespace {

using namespace testing;

// An image data set with `depth` nested sequences before its pixels (Content Sequence is group
// 0040: between 0028 and 7FE0, in tag order).
std::string nestedImage(int depth, const ByteImageSpec& base = {}) {
  ByteImageSpec spec = base;
  spec.beforePixels = nestedSequences(depth);
  return imageDataSet(spec);
}

TEST(DicomHostile, DeepNestingIsRefusedBeforeGdcmRecursesIntoIt) {
  TempDir dir;
  // 20 and 128 levels are read; 129 and a bomb of 5,000 (a 180 KB file that overflowed GDCM's
  // stack) are refused in one line.
  for (const int depth : {20, 128})
    EXPECT_EQ(checkDicomStructure(dir.write("ok" + std::to_string(depth) + ".dcm",
                                            part10(nestedImage(depth), kExplicitLittle))),
              DicomStructure::Plausible)
        << depth;
  EXPECT_EQ(loadVolume(dir.path("ok128.dcm")).dims(), (std::array<int64_t, 3>{4, 3, 1}));
  for (const int depth : {129, 5000, 200000}) {
    const std::string file = dir.write("deep" + std::to_string(depth) + ".dcm",
                                       part10(nestedImage(depth), kExplicitLittle));
    expectVolumeLoadError(file, "sequences nested more than 128 deep");
  }
  // In the implicit syntax too, with undefined lengths. Defined lengths nest in GDCM only
  // when asked for (it keeps their bytes), so a bomb of them passes and GDCM reads the file.
  const std::string sopClass =
      implicitElement(0x0008, 0x0016, evenText("1.2.840.10008.5.1.4.1.1.7", '\0'));
  std::string undefinedBomb, definedBomb;
  for (int d = 0; d < 5000; ++d) {
    undefinedBomb = uintBytes(0x0040, 2) + uintBytes(0xa730, 2) + uintBytes(0xffffffffu, 4) +
                    itemStart() + undefinedBomb + itemEnd() + sequenceEnd();
    definedBomb =
        itemStart(uint32_t(definedBomb.size() + 8)) + implicitElement(0x0040, 0xa730, definedBomb);
  }
  expectVolumeLoadError(
      dir.write("implicit.dcm", part10(sopClass + undefinedBomb, kImplicitLittle)),
      "sequences nested more than 128 deep");
  const std::string defined =
      dir.write("defined.dcm",
                part10(sopClass + implicitElement(0x0040, 0xa730, definedBomb), kImplicitLittle));
  EXPECT_EQ(checkDicomStructure(defined), DicomStructure::Plausible);
  expectVolumeLoadError(defined, "not a DICOM image");  // read, and no image in it
}

TEST(DicomHostile, AFolderWithABombLoadsItsGoodFilesAndNamesTheBomb) {
  TempDir dir;
  const std::string series = dicomSeries(dir, "s", 4);
  dir.write("s/bomb.dcm", part10(nestedImage(20000), kExplicitLittle));
  dir.write("s/deflated.dcm", part10(rawDeflate(undefinedLength(0x0008, 0x0016, "OB")), kDeflated));
  const Volume v = loadVolume(series);
  EXPECT_EQ(v.dims(), (std::array<int64_t, 3>{5, 4, 4}));
  EXPECT_TRUE(hasNoteWith(v, "warning: skipped " + series +
                                 "/bomb.dcm: corrupt or truncated "
                                 "DICOM data: sequences nested more than 128 deep"))
      << allNotes(v);
  EXPECT_TRUE(hasNoteWith(v, "warning: skipped " + series + "/deflated.dcm: ")) << allNotes(v);
}

TEST(DicomHostile, DeflatedDataSetsAreWalkedAsOthersAre) {
  TempDir dir;
  // A good deflated image loads as the same data set uncompressed does.
  const std::string plain = dir.write("plain.dcm", part10(imageDataSet({}), kExplicitLittle));
  const std::string deflated =
      dir.write("deflated.dcm", part10(rawDeflate(imageDataSet({})), kDeflated));
  EXPECT_EQ(loadVolume(deflated).bytes(), loadVolume(plain).bytes());
  // What GDCM asserted (SIGABRT) or allocated gigabytes on once inflated: refused in one line.
  ByteImageSpec columnsSs;
  std::string data = imageDataSet(columnsSs);
  const std::string columns = explicitElement(0x0028, 0x0011, "US", uintBytes(4, 2));
  data.replace(data.find(columns), columns.size(),
               explicitElement(0x0028, 0x0011, "SS", uintBytes(4, 2)));
  ByteImageSpec openItem;
  openItem.beforePixels = undefinedLength(0x0040, 0xa730, "SQ") + itemStart() +
                          explicitElement(0x0040, 0xa160, "UT", "never ends");
  ByteImageSpec openOb;
  openOb.beforePixels = undefinedLength(0x0040, 0xa170, "OB") + std::string(16, 'x');
  ByteImageSpec liar;  // 4.4 GB claimed by 30 bytes
  liar.beforePixels = uintBytes(0x0040, 2) + uintBytes(0xa170, 2) + "OB" + std::string(2, '\0') +
                      uintBytes(0xfffffff0u, 4) + std::string(30, 'x');
  const std::pair<std::string, std::string> cases[] = {
      {data, "element (0028,0011) of VR SS"},
      {imageDataSet(openItem), "a sequence or item is not closed"},
      {imageDataSet(openOb), "an undefined length for VR OB"},
      {imageDataSet(liar), "element (0040,A170) claims 4294967280 bytes but only"},
  };
  int n = 0;
  for (const auto& [dataSet, problem] : cases) {
    const std::string file =
        dir.write("bad" + std::to_string(n++) + ".dcm", part10(rawDeflate(dataSet), kDeflated));
    expectVolumeLoadError(file, "corrupt or truncated DICOM data (deflated; inflated): " + problem);
  }
  // A stream cut short or corrupt.
  const std::string stream = rawDeflate(imageDataSet({}));
  expectVolumeLoadError(
      dir.write("cut.dcm", part10(stream.substr(0, stream.size() / 2), kDeflated)),
      "the deflated DICOM data set is cut short");
  expectVolumeLoadError(dir.write("corrupt.dcm", part10(std::string(40, '\xff'), kDeflated)),
                        "the deflated DICOM data set is corrupt");
}

TEST(DicomHostile, DeflateBombsAreRefusedAtTheirBound) {
  TempDir dir;
  // 96 MiB of zeros in an OB deflate to about 100 KB: past the 64 MiB floor and 256:1.
  ByteImageSpec spec;
  const size_t zeros = size_t(96) << 20;
  spec.beforePixels = explicitElement(0x0040, 0xa170, "OB", std::string(zeros, '\0'));
  const std::string stream = rawDeflate(imageDataSet(spec));
  ASSERT_LT(stream.size() * kDicomInflateRatio, kDicomInflateFloor);
  expectVolumeLoadError(dir.write("bomb.dcm", part10(stream, kDeflated)),
                        "the deflated DICOM data set inflates to more than 67108864 bytes");
  EXPECT_EQ(dicomInflateLimit(1000), kDicomInflateFloor);
  EXPECT_EQ(dicomInflateLimit(uint64_t(1) << 20), uint64_t(256) << 20);
  EXPECT_EQ(dicomInflateLimit(uint64_t(1) << 40), kDicomInflateCap);
}

TEST(DicomHostile, ZeroPaddingAfterTheLastElementIsTheEnd) {
  TempDir dir;
  // 20 slices, one with 2.4 MB of zeros after its pixel data: GDCM reads it, so must we.
  const std::string series = dicomSeries(dir, "s", 20);
  const Volume before = loadVolume(series);
  const std::string padded = series + "/im7.dcm";
  dir.write("s/im7.dcm", fileBytes(padded) + std::string(2400000, '\0'));
  const Volume after = loadVolume(series);
  EXPECT_EQ(after.dims(), (std::array<int64_t, 3>{5, 4, 20}));
  EXPECT_EQ(after.bytes(), before.bytes());
  EXPECT_EQ(after.notes(), before.notes());
  // Any count of zeros GDCM reads (fewer than 4; in a little-endian file, 8-byte empty
  // elements and fewer than 4 over), in each syntax; other counts, on which GDCM fails or
  // asserts, and a non-zero byte after zeros are refused in one line.
  const std::string image = imageDataSet({});
  const Volume reference = loadVolume(dir.write("plain.dcm", part10(image, kExplicitLittle)));
  for (const size_t count : {1, 3, 8, 11, 4096, 4099}) {
    const std::string file = dir.write("pad" + std::to_string(count) + ".dcm",
                                       part10(image + std::string(count, '\0'), kExplicitLittle));
    EXPECT_EQ(checkDicomStructure(file), DicomStructure::Plausible) << file;
    EXPECT_EQ(loadVolume(file).bytes(), reference.bytes()) << file;
  }
  for (const size_t count : {1, 2, 3}) {
    const std::string file =
        dir.write("padd" + std::to_string(count) + ".dcm",
                  part10(rawDeflate(image + std::string(count, '\0')), kDeflated));
    EXPECT_EQ(loadVolume(file).bytes(), reference.bytes()) << file;
  }
  for (const size_t count : {4, 7, 12, 100}) {
    const std::string zeros(count, '\0');
    expectVolumeLoadError(
        dir.write("bad" + std::to_string(count) + ".dcm", part10(image + zeros, kExplicitLittle)),
        std::to_string(count) + " zero bytes after the last element");
    expectVolumeLoadError(dir.write("badd" + std::to_string(count) + ".dcm",
                                    part10(rawDeflate(image + zeros), kDeflated)),
                          std::to_string(count) + " zero bytes after the last element");
  }
  // GDCM's own implicit file, padded.
  const std::string implicit = dicomSeries(dir, "i", 1) + "/im0.dcm";
  ASSERT_TRUE(recompressDicom(implicit, gdcm::TransferSyntax::ImplicitVRLittleEndian));
  const std::vector<uint8_t> unpadded = loadVolume(implicit).bytes();
  const std::string implicitBytes = fileBytes(implicit);
  dir.write("i/im0.dcm", implicitBytes + std::string(8 * 1000 + 3, '\0'));
  EXPECT_EQ(loadVolume(implicit).bytes(), unpadded);
  dir.write("i/im0.dcm", implicitBytes + std::string(5, '\0'));
  expectVolumeLoadError(implicit, "5 zero bytes after the last element");
  expectVolumeLoadError(
      dir.write("junk.dcm", part10(image + std::string(64, '\0') + "x", kExplicitLittle)),
      "corrupt or truncated DICOM data");
}

}  // namespace
}  // namespace ewa
