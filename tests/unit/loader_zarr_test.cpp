// OME-Zarr and bare Zarr v2 arrays: every compressor and type numcodecs writes read exactly,
// fill values, pyramid levels, time points and channels, region reads that touch only their
// chunks, and bad metadata and chunks failing in one line.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "app/options.h"
#include "ci_skip.h"
#include "fuzz_case.h"
#include "io/region_read.h"
#include "io/volume_loader.h"
#include "loader_test_files.h"
#include "python_fixtures.h"

namespace ewa {
namespace {

using testing::bytesOf;
using testing::expectLoadError;
using testing::expectVolumeLoadError;
using testing::TempDir;

// Arrays of 7 x 6 x 5 voxels (numpy shape 5, 6, 7) in chunks of 3 x 4 x 2: edge chunks are
// partial on every axis. ramp = x + 10 y + 100 z.
constexpr const char* kScript = R"PY(
import os, sys
import numpy as np
import zarr
from numcodecs import Blosc, Zstd, Zlib, GZip
out = sys.argv[1]
z, y, x = np.meshgrid(np.arange(5), np.arange(6), np.arange(7), indexing='ij')
ramp = x + 10 * y + 100 * z
def array(name, dtype, compressor, values, **kw):
    a = zarr.open(os.path.join(out, name), mode='w', shape=values.shape, chunks=(2, 4, 3),
                  dtype=dtype, compressor=compressor, **kw)
    a[:] = values
array('u2_blosc_lz4.zarr', '<u2', Blosc('lz4', 5, Blosc.SHUFFLE), ramp)
array('i2_zstd.zarr', '<i2', Zstd(3), -ramp)
array('f4_zlib.zarr', '<f4', Zlib(6), ramp * 0.25)
array('u2_big_gzip.zarr', '>u2', GZip(5), ramp)
array('f4_blosc_zstd_bitshuffle.zarr', '<f4', Blosc('zstd', 3, Blosc.BITSHUFFLE), ramp * 0.5 - 3)
array('u4_blosclz.zarr', '<u4', Blosc('blosclz', 5, Blosc.NOSHUFFLE), ramp * 1000)
array('i1_nested.zarr', '|i1', None, ramp % 200 - 100, dimension_separator='/')
a = zarr.open(os.path.join(out, 'u1_fill.zarr'), mode='w', shape=(5, 6, 7), chunks=(2, 4, 3),
              dtype='|u1', compressor=None, fill_value=7)
a[0:2, 0:4, 0:3] = 1
# OME-NGFF 0.4: t, c, z, y, x and a level of half the resolution.
t, c, z, y, x = np.meshgrid(np.arange(2), np.arange(3), np.arange(4), np.arange(6), np.arange(8),
                            indexing='ij')
full = (10000 * t + 1000 * c + 100 * z + 10 * y + x).astype('<u2')
g = zarr.open_group(os.path.join(out, 'pyramid.zarr'), mode='w')
g.create_dataset('0', data=full, chunks=(1, 1, 2, 3, 4), compressor=Blosc('lz4', 5, Blosc.SHUFFLE))
g.create_dataset('1', data=full[:, :, ::2, ::2, ::2], chunks=(1, 1, 2, 3, 4), compressor=Zstd(1))
space = lambda n: {'name': n, 'type': 'space', 'unit': 'micrometer'}
g.attrs['multiscales'] = [{'version': '0.4', 'name': 'p',
  'axes': [{'name': 't', 'type': 'time', 'unit': 'second'}, {'name': 'c', 'type': 'channel'},
           space('z'), space('y'), space('x')],
  'datasets': [
    {'path': '0', 'coordinateTransformations': [{'type': 'scale', 'scale': [1, 1, 2.0, 0.5, 0.25]},
        {'type': 'translation', 'translation': [0, 0, 10, 20, 30]}]},
    {'path': '1', 'coordinateTransformations': [{'type': 'scale', 'scale': [1, 1, 4.0, 1.0, 0.5]},
        {'type': 'translation', 'translation': [0, 0, 11, 20.25, 30.125]}]}]}]
)PY";

class ZarrFiles : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::make_unique<TempDir>();
    lacking_ = testing::pythonLacks("zarr, numcodecs");
    if (lacking_.empty()) failed_ = testing::runPython(kScript, dir_->path(""));
  }
  static void TearDownTestSuite() { dir_.reset(); }
  void SetUp() override {
    if (!lacking_.empty()) {
      EWA_SKIP_UNLESS_CI() << lacking_;
    }
    ASSERT_EQ(failed_, "");
  }
  static std::string path(const std::string& name) { return dir_->path(name); }

  static std::unique_ptr<TempDir> dir_;
  static std::string lacking_, failed_;
};
std::unique_ptr<TempDir> ZarrFiles::dir_;
std::string ZarrFiles::lacking_, ZarrFiles::failed_;

