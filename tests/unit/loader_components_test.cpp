// Several values a voxel (colour and vector images): MetaImage channels, .vti components, NIfTI
// RGB and RGBA, legacy VTK SCALARS of several components, COLOR_SCALARS and VECTORS open one
// component at a time with --channel.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/volume_loader.h"
#include "loader_test_files.h"
#include "medical_test_files.h"

namespace ewa {
namespace {

using testing::bytesOf;
using testing::expectLoadError;
using testing::TempDir;

// 24 voxels of `components` values: component c of voxel n is 10 n + c.
template <typename T>
std::vector<T> interleaved(int components) {
  std::vector<T> v;
  for (int n = 0; n < 24; ++n)
    for (int c = 0; c < components; ++c) v.push_back(T(10 * n + c));
  return v;
}

// Every component opens as its own volume; one past the last is refused in one line.
void expectComponents(const std::string& path, int components) {
  for (int c = 0; c < components; ++c) {
    SCOPED_TRACE(path + " component " + std::to_string(c));
    const Volume v = loadVolume(path, {"", 0, c, {}});
    ASSERT_EQ(v.dims(), (std::array<int64_t, 3>{2, 3, 4}));
    EXPECT_EQ(v.channel(), c);
    EXPECT_EQ(v.channelCount(), components);
    for (int n = 0; n < 24; ++n) ASSERT_DOUBLE_EQ(v.valueAt(n), 10.0 * n + c) << "voxel " << n;
    const std::string note =
        std::to_string(components) + " components a voxel; showing component " + std::to_string(c);
    EXPECT_NE(testing::allNotes(v).find(note), std::string::npos) << testing::allNotes(v);
  }
  expectLoadError(
      [&] {
        loadVolume(path, {"", 0, components, {}});
      },
      path,
      "--channel " + std::to_string(components) + " is out of range (" +
          std::to_string(components) + " channels)");
}

TEST(Components, MetaImageChannels) {
  TempDir dir;
  expectComponents(dir.write("rgb.mha",
                             "NDims = 3\nDimSize = 2 3 4\nElementType = MET_UCHAR\n"
                             "ElementNumberOfChannels = 3\nElementDataFile = LOCAL\n" +
                                 bytesOf(interleaved<uint8_t>(3))),
                   3);
  expectComponents(dir.write("v.mha",
                             "NDims = 3\nDimSize = 2 3 4\nElementType = MET_FLOAT\n"
                             "ElementNumberOfChannels = 2\nBinaryDataByteOrderMSB = True\n"
                             "ElementDataFile = LOCAL\n" +
                                 bytesOf(interleaved<float>(2), true)),
                   2);
}

TEST(Components, VtiArrayOfThreeComponents) {
  TempDir dir;
  const std::string data = bytesOf(interleaved<float>(3));
  const std::string xml =
      "<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt32\"><ImageData WholeExtent=\"0 1 0 2 0 3\" Origin=\"0 0 0\" "
      "Spacing=\"1 1 1\"><Piece Extent=\"0 1 0 2 0 3\"><PointData Vectors=\"velocity\">"
      "<DataArray type=\"Float32\" Name=\"velocity\" NumberOfComponents=\"3\" "
      "format=\"appended\" offset=\"0\"/></PointData></Piece></ImageData>"
      "<AppendedData encoding=\"raw\">_" +
      testing::uintBytes(data.size(), 4) + data + "</AppendedData></VTKFile>";
  expectComponents(dir.write("v.vti", xml), 3);
}

TEST(Components, NiftiRgbAndRgba) {
  TempDir dir;
  testing::NiftiFields f;
  f.datatype = 128;
  f.bitpix = 24;
  expectComponents(dir.write("rgb.nii", testing::niftiHeader(f) + bytesOf(interleaved<uint8_t>(3))),
                   3);
  f.datatype = 2304;
  f.bitpix = 32;
  f.sclSlope = 2.0f;  // not applied to colour
  expectComponents(
      dir.write("rgba.nii", testing::niftiHeader(f, true) + bytesOf(interleaved<uint8_t>(4), true)),
      4);
}

TEST(Components, LegacyVtkScalarsColourAndVectors) {
  TempDir dir;
  const std::string head =
      "# vtk DataFile Version 3.0\ncomponents\n%s\nDATASET STRUCTURED_POINTS\n"
      "DIMENSIONS 2 3 4\nPOINT_DATA 24\n";
  const auto file = [&](const std::string& encoding, const std::string& data) {
    std::string h = head;
    h.replace(h.find("%s"), 2, encoding);
    return h + data;
  };
  std::string ascii;
  for (float v : interleaved<float>(2)) ascii += std::to_string(v) + " ";
  expectComponents(
      dir.write("s.vtk", file("ASCII", "SCALARS v float 2\nLOOKUP_TABLE default\n" + ascii)), 2);
  expectComponents(
      dir.write("c.vtk", file("BINARY", "COLOR_SCALARS c 3\n" + bytesOf(interleaved<uint8_t>(3)))),
      3);
  expectComponents(dir.write("v.vtk", file("BINARY", "VECTORS v double\n" +
                                                         bytesOf(interleaved<double>(3), true))),
                   3);
}

}  // namespace
}  // namespace ewa
