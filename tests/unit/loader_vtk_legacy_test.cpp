// Legacy VTK STRUCTURED_POINTS files: ASCII and big-endian binary scalars of every type VTK
// writes, COLOR_SCALARS, spacing and origin; other datasets and bad headers fail in one line.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/volume_loader.h"
#include "loader_test_files.h"

namespace ewa {
namespace {

using testing::bytesOf;
using testing::expectVolumeLoadError;
using testing::TempDir;

std::string header(const std::string& encoding, const std::string& scalars,
                   const std::string& dims = "2 3 4", const std::string& points = "24") {
  return "# vtk DataFile Version 3.0\nmade by a test\n" + encoding +
         "\nDATASET STRUCTURED_POINTS\nDIMENSIONS " + dims +
         "\nSPACING 0.5 1 2\nORIGIN -1 2 3.5\nPOINT_DATA " + points + "\n" + scalars + "\n";
}

std::string asciiRamp(double scale, double offset) {
  std::string out;
  for (int i = 0; i < 24; ++i)
    out += std::to_string(offset + scale * i) + (i % 5 == 4 ? "\n" : " ");
  return out + "\n";
}

template <typename T>
std::string binaryRamp(double scale, double offset) {
  std::vector<T> v(24);
  for (size_t i = 0; i < 24; ++i) v[i] = T(offset + scale * double(i));
  return bytesOf(v, true);  // VTK's binary files are big-endian
}

void expectRamp(const Volume& v, double scale, double offset, ScalarType type) {
  ASSERT_EQ(v.dims(), (std::array<int64_t, 3>{2, 3, 4}));
  EXPECT_EQ(v.type(), type);
  EXPECT_EQ(v.spacing(), glm::dvec3(0.5, 1, 2));
  EXPECT_EQ(v.origin(), glm::dvec3(-1, 2, 3.5));
  for (int64_t n = 0; n < 24; ++n)
    ASSERT_NEAR(v.valueAt(n), offset + scale * double(n), 1e-4) << "voxel " << n;
}

TEST(VtkLegacy, AsciiAndBinaryScalarsOfEveryType) {
  TempDir dir;
  const std::string lut = "\nLOOKUP_TABLE default";
  expectRamp(loadVolume(dir.write(
                 "a.vtk", header("ASCII", "SCALARS v float 1" + lut) + asciiRamp(0.25, -2))),
             0.25, -2, ScalarType::Float32);
  expectRamp(
      loadVolume(dir.write("s.vtk", header("ASCII", "SCALARS v short" + lut) + asciiRamp(-7, 30))),
      -7, 30, ScalarType::Int16);
  expectRamp(loadVolume(dir.write("b.vtk", header("BINARY", "SCALARS v unsigned_short" + lut) +
                                               binaryRamp<uint16_t>(1000, 5))),
             1000, 5, ScalarType::UInt16);
  expectRamp(loadVolume(dir.write(
                 "f.vtk", header("BINARY", "SCALARS v float" + lut) + binaryRamp<float>(-0.5, 3))),
             -0.5, 3, ScalarType::Float32);
  expectRamp(loadVolume(dir.write(
                 "c.vtk", header("BINARY", "SCALARS v char 1" + lut) + binaryRamp<int8_t>(-3, 20))),
             -3, 20, ScalarType::Int16);  // signed bytes widened
  // int, unsigned_int, long and double become float32, with a note.
  const Volume d = loadVolume(dir.write(
      "d.vtk", header("BINARY", "SCALARS v double" + lut) + binaryRamp<double>(0.125, -1)));
  expectRamp(d, 0.125, -1, ScalarType::Float32);
  EXPECT_EQ(d.notes().back(), "float64 data converted to float32");
  expectRamp(loadVolume(dir.write("i.vtk", header("BINARY", "SCALARS v int" + lut) +
                                               binaryRamp<int32_t>(-100000, 7))),
             -100000, 7, ScalarType::Float32);
  expectRamp(loadVolume(dir.write(
                 "l.vtk", header("BINARY", "SCALARS v long" + lut) + binaryRamp<int64_t>(3, -5))),
             3, -5, ScalarType::Float32);
  expectRamp(loadVolume(dir.write(
                 "ia.vtk", header("ASCII", "SCALARS v unsigned_int" + lut) + asciiRamp(9, 1))),
             9, 1, ScalarType::Float32);
}

TEST(VtkLegacy, ColorScalarsOfOneValueAreGray) {
  // How VTK writes an unsigned char image: bytes in binary files, 0..1 in ASCII ones.
  TempDir dir;
  expectRamp(loadVolume(dir.write("cb.vtk", header("BINARY", "COLOR_SCALARS ImageFile 1") +
                                                binaryRamp<uint8_t>(10, 2))),
             10, 2, ScalarType::UInt8);
  std::string ascii;
  for (int i = 0; i < 24; ++i) ascii += std::to_string((2.0 + 10.0 * i) / 255.0) + " ";
  expectRamp(loadVolume(dir.write("ca.vtk", header("ASCII", "COLOR_SCALARS ImageFile 1") + ascii)),
             10, 2, ScalarType::UInt8);
}

TEST(VtkLegacy, OtherDatasetsAndBadHeadersFailInOneLine) {
  TempDir dir;
  const std::string lut = "\nLOOKUP_TABLE default";
  const std::string floats = header("ASCII", "SCALARS v float" + lut) + asciiRamp(1, 0);
  expectVolumeLoadError(dir.write("x.vtk", "hello\n"), "not a legacy VTK file");
  std::string poly = floats;
  poly.replace(poly.find("STRUCTURED_POINTS"), 17, "POLYDATA");
  expectVolumeLoadError(dir.write("p.vtk", poly), "DATASET 'POLYDATA' is not read");
  std::string field = floats;
  field.insert(field.find("POINT_DATA"), "FIELD FieldData 1\n");
  expectVolumeLoadError(dir.write("fd.vtk", field), "FIELD before POINT_DATA is not read");
  expectVolumeLoadError(
      dir.write("n.vtk", header("ASCII", "SCALARS v float" + lut, "2 3 4", "25") + asciiRamp(1, 0)),
      "POINT_DATA 25 is not the 24 points of DIMENSIONS");
  expectVolumeLoadError(
      dir.write("v.vtk", header("ASCII", "SCALARS v float 5" + lut) + asciiRamp(1, 0)),
      "SCALARS of '5' components are not read (1 to 4)");
  expectVolumeLoadError(dir.write("vec.vtk", header("ASCII", "VECTORS v float") + asciiRamp(1, 0)),
                        "ASCII data has 24 numbers, not 72");
  expectVolumeLoadError(dir.write("ten.vtk", header("ASCII", "TENSORS v float") + asciiRamp(1, 0)),
                        "'TENSORS' point data is not read");
  expectVolumeLoadError(dir.write("t.vtk", header("ASCII", "SCALARS v bit" + lut) + "0 1\n"),
                        "SCALARS of type 'bit' are not read");
  expectVolumeLoadError(dir.write("cut.vtk", header("BINARY", "SCALARS v float" + lut) +
                                                 binaryRamp<float>(1, 0).substr(0, 40)),
                        "truncated file or wrong sizes?");
  expectVolumeLoadError(dir.write("few.vtk", header("ASCII", "SCALARS v float" + lut) +
                                                 "1 2 3 4 5 6 7 8 9 10 11 "
                                                 "12 13 14 15 16 17 18 19 20\n"),
                        "ASCII data has 20 numbers, not 24");
  expectVolumeLoadError(dir.write("huge.vtk", header("ASCII", "SCALARS v float" + lut,
                                                     "100000 100000 100000", "1000000000000000") +
                                                  "1 2\n"),
                        "more than this machine's memory");
  expectVolumeLoadError(
      dir.write("neg.vtk", header("ASCII", "SCALARS v float" + lut, "2 -3 4", "-24") + "1\n"),
      "must all be positive");
  expectVolumeLoadError(dir.write("end.vtk", header("ASCII", "SCALARS v float")),
                        "the header ends before LOOKUP_TABLE");
}

}  // namespace
}  // namespace ewa
