// Loader tests on small hand-made files covering each format variant, byte order and codec.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "io/volume_loader.h"
#include "loader_test_files.h"

namespace ewa {
namespace {

using testing::bytesOf;
using testing::gzipBytes;
using testing::TempDir;
using testing::uintBytes;
using testing::zlibBytes;

// 2 x 3 x 4 values 0..23 scaled and offset, x fastest.
template <typename T>
std::vector<T> ramp(double scale = 1.0, double offset = 0.0, size_t n = 24) {
  std::vector<T> v(n);
  for (size_t i = 0; i < n; ++i) v[i] = static_cast<T>(offset + scale * static_cast<double>(i));
  return v;
}

void expectRamp(const Volume& v, std::array<int64_t, 3> dims, double scale, double offset) {
  ASSERT_EQ(v.dims(), dims);
  for (int64_t n = 0; n < v.voxelCount(); ++n) {
    ASSERT_DOUBLE_EQ(v.valueAt(n), static_cast<double>(static_cast<float>(offset + scale * n)))
        << "voxel " << n;
  }
}

std::string nrrdHead(const std::string& type, const std::string& extra) {
  return "NRRD0004\n# test\ntype: " + type + "\ndimension: 3\nsizes: 2 3 4\n" + extra;
}

// ---- NRRD ----

TEST(NrrdLoader, AttachedRawLittleEndianWithSpacingAndOrigin) {
  TempDir dir;
  const std::string path =
      dir.write("a.nrrd", nrrdHead("unsigned short int",
                                   "endian: little\nencoding: raw\nspacings: 0.5 2 3\n"
                                   "space origin: (1,-2,3.5)\nkinds: domain domain domain\n"
                                   "key:=value\n\n") +
                              bytesOf(ramp<uint16_t>(1000.0, 7.0)));
  const Volume v = loadVolume(path);
  EXPECT_EQ(v.type(), ScalarType::UInt16);
  expectRamp(v, {2, 3, 4}, 1000.0, 7.0);
  EXPECT_EQ(v.spacing(), glm::dvec3(0.5, 2.0, 3.0));
  EXPECT_EQ(v.origin(), glm::dvec3(1.0, -2.0, 3.5));
  EXPECT_DOUBLE_EQ(v.minValue(), 7.0);
  EXPECT_DOUBLE_EQ(v.maxValue(), 23007.0);
}

TEST(NrrdLoader, SpaceUnitsAndAxisUnitsNameTheUnit) {
  TempDir dir;
  auto unitOf = [&](const std::string& name, const std::string& fields) {
    return loadVolume(dir.write(name, nrrdHead("uchar", "encoding: raw\n" + fields + "\n") +
                                          std::string(24, '\0')))
        .unit();
  };
  EXPECT_EQ(unitOf("a.nrrd", "space: LPS\nspace units: \"mm\" \"mm\" \"mm\"\n"), "mm");
  EXPECT_EQ(unitOf("b.nrrd", "spacings: 1 1 1\nunits: \"micron\" \"micron\" \"micron\"\n"),
            "\xC2\xB5m");
  EXPECT_EQ(unitOf("c.nrrd", "space units: \"mm\" \"cm\" \"mm\"\n"), "");  // mixed: none
  EXPECT_EQ(unitOf("d.nrrd", "space units: \"\\x01\" \"\\x01\" \"\\x01\"\n"), "");
  EXPECT_EQ(unitOf("e.nrrd", "space units: \"mm\n"), "");  // unclosed
  EXPECT_EQ(unitOf("f.nrrd", ""), "");
  // Å in either code point, or spelled out, is one unit (MRC's and OME's).
  EXPECT_EQ(unitOf("g.nrrd", "units: \"\xE2\x84\xAB\" \"Angstrom\" \"\xC3\x85\"\n"), "\xC3\x85");
}

// Orthogonal axes of lengths 2, 5 and 0.5 (a sheared grid would be resampled: shear_resample).
TEST(NrrdLoader, AttachedBigEndianSignedShortWithSpaceDirections) {
  TempDir dir;
  const std::string path =
      dir.write("b.nrrd", nrrdHead("signed short",
                                   "endian: big\nencoding: raw\n"
                                   "space directions: (0,2,0) (3,0,4) (0.4,0,-0.3)\n\n") +
                              bytesOf(ramp<int16_t>(-300.0, 100.0), true));
  const Volume v = loadVolume(path);
  EXPECT_EQ(v.type(), ScalarType::Int16);
  expectRamp(v, {2, 3, 4}, -300.0, 100.0);
  EXPECT_DOUBLE_EQ(v.spacing().x, 2.0);
  EXPECT_DOUBLE_EQ(v.spacing().y, 5.0);
  EXPECT_DOUBLE_EQ(v.spacing().z, 0.5);
}

TEST(NrrdLoader, GzipFloatWithByteSkipAfterInflation) {
  TempDir dir;
  const std::string data = "SKIP" + bytesOf(ramp<float>(0.25, -1.0));
  const std::string path =
      dir.write("c.nrrd", nrrdHead("float", "endian: little\nencoding: gzip\nbyte skip: 4\n\n") +
                              gzipBytes(data));
  const Volume v = loadVolume(path);
  EXPECT_EQ(v.type(), ScalarType::Float32);
  expectRamp(v, {2, 3, 4}, 0.25, -1.0);
}

TEST(NrrdLoader, GzipBigEndianAndGzSpellingAndConcatenatedMembers) {
  TempDir dir;
  const std::string data = bytesOf(ramp<uint16_t>(3.0), true);
  const std::string path =
      dir.write("d.nrrd", nrrdHead("uint16", "endian: big\nencoding: gz\n\n") +
                              gzipBytes(data.substr(0, 10)) + gzipBytes(data.substr(10)));
  expectRamp(loadVolume(path), {2, 3, 4}, 3.0, 0.0);
}

TEST(NrrdLoader, DetachedHeaderWithLineAndByteSkip) {
  TempDir dir;
  dir.write("d.raw", "line one\nline two\nXY" + bytesOf(ramp<uint8_t>(2.0)) + "trailing");
  const std::string path = dir.write(
      "d.nhdr", nrrdHead("uchar", "encoding: raw\nline skip: 2\nbyte skip: 2\ndata file: d.raw\n"));
  expectRamp(loadVolume(path), {2, 3, 4}, 2.0, 0.0);
}

TEST(NrrdLoader, DetachedGzipDataFile) {
  TempDir dir;
  dir.write("e.raw.gz", gzipBytes(bytesOf(ramp<int16_t>(-5.0), false)));
  const std::string path = dir.write(
      "e.nhdr", nrrdHead("short", "endian: little\nencoding: gzip\ndata file: ./e.raw.gz\n"));
  expectRamp(loadVolume(path), {2, 3, 4}, -5.0, 0.0);
}

TEST(NrrdLoader, ByteSkipMinusOneReadsTheFileEnd) {
  TempDir dir;
  dir.write("f.raw", std::string(17, 'h') + bytesOf(ramp<uint8_t>()));
  const std::string path =
      dir.write("f.nhdr", nrrdHead("uint8_t", "encoding: raw\nbyte skip: -1\ndata file: f.raw\n"));
  expectRamp(loadVolume(path), {2, 3, 4}, 1.0, 0.0);
}

TEST(NrrdLoader, DataFileListOfSlices) {
  TempDir dir;
  const std::string all = bytesOf(ramp<uint16_t>(11.0));
  std::string list;
  for (int k = 0; k < 4; ++k) {
    const std::string name = "slice_" + std::string(1, static_cast<char>('a' + k)) + ".raw";
    dir.write(name, all.substr(static_cast<size_t>(k) * 12, 12));
    list += name + "\n";
  }
  const std::string path = dir.write(
      "g.nhdr", nrrdHead("ushort", "endian: little\nencoding: raw\ndata file: LIST 2\n") + list);
  expectRamp(loadVolume(path), {2, 3, 4}, 11.0, 0.0);
}

TEST(NrrdLoader, DataFilePatternCountingDown) {
  TempDir dir;
  const std::string all = bytesOf(ramp<uint8_t>(3.0));
  // Files s09.raw (first slice) down to s03.raw (last), step -2.
  for (int k = 0; k < 4; ++k) {
    char name[16];
    std::snprintf(name, sizeof name, "s%02d.raw", 9 - 2 * k);
    dir.write(name, all.substr(static_cast<size_t>(k) * 6, 6));
  }
  const std::string path =
      dir.write("h.nhdr", nrrdHead("uchar", "encoding: raw\ndata file: s%02d.raw 9 3 -2 2\n"));
  expectRamp(loadVolume(path), {2, 3, 4}, 3.0, 0.0);
}

TEST(NrrdLoader, OldStyleDatafileFieldAndTwoDimensions) {
  TempDir dir;
  dir.write("i.raw", bytesOf(ramp<uint8_t>(1.0, 0.0, 6)));
  const std::string path =
      dir.write("i.nrrd",
                "NRRD0001\ncontent: x\ndimension: 2\ntype: uchar\nsizes: 2 3\nspacings: 2 nan\n"
                "datafile: ./i.raw\nencoding: raw\n");
  const Volume v = loadVolume(path);
  EXPECT_EQ(v.dims(), (std::array<int64_t, 3>{2, 3, 1}));
  EXPECT_EQ(v.spacing(), glm::dvec3(2.0, 1.0, 1.0));
  EXPECT_DOUBLE_EQ(v.value(1, 2, 0), 5.0);
}

TEST(NrrdLoader, SignedCharIsWidenedToInt16) {
  TempDir dir;
  const std::string path = dir.write(
      "j.nrrd", nrrdHead("signed char", "encoding: raw\n\n") + bytesOf(ramp<int8_t>(-5.0, 60.0)));
  const Volume v = loadVolume(path);
  EXPECT_EQ(v.type(), ScalarType::Int16);
  expectRamp(v, {2, 3, 4}, -5.0, 60.0);
}

TEST(NrrdLoader, CrLfHeader) {
  TempDir dir;
  const std::string path = dir.write(
      "k.nrrd", "NRRD0005\r\ntype: uchar\r\ndimension: 3\r\nsizes: 2 3 4\r\nencoding: raw\r\n\r\n" +
                    bytesOf(ramp<uint8_t>()));
  expectRamp(loadVolume(path), {2, 3, 4}, 1.0, 0.0);
}

// ---- MetaImage ----

TEST(MetaImageLoader, DetachedBigEndianWithHeaderSize) {
  TempDir dir;
  dir.write("m.raw", "HDR" + bytesOf(ramp<uint16_t>(500.0, 1.0), true));
  const std::string path =
      dir.write("m.mhd",
                "ObjectType = Image\nNDims = 3\nDimSize = 2 3 4\nElementSpacing = 0.5 0.25 4\n"
                "Offset = 10 20 30\nElementType = MET_USHORT\nBinaryData = True\n"
                "BinaryDataByteOrderMSB = True\nHeaderSize = 3\nElementDataFile = m.raw\n");
  const Volume v = loadVolume(path);
  EXPECT_EQ(v.type(), ScalarType::UInt16);
  expectRamp(v, {2, 3, 4}, 500.0, 1.0);
  EXPECT_EQ(v.spacing(), glm::dvec3(0.5, 0.25, 4.0));
  EXPECT_EQ(v.origin(), glm::dvec3(10.0, 20.0, 30.0));
}

TEST(MetaImageLoader, LocalZlibWithCompressedDataSize) {
  TempDir dir;
  const std::string packed = zlibBytes(bytesOf(ramp<float>(-0.5, 2.0)));
  const std::string path = dir.write(
      "n.mha",
      "ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = False\n"
      "CompressedData = True\nCompressedDataSize = " +
          std::to_string(packed.size()) +
          "\nDimSize = 2 3 4\nElementType = MET_FLOAT\nElementDataFile = LOCAL\n" + packed);
  const Volume v = loadVolume(path);
  EXPECT_EQ(v.type(), ScalarType::Float32);
  expectRamp(v, {2, 3, 4}, -0.5, 2.0);
}

TEST(MetaImageLoader, LocalRawTwoDimensionsAndElementSize) {
  TempDir dir;
  const std::string path =
      dir.write("o.mha",
                "NDims = 2\nDimSize = 3 2\nElementSize = 2 3\nElementType = MET_SHORT\n"
                "ElementByteOrderMSB = True\nElementDataFile = LOCAL\n" +
                    bytesOf(std::vector<int16_t>{-1, 2, -3, 4, -5, 6}, true));
  const Volume v = loadVolume(path);
  EXPECT_EQ(v.dims(), (std::array<int64_t, 3>{3, 2, 1}));
  EXPECT_EQ(v.spacing(), glm::dvec3(2.0, 3.0, 1.0));
  EXPECT_DOUBLE_EQ(v.value(2, 1, 0), 6.0);
  EXPECT_DOUBLE_EQ(v.minValue(), -5.0);
}

// ---- .dat ----

TEST(DatLoader, VoreenStyleUShort) {
  TempDir dir;
  dir.write("p.raw", bytesOf(ramp<uint16_t>(9.0)));
  const std::string path =
      dir.write("p.dat",
                "# comment\r\nObjectFileName:\tp.raw\r\nResolution:  2 3 4\r\n"
                "SliceThickness: 1.5 1 0.5\r\nFormat:\t\tUSHORT\r\nObjectModel: I");
  const Volume v = loadVolume(path);
  expectRamp(v, {2, 3, 4}, 9.0, 0.0);
  EXPECT_EQ(v.spacing(), glm::dvec3(1.5, 1.0, 0.5));
}

TEST(DatLoader, InviwoStyleBigEndianUInt16) {
  TempDir dir;
  dir.write("q.raw", bytesOf(ramp<uint16_t>(300.0), true));
  const std::string path =
      dir.write("q.dat",
                "RawFile: q.raw\nDimensions: 2 3 4\nSpacing: 2 2 2\nFormat: UINT16\n"
                "ByteOrder: BigEndian\n");
  const Volume v = loadVolume(path);
  expectRamp(v, {2, 3, 4}, 300.0, 0.0);
  EXPECT_EQ(v.spacing(), glm::dvec3(2.0));
}

// ---- VTI ----

std::string vtiFile(const std::string& fileAttrs, const std::string& extent,
                    const std::string& type, const std::string& arrayAttrs,
                    const std::string& inlineText, const std::string& appended) {
  std::string xml =
      "<?xml version=\"1.0\"?>\n<!-- made by a test -->\n<VTKFile type=\"ImageData\" "
      "version=\"1.0\" " +
      fileAttrs + ">\n  <ImageData WholeExtent=\"" + extent +
      "\" Origin=\"1 2 3\" Spacing=\"0.5 1 2\">\n    <Piece Extent=\"" + extent +
      "\">\n      <PointData Scalars=\"values\">\n"
      "        <DataArray type=\"Float32\" Name=\"other\" format=\"ascii\">1 2</DataArray>\n"
      "        <DataArray type=\"" +
      type + "\" Name=\"values\" " + arrayAttrs + ">" + inlineText +
      "</DataArray>\n      </PointData>\n      <CellData>\n      </CellData>\n"
      "    </Piece>\n  </ImageData>\n";
  if (!appended.empty())
    xml += "  <AppendedData encoding=\"raw\">\n   _" + appended + "\n  </AppendedData>\n";
  return xml + "</VTKFile>\n";
}

// The block layout vtkZLibDataCompressor writes, header integers of `width` bytes.
std::string zlibBlocks(const std::string& data, size_t blockSize, int width, bool bigEndian) {
  std::vector<std::string> blocks;
  for (size_t at = 0; at < data.size(); at += blockSize)
    blocks.push_back(zlibBytes(data.substr(at, blockSize)));
  const size_t last = data.size() % blockSize;
  std::string out = uintBytes(blocks.size(), width, bigEndian) +
                    uintBytes(blockSize, width, bigEndian) + uintBytes(last, width, bigEndian);
  for (const std::string& b : blocks) out += uintBytes(b.size(), width, bigEndian);
  for (const std::string& b : blocks) out += b;
  return out;
}

TEST(VtiLoader, AppendedRawUInt32HeaderAndExtentOffset) {
  TempDir dir;
  const std::string data = bytesOf(ramp<int16_t>(-100.0, 50.0));
  const std::string path =
      dir.write("r.vti", vtiFile("byte_order=\"LittleEndian\" header_type=\"UInt32\"",
                                 "1 2 0 2 -2 1", "Int16", "format=\"appended\" offset=\"0\"", "",
                                 uintBytes(data.size(), 4) + data));
  const Volume v = loadVolume(path);
  EXPECT_EQ(v.type(), ScalarType::Int16);
  expectRamp(v, {2, 3, 4}, -100.0, 50.0);
  EXPECT_EQ(v.spacing(), glm::dvec3(0.5, 1.0, 2.0));
  // Origin + extent start * spacing.
  EXPECT_EQ(v.origin(), glm::dvec3(1.5, 2.0, -1.0));
}

TEST(VtiLoader, AppendedZlibBlocksUInt64HeaderWithSecondArrayOffset) {
  TempDir dir;
  const std::string data = bytesOf(ramp<float>(1.5, -3.0));  // 96 bytes: blocks 40, 40, 16
  const std::string filler = zlibBlocks(std::string(8, 'z'), 8, 8, false);
  const std::string path = dir.write(
      "s.vti",
      vtiFile(
          "byte_order=\"LittleEndian\" header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\"",
          "0 1 0 2 0 3", "Float32",
          "format=\"appended\" offset=\"" + std::to_string(filler.size()) + "\"", "",
          filler + zlibBlocks(data, 40, 8, false)));
  const Volume v = loadVolume(path);
  EXPECT_EQ(v.type(), ScalarType::Float32);
  expectRamp(v, {2, 3, 4}, 1.5, -3.0);
}

TEST(VtiLoader, BigEndianZlibUInt16FullLastBlock) {
  TempDir dir;
  const std::string data = bytesOf(ramp<uint16_t>(1000.0), true);  // 48 bytes: blocks 24, 24
  const std::string path =
      dir.write("t.vti", vtiFile("byte_order=\"BigEndian\" compressor=\"vtkZLibDataCompressor\"",
                                 "0 1 0 2 0 3", "UInt16", "format=\"appended\" offset=\"0\"", "",
                                 zlibBlocks(data, 24, 4, true)));
  expectRamp(loadVolume(path), {2, 3, 4}, 1000.0, 0.0);
}

std::string base64(const std::string& bytes) {
  static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t v = static_cast<uint8_t>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) v |= static_cast<uint8_t>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) v |= static_cast<uint8_t>(bytes[i + 2]);
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kAlphabet[v & 63] : '=';
  }
  return out;
}

