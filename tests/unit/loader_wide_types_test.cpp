// Loader tests for 32- and 64-bit voxel types (made float32) and NRRD's bzip2, ASCII and hex data.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "io/volume_loader.h"
#include "loader_test_files.h"
#include "medical_test_files.h"

namespace ewa {
namespace {

using testing::bytesOf;
using testing::bzip2Bytes;
using testing::expectVolumeLoadError;
using testing::TempDir;

// 24 values: offset + scale * i.
template <typename T>
std::vector<T> ramp(double scale, double offset) {
  std::vector<T> v(24);
  for (size_t i = 0; i < v.size(); ++i) v[i] = T(offset + scale * double(i));
  return v;
}

void expectFloatRamp(const Volume& v, double scale, double offset) {
  ASSERT_EQ(v.dims(), (std::array<int64_t, 3>{2, 3, 4}));
  EXPECT_EQ(v.type(), ScalarType::Float32);
  for (int64_t n = 0; n < v.voxelCount(); ++n)
    ASSERT_DOUBLE_EQ(v.valueAt(n), double(float(offset + scale * double(n)))) << "voxel " << n;
}

std::string nrrd(const std::string& type, const std::string& fields) {
  return "NRRD0005\ntype: " + type + "\ndimension: 3\nsizes: 2 3 4\n" + fields + "\n\n";
}

bool hasNote(const Volume& v, const std::string& note) {
  for (const std::string& n : v.notes())
    if (n == note) return true;
  return false;
}

TEST(WideTypes, NrrdIntegersAndDoublesInEitherByteOrderBecomeFloat32) {
  TempDir dir;
  const Volume i32 = loadVolume(dir.write("i.nrrd", nrrd("int", "encoding: raw\nendian: big") +
                                                        bytesOf(ramp<int32_t>(-70000, 9), true)));
  expectFloatRamp(i32, -70000, 9);
  EXPECT_TRUE(hasNote(i32, "int32 data converted to float32"));
  expectFloatRamp(
      loadVolume(dir.write("u.nrrd", nrrd("unsigned int", "encoding: raw\nendian: little") +
                                         bytesOf(ramp<uint32_t>(100000, 3)))),
      100000, 3);
  expectFloatRamp(loadVolume(dir.write("l.nrrd", nrrd("long long", "encoding: raw\nendian: big") +
                                                     bytesOf(ramp<int64_t>(-5, 2), true))),
                  -5, 2);
  expectFloatRamp(
      loadVolume(dir.write("ul.nrrd", nrrd("uint64", "encoding: gzip\nendian: little") +
                                          testing::gzipBytes(bytesOf(ramp<uint64_t>(7, 0))))),
      7, 0);
  const Volume d = loadVolume(dir.write("d.nrrd", nrrd("double", "encoding: raw\nendian: little") +
                                                      bytesOf(ramp<double>(0.125, -1.5))));
  expectFloatRamp(d, 0.125, -1.5);
  EXPECT_TRUE(hasNote(d, "float64 data converted to float32"));
}

TEST(WideTypes, WhatFloat32CannotHoldIsNoted) {
  TempDir dir;
  // 2^24 + 1 is the first integer float32 rounds; 1e300 is beyond its range.
  const Volume big =
      loadVolume(dir.write("big.nrrd", nrrd("int64", "encoding: raw\nendian: little") +
                                           bytesOf(ramp<int64_t>(0, 16777217))));
  EXPECT_DOUBLE_EQ(big.valueAt(0), 16777216.0);
  EXPECT_TRUE(hasNote(big, "int64 data converted to float32 (values beyond 16777216 are rounded)"));
  std::vector<double> values = ramp<double>(1, 0);
  values[5] = 1e300;
  const Volume huge = loadVolume(
      dir.write("huge.nrrd", nrrd("double", "encoding: raw\nendian: little") + bytesOf(values)));
  EXPECT_TRUE(std::isinf(huge.valueAt(5)));
  EXPECT_DOUBLE_EQ(huge.maxValue(), 23.0);  // the range skips what is not finite
  EXPECT_TRUE(hasNote(huge,
                      "float64 data converted to float32 (values beyond float32's range "
                      "became infinite)"));
}

TEST(WideTypes, MetaImageElementTypesOfMetaIoSizes) {
  TempDir dir;
  const std::string base = "NDims = 3\nDimSize = 2 3 4\nBinaryDataByteOrderMSB = True\n";
  auto load = [&](const std::string& name, const std::string& type, const std::string& data) {
    return loadVolume(
        dir.write(name, base + "ElementType = " + type + "\nElementDataFile = LOCAL\n" + data));
  };
  expectFloatRamp(load("i.mha", "MET_INT", bytesOf(ramp<int32_t>(-3, 1), true)), -3, 1);
  expectFloatRamp(load("l.mha", "MET_LONG", bytesOf(ramp<int32_t>(11, 4), true)), 11,
                  4);  // 4 bytes
  expectFloatRamp(load("ul.mha", "MET_ULONG_LONG", bytesOf(ramp<uint64_t>(2, 8), true)), 2, 8);
  expectFloatRamp(load("d.mha", "MET_DOUBLE", bytesOf(ramp<double>(-0.5, 0.25), true)), -0.5, 0.25);
}

TEST(WideTypes, NiftiInt64AndScaledInt32) {
  TempDir dir;
  testing::NiftiFields f;
  f.datatype = 1024;
  f.bitpix = 64;
  expectFloatRamp(
      loadVolume(dir.write("l.nii", testing::niftiHeader(f) + bytesOf(ramp<int64_t>(-9, 4)))), -9,
      4);
  f.datatype = 8;
  f.bitpix = 32;
  f.sclSlope = 0.5f;
  f.sclInter = -2.0f;
  const Volume s = loadVolume(
      dir.write("s.nii", testing::niftiHeader(f, true) + bytesOf(ramp<int32_t>(4, 0), true)));
  expectFloatRamp(s, 2, -2);
  EXPECT_TRUE(hasNote(s,
                      "int32 data scaled by scl_slope 0.500000 and scl_inter -2.000000, "
                      "converted to float32"));
}

TEST(NrrdEncodings, Bzip2WithByteSkipAndConcatenatedStreams) {
  TempDir dir;
  const std::string data = "SKIPPED!" + bytesOf(ramp<uint16_t>(1000, 5), true);
  const Volume v = loadVolume(
      dir.write("b.nrrd", nrrd("ushort", "encoding: bzip2\nendian: big\nbyte skip: 8") +
                              bzip2Bytes(data.substr(0, 20)) + bzip2Bytes(data.substr(20))));
  EXPECT_EQ(v.type(), ScalarType::UInt16);
  for (int64_t n = 0; n < 24; ++n) ASSERT_DOUBLE_EQ(v.valueAt(n), 5.0 + 1000.0 * double(n));
  // Detached, spelt bz2.
  dir.write("c.raw.bz2", bzip2Bytes(bytesOf(ramp<float>(0.5, -3))));
  expectFloatRamp(loadVolume(dir.write("c.nhdr", nrrd("float",
                                                      "encoding: bz2\nendian: little\n"
                                                      "data file: c.raw.bz2"))),
                  0.5, -3);
}

TEST(NrrdEncodings, Bzip2DataOfTheWrongLengthOrCorruptFails) {
  TempDir dir;
  const std::string data = bytesOf(ramp<uint8_t>(1, 0));
  expectVolumeLoadError(
      dir.write("short.nrrd", nrrd("uchar", "encoding: bzip2") + bzip2Bytes(data.substr(0, 20))),
      "decompresses to only 20 bytes, expected 24");
  expectVolumeLoadError(
      dir.write("long.nrrd", nrrd("uchar", "encoding: bzip2") + bzip2Bytes(data + "extra")),
      "more than the expected 24 bytes");
  const std::string packed = bzip2Bytes(data);
  expectVolumeLoadError(
      dir.write("cut.nrrd", nrrd("uchar", "encoding: bzip2") + packed.substr(0, packed.size() - 6)),
      "bzip2 data");
  expectVolumeLoadError(
      dir.write("junk.nrrd", nrrd("uchar", "encoding: bzip2") + "not bzip2 at all"), "corrupt");
}

TEST(NrrdEncodings, AsciiNumbersOfEveryType) {
  TempDir dir;
  // White space and commas between numbers, as teem and hand-written files have them.
  std::string text;
  for (int i = 0; i < 24; ++i) text += std::to_string(-300 + 7 * i) + (i % 5 == 4 ? ",\n" : "  ");
  const Volume s = loadVolume(dir.write("s.nrrd", nrrd("short", "encoding: ascii") + text));
  EXPECT_EQ(s.type(), ScalarType::Int16);
  for (int64_t n = 0; n < 24; ++n) ASSERT_DOUBLE_EQ(s.valueAt(n), -300.0 + 7.0 * double(n));
  std::string reals;
  for (int i = 0; i < 24; ++i) reals += std::to_string(0.25 * i - 1) + "\n";
  expectFloatRamp(
      loadVolume(dir.write("f.nrrd", nrrd("float", "encoding: text\nendian: big") + reals)), 0.25,
      -1);
  // Detached, with lines skipped: the byte skip counts characters.
  dir.write("d.txt", "# values\nXX" + reals);
  expectFloatRamp(loadVolume(dir.write("d.nhdr", nrrd("double",
                                                      "encoding: txt\nline skip: 1\n"
                                                      "byte skip: 2\ndata file: d.txt"))),
                  0.25, -1);
}

TEST(NrrdEncodings, AsciiWithTooFewNumbersOrAWordFails) {
  TempDir dir;
  expectVolumeLoadError(dir.write("few.nrrd", nrrd("uchar", "encoding: ascii") + "1 2 3"),
                        "cannot hold 24 values");
  expectVolumeLoadError(
      dir.write("word.nrrd", nrrd("uchar", "encoding: ascii") + "1 2 3 four 5 6 7 8 9 10 11 12 13 "
                                                                "14 15 16 17 18 19 20 21 22 23 24"),
      "ASCII data has 3 numbers, not 24");
}

TEST(NrrdEncodings, HexBytesInTheHeadersByteOrder) {
  TempDir dir;
  const std::string data = bytesOf(ramp<int16_t>(-1000, 300), true);
  std::string hex;
  const char* digits = "0123456789aBcDeF";
  for (size_t i = 0; i < data.size(); ++i) {
    const auto b = uint8_t(data[i]);
    hex += std::string(1, digits[b >> 4]) + digits[b & 15] +
           (i % 16 == 15 ? "\n"
            : i % 2      ? " "
                         : "");
  }
  const Volume v =
      loadVolume(dir.write("h.nrrd", nrrd("short", "encoding: hex\nendian: big") + hex));
  for (int64_t n = 0; n < 24; ++n) ASSERT_DOUBLE_EQ(v.valueAt(n), 300.0 - 1000.0 * double(n));
  expectVolumeLoadError(
      dir.write("odd.nrrd", nrrd("uchar", "encoding: hex") + std::string(47, '0')),
      "ends after 23 of 24 bytes");
  expectVolumeLoadError(
      dir.write("bad.nrrd", nrrd("uchar", "encoding: hex") + "0g" + std::string(46, '0')),
      "not a hex digit");
}

}  // namespace
}  // namespace ewa
