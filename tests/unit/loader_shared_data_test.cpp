// Loads every real volume in ../shared/data (but DICOM and .slc) and checks what it holds.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "io/volume_loader.h"

// The expected values were computed once with a python3 script reading the files' bytes
// directly (zlib/gzip for the compressed ones), not with this code.

namespace ewa {
namespace {

struct Voxel {
  int64_t i, j, k;
  double value;
};

struct Expected {
  std::array<int64_t, 3> dims;
  ScalarType type;
  glm::dvec3 spacing;
  double min, max;
  std::vector<Voxel> voxels;
};

class SharedData : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::is_directory(EWA_SHARED_DATA)) {
      GTEST_SKIP() << "shared data folder " << EWA_SHARED_DATA
                   << " is absent; real-volume loader tests skipped";
    }
  }
  static std::string data(const std::string& relative) {
    return std::string(EWA_SHARED_DATA) + "/" + relative;
  }
  static void check(const Volume& v, const Expected& e) {
    EXPECT_EQ(v.dims(), e.dims);
    EXPECT_EQ(v.type(), e.type) << scalarName(v.type());
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(v.spacing()[a], e.spacing[a], 1e-9) << "axis " << a;
    EXPECT_DOUBLE_EQ(v.minValue(), e.min);
    EXPECT_DOUBLE_EQ(v.maxValue(), e.max);
    for (const Voxel& p : e.voxels) {
      EXPECT_DOUBLE_EQ(v.value(p.i, p.j, p.k), p.value) << p.i << "," << p.j << "," << p.k;
    }
  }
};

const glm::dvec3 kUnit{1.0};

TEST_F(SharedData, EngineVtiMatchesNhdr) {
  const Expected e{{256, 256, 128},
                   ScalarType::UInt8,
                   kUnit,
                   0,
                   255,
                   {{128, 128, 64, 133}, {100, 100, 50, 5}, {0, 0, 0, 0}, {200, 100, 64, 5}}};
  const Volume vti = loadVolume(data("engine/engine.vti"));
  const Volume nhdr = loadVolume(data("engine/engine.nhdr"));
  check(vti, e);
  check(nhdr, e);
  EXPECT_TRUE(vti.bytes() == nhdr.bytes());
}

TEST_F(SharedData, BonsaiVtiMatchesNhdr) {
  const Expected e{{256, 256, 256},
                   ScalarType::UInt8,
                   kUnit,
                   0,
                   255,
                   {{0, 0, 0, 40}, {128, 128, 128, 13}, {10, 20, 30, 0}}};
  const Volume vti = loadVolume(data("bonsai/bonsai.vti"));
  const Volume nhdr = loadVolume(data("bonsai/bonsai.nhdr"));
  check(vti, e);
  check(nhdr, e);
  EXPECT_TRUE(vti.bytes() == nhdr.bytes());
}

TEST_F(SharedData, AneurismVtiMatchesNhdr) {
  const Expected e{
      {256, 256, 256}, ScalarType::UInt8, kUnit, 0, 255, {{120, 82, 7, 255}, {0, 0, 0, 0}}};
  const Volume vti = loadVolume(data("aneurism/aneurism.vti"));
  const Volume nhdr = loadVolume(data("aneurism/aneurism.nhdr"));
  check(vti, e);
  check(nhdr, e);
  EXPECT_TRUE(vti.bytes() == nhdr.bytes());
}

TEST_F(SharedData, CtHeadBigEndianUInt16) {
  check(loadVolume(data("cthead/CThead.nhdr")),
        {{256, 256, 113},
         ScalarType::UInt16,
         {1, 1, 2},
         0,
         3272,
         {{0, 0, 0, 25}, {128, 128, 56, 2322}, {100, 100, 50, 0}}});
}