TEST(VtiLoader, InlineBinaryHeaderAndDataEncodedApart) {
  TempDir dir;
  const std::string data = bytesOf(ramp<uint8_t>(10.0));
  const std::string path = dir.write(
      "u.vti",
      vtiFile("byte_order=\"LittleEndian\"", "0 1 0 2 0 3", "UInt8", "format=\"binary\"",
              "\n          " + base64(uintBytes(data.size(), 4)) + base64(data) + "\n        ",
              ""));
  expectRamp(loadVolume(path), {2, 3, 4}, 10.0, 0.0);
}

TEST(VtiLoader, InlineBinaryZlibInt8WidenedToInt16) {
  TempDir dir;
  const std::string data = bytesOf(ramp<int8_t>(-3.0, 30.0));
  const std::string blocks = zlibBlocks(data, 16, 4, false);
  const size_t tableSize = 4 * (3 + 2);
  const std::string path = dir.write(
      "v.vti", vtiFile("byte_order=\"LittleEndian\" compressor=\"vtkZLibDataCompressor\"",
                       "0 1 0 2 0 3", "Int8", "format=\"binary\" NumberOfComponents=\"1\"",
                       base64(blocks.substr(0, tableSize)) + base64(blocks.substr(tableSize)), ""));
  const Volume v = loadVolume(path);
  EXPECT_EQ(v.type(), ScalarType::Int16);
  expectRamp(v, {2, 3, 4}, -3.0, 30.0);
}