double ramp(int64_t x, int64_t y, int64_t z) {
  return double(x + 10 * y + 100 * z);
}

// Every voxel of `v` (the box at `lo` of the whole) equals expected(x, y, z) of the whole.
void expectVoxels(const Volume& v, const std::function<double(int64_t, int64_t, int64_t)>& expected,
                  std::array<int64_t, 3> lo = {0, 0, 0}) {
  int wrong = 0;
  for (int64_t z = 0; z < v.dims()[2]; ++z)
    for (int64_t y = 0; y < v.dims()[1]; ++y)
      for (int64_t x = 0; x < v.dims()[0]; ++x) {
        const double want = expected(x + lo[0], y + lo[1], z + lo[2]);
        if (v.value(x, y, z) != want && wrong++ < 5)
          ADD_FAILURE() << "voxel " << x << "," << y << "," << z << ": " << v.value(x, y, z)
                        << ", want " << want;
      }
  EXPECT_EQ(wrong, 0);
}

TEST_F(ZarrFiles, EveryCompressorAndTypeReadsExactly) {
  struct Case {
    const char* name;
    ScalarType type;
    std::function<double(int64_t, int64_t, int64_t)> value;
  };
  const Case cases[] = {
      {"u2_blosc_lz4.zarr", ScalarType::UInt16, ramp},
      {"i2_zstd.zarr", ScalarType::Int16, [](auto x, auto y, auto z) { return -ramp(x, y, z); }},
      {"f4_zlib.zarr", ScalarType::Float32,
       [](auto x, auto y, auto z) { return ramp(x, y, z) * 0.25; }},
      {"u2_big_gzip.zarr", ScalarType::UInt16, ramp},
      {"f4_blosc_zstd_bitshuffle.zarr", ScalarType::Float32,
       [](auto x, auto y, auto z) { return ramp(x, y, z) * 0.5 - 3; }},
      {"u4_blosclz.zarr", ScalarType::Float32,
       [](auto x, auto y, auto z) { return ramp(x, y, z) * 1000; }},
      {"i1_nested.zarr", ScalarType::Int16,
       [](auto x, auto y, auto z) { return std::fmod(ramp(x, y, z), 200.0) - 100; }},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const Volume v = loadVolume(path(c.name));
    EXPECT_EQ(v.dims(), (std::array<int64_t, 3>{7, 6, 5}));
    EXPECT_EQ(v.type(), c.type);
    EXPECT_EQ(v.spacing(), glm::dvec3(1.0));
    expectVoxels(v, c.value);
  }
  // The array's .zarray names it as well as its folder.
  expectVoxels(loadVolume(path("u2_blosc_lz4.zarr/.zarray")), ramp);
}

TEST_F(ZarrFiles, MissingChunksHoldTheFillValue) {
  const Volume v = loadVolume(path("u1_fill.zarr"));
  expectVoxels(v, [](int64_t x, int64_t y, int64_t z) { return x < 3 && y < 4 && z < 2 ? 1 : 7; });
}

double pyramid(int t, int c, int64_t x, int64_t y, int64_t z) {
  return 10000.0 * t + 1000.0 * c + 100.0 * z + 10.0 * y + double(x);
}

