// MRC2014 and CCP4 maps: every mode ewaview reads, both byte orders, the cell's spacing, the
// origin, the axis order and IMOD's unsigned bytes; bad headers fail in one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <string>
#include <vector>

#include "io/volume_loader.h"
#include "loader_test_files.h"

namespace ewa {
namespace {

using testing::bytesOf;
using testing::expectVolumeLoadError;
using testing::TempDir;

// A 1024-byte MRC header: `ints` and `reals` set words (1-based) to values, the rest zero.
struct MrcFile {
  std::vector<std::pair<int, int32_t>> ints;
  std::vector<std::pair<int, float>> reals;
  bool big = false;
  bool stamp = true;  // the machine stamp at byte 212
  std::string data;

  std::string bytes() const {
    std::vector<uint32_t> words(256, 0);
    for (const auto& [n, v] : ints) words[size_t(n - 1)] = uint32_t(v);
    for (const auto& [n, v] : reals) std::memcpy(&words[size_t(n - 1)], &v, 4);
    std::string out = bytesOf(words, big);
    std::memcpy(&out[208], "MAP ", 4);
    out[212] = stamp ? char(big ? 0x11 : 0x44) : 0;
    out[213] = stamp ? char(big ? 0x11 : 0x44) : 0;
    return out + data;
  }
};

// 2 x 3 x 4 with the cell 2 x 6 x 20 angstroms sampled 2, 3, 4 times: spacing 1, 2, 5.
MrcFile ramp(int mode, const std::string& data, bool big = false) {
  MrcFile f;
  f.ints = {{1, 2}, {2, 3}, {3, 4}, {4, mode}, {8, 2}, {9, 3}, {10, 4}, {17, 1}, {18, 2}, {19, 3}};
  f.reals = {{11, 2.0f}, {12, 6.0f}, {13, 20.0f}};
  f.big = big;
  f.data = data;
  return f;
}

template <typename T>
std::vector<T> values(double scale, double offset) {
  std::vector<T> v(24);
  for (size_t i = 0; i < 24; ++i) v[i] = T(offset + scale * double(i));
  return v;
}

void expectRamp(const Volume& v, double scale, double offset) {
  ASSERT_EQ(v.dims(), (std::array<int64_t, 3>{2, 3, 4}));
  for (int64_t n = 0; n < 24; ++n)
    ASSERT_NEAR(v.valueAt(n), offset + scale * double(n), 1e-6) << "voxel " << n;
}

TEST(Mrc, EveryModeInBothByteOrders) {
  TempDir dir;
  for (bool big : {false, true}) {
    SCOPED_TRACE(big ? "big-endian" : "little-endian");
    const Volume f32 = loadVolume(
        dir.write("f.mrc", ramp(2, bytesOf(values<float>(0.5, -3.0), big), big).bytes()));
    expectRamp(f32, 0.5, -3.0);
    EXPECT_EQ(f32.type(), ScalarType::Float32);
    EXPECT_EQ(f32.spacing(), glm::dvec3(1.0, 2.0, 5.0));
    EXPECT_EQ(f32.unit(), "\xC3\x85");
    expectRamp(loadVolume(dir.write(
                   "s.map", ramp(1, bytesOf(values<int16_t>(-100, 900), big), big).bytes())),
               -100, 900);
    expectRamp(loadVolume(dir.write("u.rec",
                                    ramp(6, bytesOf(values<uint16_t>(1000, 7), big), big).bytes())),
               1000, 7);
    // Half floats: 1.5 * n - 8 is exact in binary16.
    std::vector<uint16_t> halves(24);
    for (size_t i = 0; i < 24; ++i) {
      const float f = float(1.5 * double(i) - 8.0);
      const int e = f == 0.0f ? 0 : std::ilogb(f);
      const uint16_t sign = f < 0 ? 0x8000 : 0;
      const double m = std::fabs(f) / std::ldexp(1.0, e);  // 1 <= m < 2
      halves[i] = f == 0.0f ? 0
                            : uint16_t(sign | uint16_t((e + 15) << 10) |
                                       uint16_t(std::lround((m - 1.0) * 1024.0)));
    }
    const Volume h = loadVolume(dir.write("h.mrc", ramp(12, bytesOf(halves, big), big).bytes()));
    expectRamp(h, 1.5, -8.0);
    EXPECT_EQ(h.type(), ScalarType::Float32);
  }
  // Old files without a machine stamp: the byte order that gives a mode the format has.
  MrcFile old = ramp(1, bytesOf(values<int16_t>(3, 1), true), true);
  old.stamp = false;
  expectRamp(loadVolume(dir.write("old.mrc", old.bytes())), 3, 1);
}

TEST(Mrc, BytesAreSignedUnlessImodSaysOtherwise) {
  TempDir dir;
  std::string data;
  for (int i = 0; i < 24; ++i) data.push_back(char(uint8_t(120 + i)));  // 120 ... 143
  const Volume mrc2014 = loadVolume(dir.write("s.mrc", ramp(0, data).bytes()));
  EXPECT_EQ(mrc2014.type(), ScalarType::Int16);  // int8 widened
  EXPECT_EQ(mrc2014.valueAt(7), 127);
  EXPECT_EQ(mrc2014.valueAt(8), -128);
  MrcFile imod = ramp(0, data);
  imod.ints.push_back({39, 1146047817});  // IMOD's stamp, flags 0: unsigned bytes
  const Volume unsignedBytes = loadVolume(dir.write("u.mrc", imod.bytes()));
  EXPECT_EQ(unsignedBytes.type(), ScalarType::UInt8);
  EXPECT_EQ(unsignedBytes.valueAt(8), 128);
  imod.ints.push_back({40, 1});  // flags bit 0: signed
  EXPECT_EQ(loadVolume(dir.write("i.mrc", imod.bytes())).valueAt(8), -128);
}

TEST(Mrc, OriginStartAndAxisOrderPlaceTheVoxels) {
  TempDir dir;
  const std::string data = bytesOf(values<float>(1, 0));
  MrcFile placed = ramp(2, data);
  placed.reals.push_back({50, 10.0f});
  placed.reals.push_back({51, 20.0f});
  placed.reals.push_back({52, -30.0f});
  const Volume a = loadVolume(dir.write("a.mrc", placed.bytes()));
  EXPECT_EQ(a.origin(), glm::dvec3(10, 20, -30));
  // Without ORIGIN: NXSTART, NYSTART, NZSTART samples of each axis.
  MrcFile started = ramp(2, data);
  started.ints.insert(started.ints.end(), {{5, 4}, {6, -1}, {7, 2}});
  EXPECT_EQ(loadVolume(dir.write("b.mrc", started.bytes())).origin(), glm::dvec3(4, -2, 10));
  // Columns along z, rows along y, sections along x (MAPC 3, MAPR 2, MAPS 1): the voxel of
  // column i, row j, section k lies at world (k * 1, j * 2, i * 5) with spacing along world
  // x, y, z of 1, 2, 5 (cell 4 x 6 x 10 sampled 4, 3, 2 times).
  MrcFile swapped;
  swapped.ints = {{1, 2}, {2, 3},  {3, 4},  {4, 2},  {8, 4},
                  {9, 3}, {10, 2}, {17, 3}, {18, 2}, {19, 1}};
  swapped.reals = {{11, 4.0f}, {12, 6.0f}, {13, 10.0f}};
  swapped.data = data;
  const Volume s = loadVolume(dir.write("s.mrc", swapped.bytes()));
  // Whatever order the volume keeps its voxels in (a reflected order reverses its slices),
  // the voxel at each world position holds the value written there.
  int found = 0;
  for (int k = 0; k < s.dims()[2]; ++k)
    for (int j = 0; j < s.dims()[1]; ++j)
      for (int i = 0; i < s.dims()[0]; ++i) {
        const glm::dvec3 w = s.worldPosition(i, j, k);
        const int c = int(std::lround(w.z / 5.0)), r = int(std::lround(w.y / 2.0)),
                  sec = int(std::lround(w.x));
        ASSERT_NEAR(glm::length(w - glm::dvec3(sec, 2.0 * r, 5.0 * c)), 0.0, 1e-9);
        ASSERT_EQ(s.value(i, j, k), double(c + 2 * r + 6 * sec)) << i << "," << j << "," << k;
        ++found;
      }
  EXPECT_EQ(found, 24);
}

// A crystal's skewed cell (monoclinic: beta; hexagonal: gamma) puts its voxels on oblique axes;
// the loaded volume is upright and each voxel holds the (linear) field where it lies in world.
TEST(Mrc, CellAnglesSkewTheAxesAndTheGridIsResampled) {
  TempDir dir;
  const auto field = [](const glm::dvec3& w) { return 3.0 * w.x + w.y - 0.5 * w.z; };
  for (const glm::dvec3& angles : {glm::dvec3(90, 120, 90), glm::dvec3(90, 90, 120)}) {
    SCOPED_TRACE(std::to_string(angles.y) + ", " + std::to_string(angles.z));
    // 6 x 5 x 4 samples of a 6 x 10 x 8 cell: spacing 1, 2, 2 along a, b, c.
    const double deg = 3.14159265358979323846 / 180.0;
    const glm::dvec3 a(1, 0, 0), b(std::cos(angles.z * deg), std::sin(angles.z * deg), 0);
    const glm::dvec3 c(std::cos(angles.y * deg), 0, std::sin(angles.y * deg));  // alpha 90
    std::vector<float> data;
    for (int k = 0; k < 4; ++k)
      for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 6; ++i)
          data.push_back(float(field(double(i) * a + 2.0 * j * b + 2.0 * k * c)));
    MrcFile f;
    f.ints = {{1, 6}, {2, 5}, {3, 4}, {4, 2}, {8, 6}, {9, 5}, {10, 4}, {17, 1}, {18, 2}, {19, 3}};
    f.reals = {
        {11, 6.0f},           {12, 10.0f}, {13, 8.0f}, {14, float(angles.x)}, {15, float(angles.y)},
        {16, float(angles.z)}};
    f.data = bytesOf(data);
    const Volume v = loadVolume(dir.write("skew.mrc", f.bytes()));
    std::string notes;
    for (const std::string& n : v.notes()) notes += n + "\n";
    EXPECT_NE(notes.find("sheared 30.0 degrees"), std::string::npos) << notes;
    const double fill = *std::min_element(data.begin(), data.end());
    int checked = 0;
    for (int k = 0; k < v.dims()[2]; ++k)
      for (int j = 0; j < v.dims()[1]; ++j)
        for (int i = 0; i < v.dims()[0]; ++i) {
          if (v.value(i, j, k) == fill) continue;  // a corner the oblique grid does not cover
          ASSERT_NEAR(v.value(i, j, k), field(v.worldPosition(i, j, k)), 1e-3)
              << i << "," << j << "," << k;
          ++checked;
        }
    EXPECT_GE(checked, 60);
  }
  // Angles that make no cell are noted and the axes taken as orthogonal.
  MrcFile bad = ramp(2, bytesOf(values<float>(1, 0)));
  bad.reals.insert(bad.reals.end(), {{14, 10.0f}, {15, 10.0f}, {16, 170.0f}});
  const Volume o = loadVolume(dir.write("bad.mrc", bad.bytes()));
  expectRamp(o, 1, 0);
  EXPECT_NE(o.notes().front().find("make no cell: axes taken as orthogonal"), std::string::npos);
}

TEST(Mrc, BadHeadersFailInOneLine) {
  TempDir dir;
  const std::string data = bytesOf(values<float>(1, 0));
  expectVolumeLoadError(dir.write("short.mrc", std::string(100, '\0')),
                        "shorter than its 1024-byte header");
  expectVolumeLoadError(dir.write("complex.mrc", ramp(4, data).bytes()), "MRC mode 4 is not read");
  expectVolumeLoadError(dir.write("cut.mrc", ramp(2, data.substr(0, 50)).bytes()),
                        "truncated file or wrong sizes?");
  MrcFile axes = ramp(2, data);
  axes.ints.push_back({18, 1});
  expectVolumeLoadError(dir.write("axes.mrc", axes.bytes()),
                        "bad axis order MAPC, MAPR, MAPS 1, 1, 3");
  MrcFile extended = ramp(2, data);
  extended.ints.push_back({24, 1 << 30});
  expectVolumeLoadError(dir.write("ext.mrc", extended.bytes()), "bad extended header length");
  MrcFile huge = ramp(2, data);
  huge.ints.insert(huge.ints.end(), {{1, 1 << 16}, {2, 1 << 16}, {3, 1 << 16}});
  expectVolumeLoadError(dir.write("huge.mrc", huge.bytes()), "more than this machine's memory");
  MrcFile negative = ramp(2, data);
  negative.ints.push_back({2, -3});
  expectVolumeLoadError(dir.write("neg.mrc", negative.bytes()), "must all be positive");
}

}  // namespace
}  // namespace ewa