TEST_F(SharedData, MrBrainRaw) {
  const RawOptions options = parseRawOptions("256,256,109", "uint16", "1,1,2", "big");
  check(loadRawVolume(data("mrbrain/MRbrain.raw"), options),
        {{256, 256, 109},
         ScalarType::UInt16,
         {1, 1, 2},
         1026,
         5119,
         {{0, 0, 0, 1060}, {100, 100, 50, 2164}, {128, 128, 54, 1646}}});
}

TEST_F(SharedData, ToothAttachedNrrd) {
  check(loadVolume(data("tooth/tooth.nrrd")),
        {{103, 94, 161},
         ScalarType::UInt8,
         kUnit,
         0,
         255,
         {{0, 0, 0, 74}, {50, 47, 80, 158}, {10, 20, 30, 77}}});
}

TEST_F(SharedData, Lidc2MetaImageLocalZlib) {
  const Volume v = loadVolume(data("lidc2/LIDC2.mha"));
  check(v, {{256, 256, 133},
            ScalarType::UInt8,
            {1.40625, 1.40625, 2.5},
            0,
            255,
            {{128, 128, 66, 128}, {10, 20, 30, 0}}});
  EXPECT_NEAR(v.origin().y, 360.0, 1e-9);
  EXPECT_NEAR(v.origin().z, 332.5, 1e-9);
}

TEST_F(SharedData, HeadMrMetaImage) {
  check(loadVolume(data("headmr/HeadMRVolume.mhd")),
        {{48, 62, 42},
         ScalarType::UInt8,
         {4, 4, 4},
         0,
         255,
         {{0, 0, 0, 1}, {24, 31, 21, 79}, {10, 20, 30, 32}}});
}

TEST_F(SharedData, HydrogenDat) {
  check(loadVolume(data("hydrogen/hydrogenatom.dat")),
        {{128, 128, 128}, ScalarType::UInt8, kUnit, 0, 250, {{64, 64, 64, 62}, {10, 20, 30, 0}}});
}

TEST_F(SharedData, NucleonDatAndNrrd) {
  const Expected e{
      {41, 41, 41}, ScalarType::UInt8, kUnit, 0, 249, {{20, 20, 20, 8}, {10, 20, 30, 117}}};
  const Volume dat = loadVolume(data("nucleon/nucleon.dat"));
  const Volume nrrd = loadVolume(data("nucleon/nucleon.nrrd"));
  check(dat, e);
  check(nrrd, e);
  EXPECT_TRUE(dat.bytes() == nrrd.bytes());
}

TEST_F(SharedData, WalnutDatUInt16) {
  check(loadVolume(data("walnut/walnut.dat")), {{128, 96, 114},
                                                ScalarType::UInt16,
                                                kUnit,
                                                0,
                                                22526,
                                                {{64, 48, 57, 5353}, {10, 20, 30, 729}}});
}

TEST_F(SharedData, FetalT2GzipFloat) {
  const Volume v = loadVolume(data("fetal-t2/template_T2.nrrd"));
  check(v, {{117, 159, 126},
            ScalarType::Float32,
            glm::dvec3(0.859375),
            0.0,
            static_cast<double>(710.6775512695312f),
            {{58, 79, 63, static_cast<double>(401.7080383300781f)},
             {10, 20, 30, static_cast<double>(36.73801803588867f)}}});
  EXPECT_DOUBLE_EQ(v.origin().x, -49.84375);
  EXPECT_DOUBLE_EQ(v.origin().y, 67.890625);
  EXPECT_DOUBLE_EQ(v.origin().z, -53.7109375);
}

TEST_F(SharedData, HeadSqPatternOf93Slices) {
  check(loadVolume(data("headsq/quarter.nhdr")),
        {{64, 64, 93},
         ScalarType::Int16,
         {3.2, 3.2, 1.5},
         0,
         3926,
         {{0, 0, 0, 0}, {32, 32, 46, 122}, {10, 20, 30, 861}}});
}

}  // namespace
}  // namespace ewa