TEST(VtiLoader, Float64AndInt32ArraysBecomeFloat32) {
  TempDir dir;
  const std::string doubles = bytesOf(ramp<double>(-0.125, 4.0), true);
  const Volume d = loadVolume(
      dir.write("d.vti", vtiFile("byte_order=\"BigEndian\" header_type=\"UInt64\"", "0 1 0 2 0 3",
                                 "Float64", "format=\"appended\" offset=\"0\"", "",
                                 uintBytes(doubles.size(), 8, true) + doubles)));
  EXPECT_EQ(d.type(), ScalarType::Float32);
  expectRamp(d, {2, 3, 4}, -0.125, 4.0);
  EXPECT_EQ(d.notes().back(), "float64 data converted to float32");
  const std::string ints = bytesOf(ramp<int32_t>(-40000.0, 3.0));
  const Volume i = loadVolume(dir.write(
      "i.vti", vtiFile("byte_order=\"LittleEndian\"", "0 1 0 2 0 3", "Int32", "format=\"binary\"",
                       base64(uintBytes(ints.size(), 4) + ints), "")));
  expectRamp(i, {2, 3, 4}, -40000.0, 3.0);
}

TEST(VtiLoader, AsciiArraysOfIntegersAndReals) {
  TempDir dir;
  std::string ints, reals;
  for (int i = 0; i < 24; ++i) {
    ints += std::to_string(-500 + 45 * i) + (i % 6 == 5 ? "\n          " : " ");
    reals += std::to_string(0.5 * i - 2.0) + " ";
  }
  const Volume s = loadVolume(dir.write(
      "s.vti", vtiFile("", "0 1 0 2 0 3", "Int16", "format=\"ascii\"", "\n          " + ints, "")));
  EXPECT_EQ(s.type(), ScalarType::Int16);
  expectRamp(s, {2, 3, 4}, 45.0, -500.0);
  expectRamp(loadVolume(dir.write("d.vti", vtiFile("byte_order=\"BigEndian\"", "0 1 0 2 0 3",
                                                   "Float64", "format=\"ascii\"", reals, ""))),
             {2, 3, 4}, 0.5, -2.0);
  testing::expectVolumeLoadError(
      dir.write("short.vti", vtiFile("", "0 1 0 2 0 3", "UInt8", "format=\"ascii\"", "1 2 3", "")),
      "ASCII DataArray cannot hold 24 values");
}