TEST_F(ZarrFiles, PyramidLevelsTimePointsChannelsAndPlacement) {
  LoadOptions o;
  o.frame = 1;
  o.channel = 2;
  const Volume full = loadVolume(path("pyramid.zarr"), o);
  EXPECT_EQ(full.dims(), (std::array<int64_t, 3>{8, 6, 4}));
  EXPECT_EQ(full.type(), ScalarType::UInt16);
  EXPECT_EQ(full.spacing(), glm::dvec3(0.25, 0.5, 2.0));
  EXPECT_EQ(full.origin(), glm::dvec3(30, 20, 10));
  EXPECT_EQ(full.unit(), "\xC2\xB5m");
  EXPECT_EQ(full.frameCount(), 2);
  EXPECT_EQ(full.channelCount(), 3);
  expectVoxels(full, [](auto x, auto y, auto z) { return pyramid(1, 2, x, y, z); });

  o.level = 1;
  o.frame = 0;
  o.channel = 1;
  const Volume coarse = loadVolume(path("pyramid.zarr/.zattrs"), o);
  EXPECT_EQ(coarse.dims(), (std::array<int64_t, 3>{4, 3, 2}));
  EXPECT_EQ(coarse.spacing(), glm::dvec3(0.5, 1.0, 4.0));
  EXPECT_EQ(coarse.origin(), glm::dvec3(30.125, 20.25, 11));
  expectVoxels(coarse, [](auto x, auto y, auto z) { return pyramid(0, 1, 2 * x, 2 * y, 2 * z); });

  const std::string p = path("pyramid.zarr");
  o.level = 2;
  expectLoadError([&] { loadVolume(p, o); }, p, "--level 2 is out of range (the image has 2");
  o.level = 0;
  o.frame = 2;
  expectLoadError([&] { loadVolume(p, o); }, p, "--frame 2 is out of range");
  o.frame = 0;
  o.channel = 3;
  expectLoadError([&] { loadVolume(p, o); }, p, "--channel 3 is out of range");
}

TEST_F(ZarrFiles, RegionsEqualTheirBoxOfTheWholeAndReadOnlyTheirChunks) {
  const std::string p = path("u2_blosc_lz4.zarr");
  const RegionSourceShape shape = zarrShape(p, 0);
  EXPECT_EQ(shape.dims, (std::array<int64_t, 3>{7, 6, 5}));
  EXPECT_EQ(shape.type, FileScalar::UInt16);
  VoxelRegion box{{1, 2, 1}, {5, 6, 4}};
  const Volume part = loadZarrRegion(p, 0, 0, 0, box);
  EXPECT_EQ(part.dims(), (std::array<int64_t, 3>{4, 4, 3}));
  EXPECT_EQ(part.origin(), glm::dvec3(1, 2, 1));
  expectVoxels(part, ramp, box.lo);

  // Chunk 2.0.2 (z 4, y 0..3, x 6) lies outside the box: spoilt, the whole fails, the box not.
  testing::TempDir scratch;
  std::filesystem::copy(p, scratch.path("copy.zarr"), std::filesystem::copy_options::recursive);
  const std::string copy = scratch.path("copy.zarr");
  scratch.write("copy.zarr/2.0.2", "not blosc at all, but long enough for a header");
  expectVolumeLoadError(copy, "chunk 2.0.2: not a blosc chunk");
  expectVoxels(loadZarrRegion(copy, 0, 0, 0, box), ramp, box.lo);

  // A box of a time point and channel of a pyramid's level.
  const VoxelRegion small{{3, 1, 1}, {8, 4, 3}};
  expectVoxels(
      loadZarrRegion(path("pyramid.zarr"), 0, 1, 2, small),
      [](auto x, auto y, auto z) { return pyramid(1, 2, x, y, z); }, small.lo);
  const RegionSourceShape coarse = zarrShape(path("pyramid.zarr"), 1);
  EXPECT_EQ(coarse.dims, (std::array<int64_t, 3>{4, 3, 2}));
  EXPECT_EQ(coarse.frames, 2);
  EXPECT_EQ(coarse.channels, 3);
  EXPECT_EQ(coarse.levels, 2);
  expectLoadError(
      [&] {
        loadZarrRegion(p, 0, 0, 0, VoxelRegion{{0, 0, 0}, {8, 6, 5}});
      },
      p, "region 0..8, 0..6, 0..5 is empty or not inside");
}

// Hand-made arrays, no Python needed: a .zarray and raw (uncompressed) chunks.
class ZarrHandMade : public ::testing::Test {
 protected:
  std::string array(const std::string& name, const std::string& zarray) {
    std::filesystem::create_directories(dir_.path(name));
    dir_.write(name + "/.zarray", zarray);
    return dir_.path(name);
  }
  static std::string meta(const std::string& shape, const std::string& chunks,
                          const std::string& dtype, const std::string& extra = "") {
    return "{\"zarr_format\": 2, \"shape\": " + shape + ", \"chunks\": " + chunks +
           ", \"dtype\": \"" + dtype + "\", \"compressor\": null, \"fill_value\": 0, " +
           "\"order\": \"C\", \"filters\": null" + extra + "}";
  }
  TempDir dir_;
};

TEST_F(ZarrHandMade, BigEndianRawChunksAndATwoDimensionalImage) {
  // 3 x 2 x 2 voxels of >u2 in chunks of 2 x 2 x 2: the x edge chunk is padded.
  const std::string a = array("be.zarr", meta("[2, 2, 3]", "[2, 2, 2]", ">u2"));
  for (int cx = 0; cx < 2; ++cx) {
    std::vector<uint16_t> chunk(8);
    for (int i = 0; i < 8; ++i) {
      const int x = cx * 2 + i % 2, y = i / 2 % 2, z = i / 4;
      chunk[size_t(i)] = uint16_t(x < 3 ? ramp(x, y, z) + 300 : 9999);
    }
    dir_.write("be.zarr/0.0." + std::to_string(cx), bytesOf(chunk, true));
  }
  const Volume v = loadVolume(a);
  EXPECT_EQ(v.dims(), (std::array<int64_t, 3>{3, 2, 2}));
  expectVoxels(v, [](auto x, auto y, auto z) { return ramp(x, y, z) + 300; });

  // y, x alone: one slice.
  const std::string flat = array("flat.zarr", meta("[2, 3]", "[2, 3]", "|u1"));
  dir_.write("flat.zarr/0.0", std::string("\1\2\3\4\5\6"));
  const Volume f = loadVolume(flat);
  EXPECT_EQ(f.dims(), (std::array<int64_t, 3>{3, 2, 1}));
  EXPECT_EQ(f.value(2, 1, 0), 6);
}

TEST_F(ZarrHandMade, BadMetadataAndChunksFailInOneLine) {
  const auto bad = [&](const std::string& zarray, const std::string& fragment) {
    SCOPED_TRACE(fragment);
    const std::string a = array("bad.zarr", zarray);
    expectVolumeLoadError(a, fragment);
    std::filesystem::remove_all(a);
  };
  bad("{\"shape\": [2,", "not valid JSON in .zarray");
  bad("[1, 2]", "must hold a JSON object");
  bad(meta("[2, 2, 2]", "[2, 2, 2]", "<c8"), "dtype '<c8' is not read");
  bad(meta("[2, 2, 2]", "[2, 2, 2]", "<f2"), "dtype '<f2' is not read");
  bad(meta("[2, 2, 2]", "[2, 2, 2]", "u2"), "dtype 'u2' is not read");
  bad(meta("[2, 2, 2]", "[2, 2]", "<u2"), "\"chunks\" has 2 sizes for a \"shape\" of 3");
  bad(meta("[2, 0, 2]", "[2, 2, 2]", "<u2"), "\"shape\" must hold positive integers");
  bad(meta("[2, -5, 2]", "[2, 2, 2]", "<u2"), "\"shape\" must hold positive integers");
  bad(meta("[2, 2.5, 2]", "[2, 2, 2]", "<u2"), "\"shape\" must hold positive integers");
  bad(meta("[2]", "[2]", "<u2"), "an array of 1 axes without OME-NGFF axes is not read");
  bad(meta("[2, 2, 2, 2, 2, 2]", "[2, 2, 2, 2, 2, 2]", "<u2"), "an array of 6 axes");
  bad(meta("[2, 2, 2]", "[2000000000, 2000000000, 2000000000]", "<u2"),
      "a chunk of [2000000000,2000000000,2000000000] is more than this machine's memory");
  bad(meta("[400000, 400000, 400000]", "[1, 1, 1]", "<u2"), "is more than this machine's memory");
  bad(meta("[2, 2, 2]", "[2, 2, 2]", "<u2", ", \"order\": \"F\""), "C order only");
  bad(meta("[2, 2, 2]", "[2, 2, 2]", "<u2", ", \"filters\": [{\"id\": \"delta\"}]"),
      "are not read (none only)");
  bad(meta("[2, 2, 2]", "[2, 2, 2]", "<u2", ", \"compressor\": {\"id\": \"lzma\"}"),
      "compressor 'lzma' is not read");
  bad(meta("[2, 2, 2]", "[2, 2, 2]", "|u1", ", \"fill_value\": 300"),
      "fill_value 300 does not fit the array's uint8 type");
  bad(meta("[2, 2, 2]", "[2, 2, 2]", "<u2", ", \"zarr_format\": 3"), "Zarr version 2 only");
  bad(meta("[2, 2, 2]", "[2, 2, 2]", "<u2", ", \"dimension_separator\": \"-\""),
      "dimension_separator");

  // Chunks: short, long, corrupt, too large to be one, a folder.
  const auto badChunk = [&](const std::string& compressor, const std::string& bytes,
                            const std::string& fragment) {
    SCOPED_TRACE(fragment);
    const std::string a = array(
        "chunky.zarr", meta("[2, 2, 2]", "[2, 2, 2]", "<u2", ", \"compressor\": " + compressor));
    dir_.write("chunky.zarr/0.0.0", bytes);
    expectVolumeLoadError(a, fragment);
    std::filesystem::remove_all(a);
  };
  badChunk("null", "abc", "chunk 0.0.0: uncompressed chunk of 3 bytes, the array's chunks 16");
  badChunk("null", std::string(17, 'x'), "uncompressed chunk of 17 bytes");
  badChunk("{\"id\": \"blosc\"}", std::string(40, '\x02'), "not a blosc chunk of 40 bytes");
  badChunk("{\"id\": \"zstd\"}", "garbage!", "chunk 0.0.0: not a zstd chunk");
  badChunk("{\"id\": \"zlib\"}", "garbage!", "chunk 0.0.0");
  badChunk("{\"id\": \"bz2\"}", "garbage!", "chunk 0.0.0");
  badChunk("{\"id\": \"zstd\"}", std::string(70000, '\0'), "is larger than a chunk of 16 bytes");
  // zlib data of more bytes than a chunk holds.
  badChunk("{\"id\": \"zlib\"}", testing::zlibBytes(std::string(64, 'a')), "chunk 0.0.0");
  const std::string folderChunk = array("folder.zarr", meta("[2, 2, 2]", "[2, 2, 2]", "<u2"));
  std::filesystem::create_directories(dir_.path("folder.zarr/0.0.0"));
  expectVolumeLoadError(folderChunk, "0.0.0");
}