// ---- raw ----

TEST(RawLoader, ParsesOptions) {
  RawOptions o = parseRawOptions("256,256,109", "ushort", "1,1,2", "big");
  EXPECT_EQ(o.dims, (std::array<int64_t, 3>{256, 256, 109}));
  EXPECT_EQ(o.type, FileScalar::UInt16);
  EXPECT_EQ(o.spacing, glm::dvec3(1.0, 1.0, 2.0));
  EXPECT_TRUE(o.bigEndian);
  o = parseRawOptions(" 4x5x6 ", "FLOAT32", "0.5", "little");
  EXPECT_EQ(o.dims, (std::array<int64_t, 3>{4, 5, 6}));
  EXPECT_EQ(o.type, FileScalar::Float32);
  EXPECT_EQ(o.spacing, glm::dvec3(0.5));
  EXPECT_FALSE(o.bigEndian);
  EXPECT_EQ(parseRawOptions("1,1,1", "uchar", "", "").type, FileScalar::UInt8);
  EXPECT_EQ(parseRawOptions("1,1,1", "short", "", "").type, FileScalar::Int16);
  EXPECT_EQ(parseRawOptions("1,1,1", "float", "", "").type, FileScalar::Float32);
  EXPECT_EQ(parseRawOptions("1,1,1", "int16", "", "").type, FileScalar::Int16);
  EXPECT_EQ(parseRawOptions("1,1,1", "uint16", "", "").type, FileScalar::UInt16);
  EXPECT_EQ(parseRawOptions("1,1,1", "uint8", "", "").type, FileScalar::UInt8);
  EXPECT_EQ(parseRawOptions("1,1,1", "char", "", "").type, FileScalar::Int8);
  EXPECT_EQ(parseRawOptions("1,1,1", "int", "", "").type, FileScalar::Int32);
  EXPECT_EQ(parseRawOptions("1,1,1", "UInt64", "", "").type, FileScalar::UInt64);
  EXPECT_EQ(parseRawOptions("1,1,1", "double", "", "").type, FileScalar::Float64);
}

TEST(RawLoader, WideTypesBecomeFloat32) {
  TempDir dir;
  const std::string path = dir.write("d.raw", bytesOf(ramp<double>(-0.75, 12.0), true));
  const Volume v = loadRawVolume(path, parseRawOptions("2,3,4", "float64", "", "big"));
  EXPECT_EQ(v.type(), ScalarType::Float32);
  expectRamp(v, {2, 3, 4}, -0.75, 12.0);
}

TEST(RawLoader, LittleAndBigEndian) {
  TempDir dir;
  const std::string le = dir.write("w.raw", bytesOf(ramp<int16_t>(-7.0, 3.0)) + "extra");
  const std::string be = dir.write("x.raw", bytesOf(ramp<int16_t>(-7.0, 3.0), true));
  RawOptions o = parseRawOptions("2,3,4", "int16", "1,2,3", "little");
  const Volume a = loadRawVolume(le, o);
  expectRamp(a, {2, 3, 4}, -7.0, 3.0);
  EXPECT_EQ(a.spacing(), glm::dvec3(1.0, 2.0, 3.0));
  o.bigEndian = true;
  const Volume b = loadRawVolume(be, o);
  EXPECT_TRUE(a.bytes() == b.bytes());
}

}  // namespace
}  // namespace ewa