TEST_F(ZarrHandMade, BadMultiscalesFailInOneLine) {
  const std::string image = dir_.path("image.zarr");
  std::filesystem::create_directories(image);
  array("image.zarr/0", meta("[2, 2, 2]", "[2, 2, 2]", "|u1"));
  const auto bad = [&](const std::string& zattrs, const std::string& fragment) {
    SCOPED_TRACE(fragment);
    dir_.write("image.zarr/.zattrs", zattrs);
    expectVolumeLoadError(image, fragment);
  };
  const auto multiscales = [](const std::string& datasets, const std::string& axes = "") {
    return "{\"multiscales\": [{\"version\": \"0.4\"" + axes + ", \"datasets\": " + datasets +
           "}]}";
  };
  bad(multiscales("[{\"path\": \"../../etc\"}]"),
      "dataset path '../../etc' must be a folder inside the image");
  bad(multiscales("[{\"path\": \"/etc\"}]"), "must be a folder inside the image");
  bad(multiscales("[{\"path\": \"missing\"}]"), "level 'missing' has no .zarray");
  bad(multiscales("[]"), "must list 1 to 64 levels");
  bad(multiscales("[{\"path\": \"0\"}]", ", \"axes\": [\"z\", \"y\"]"),
      "multiscales names 2 axes for an array of 3");
  bad(multiscales("[{\"path\": \"0\"}]", ", \"axes\": [\"z\", \"q\", \"x\"]"),
      "axis 'q' of type '' is not read");
  bad(multiscales("[{\"path\": \"0\"}]", ", \"axes\": [\"z\", \"y\", \"c\"]"),
      "follows a space axis");
  bad(multiscales("[{\"path\": \"0\", \"coordinateTransformations\": [{\"type\": \"scale\", "
                  "\"scale\": [1, 0, 1]}]}]",
                  ", \"axes\": [\"z\", \"y\", \"x\"]"),
      "scale must be positive");
  bad(multiscales("[{\"path\": \"0\", \"coordinateTransformations\": [{\"type\": \"scale\", "
                  "\"path\": \"s.bin\"}]}]",
                  ", \"axes\": [\"z\", \"y\", \"x\"]"),
      "a binary \"path\" is not read");
  bad("{\"multiscales\": 3}", "\"multiscales\" must be a list of images");
  // A group without images, and a folder named .zarr without any metadata.
  dir_.write("image.zarr/.zattrs", "{}");
  std::filesystem::remove_all(dir_.path("image.zarr/0"));
  expectVolumeLoadError(image, "a Zarr group without OME-NGFF multiscales");
  std::filesystem::create_directories(dir_.path("empty.zarr"));
  expectVolumeLoadError(dir_.path("empty.zarr"), "not a Zarr image");
}

TEST(ZarrOptions, LevelAndDatasetReachTheLoadOptions) {
  const char* argv[] = {"ewaview", "img.zarr", "--level", "2", "--dataset", "/group/raw"};
  Options o;
  ASSERT_TRUE(parseCommandLine(6, argv, &o).run);
  EXPECT_EQ(o.load.level, 2);
  EXPECT_EQ(o.load.dataset, "/group/raw");
  const char* negative[] = {"ewaview", "img.zarr", "--level", "-1"};
  EXPECT_EQ(parseCommandLine(4, negative, &o).exitCode, 2);
}

TEST(ZarrOptions, LevelOfAnythingButZarrIsAUsageErrorNamingTheFile) {
  testing::TempDir scratch;
  scratch.write("plain.nrrd", "NRRD0004\n");
  std::filesystem::create_directories(scratch.path("img.zarr"));
  scratch.write("img.zarr/.zattrs", "{}");
  scratch.write("volume.zip", "PK");
  auto parse = [](std::vector<std::string> words, std::string* err) {
    words.insert(words.begin(), "ewaview");
    std::vector<const char*> argv;
    for (const std::string& w : words) argv.push_back(w.c_str());
    Options o;
    ::testing::internal::CaptureStderr();
    const ParseResult r = parseCommandLine(int(argv.size()), argv.data(), &o);
    *err = ::testing::internal::GetCapturedStderr();
    return r;
  };
  std::string err;
  const std::string plain = scratch.path("plain.nrrd");
  EXPECT_EQ(parse({plain, "--level", "1"}, &err).exitCode, 2);
  EXPECT_EQ(err, "ewaview: " + plain +
                     ": --level 1 picks a level of an OME-Zarr pyramid, and this is not an "
                     "OME-Zarr image (see --help)\n");
  EXPECT_TRUE(parse({plain, "--level", "0"}, &err).run) << "full resolution, which every file has";
  EXPECT_EQ(parse({"--synthetic", "sphere:8", "--level", "1"}, &err).exitCode, 2);
  EXPECT_NE(err.find("not of --synthetic sphere:8"), std::string::npos) << err;
  EXPECT_EQ(
      parse({plain, "--raw-dims", "2,2,2", "--raw-type", "uint8", "--level", "1"}, &err).exitCode,
      2);
  EXPECT_EQ(parse({"--level", "1"}, &err).exitCode, 2);
  EXPECT_NE(err.find("the default volume"), std::string::npos) << err;
  // A Zarr folder, an archive (which may hold one) and a missing path (loading says so) pass.
  EXPECT_TRUE(parse({scratch.path("img.zarr"), "--level", "1"}, &err).run) << err;
  EXPECT_TRUE(parse({scratch.path("volume.zip"), "--level", "1"}, &err).run) << err;
  EXPECT_TRUE(parse({scratch.path("none.nrrd"), "--level", "1"}, &err).run) << err;
  EXPECT_TRUE(parse({plain}, &err).run) << err;
}

TEST_F(ZarrHandMade, FuzzSeedsAreArraysThatLoad) {
  // fuzz/zarr_fuzzer.cpp's input: the .zarray, then chunks 0.0.0 and 0.0.1.
  int seeds = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(EWA_FUZZ_DIR) + "/corpus/zarr")) {
    const std::string bytes = testing::fileBytes(entry.path().string());
    const std::vector<std::string> sections =
        fuzz::splitSections(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
    ASSERT_EQ(sections.size(), 3u) << entry.path();
    const std::string a = array("seed.zarr", sections[0]);
    dir_.write("seed.zarr/0.0.0", sections[1]);
    dir_.write("seed.zarr/0.0.1", sections[2]);
    const Volume v = loadVolume(a);
    EXPECT_EQ(v.dims(), (std::array<int64_t, 3>{4, 2, 2})) << entry.path();
    EXPECT_EQ(v.value(3, 1, 1), 45) << entry.path();
    std::filesystem::remove_all(a);
    ++seeds;
  }
  EXPECT_GE(seeds, 3);
}

}  // namespace
}  // namespace ewa
