// A distributed run's bricks read alone: raw, NRRD and MetaImage boxes by offsets and synthetic
// boxes each equal the whole volume's voxels in that box, sitting where the whole's do; bricks'
// histograms over the whole's range add up to the whole's.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "core/synthetic_volume.h"
#include "io/load_failure.h"
#include "io/region_read.h"
#include "loader_test_files.h"

namespace ewa {
namespace {

using testing::bytesOf;
using testing::TempDir;

constexpr std::array<int64_t, 3> kDims{7, 5, 6};

std::vector<int16_t> ramp() {
  std::vector<int16_t> v(size_t(kDims[0] * kDims[1] * kDims[2]));
  for (size_t i = 0; i < v.size(); ++i) v[i] = int16_t(int(i * 37 % 1001) - 300);
  return v;
}

// Every voxel of `part` equals the whole's at the same place, and sits where it does.
void expectBoxOf(const Volume& whole, const Volume& part, const VoxelRegion& box) {
  ASSERT_EQ(part.dims()[0], box.hi[0] - box.lo[0]);
  ASSERT_EQ(part.dims()[1], box.hi[1] - box.lo[1]);
  ASSERT_EQ(part.dims()[2], box.hi[2] - box.lo[2]);
  EXPECT_EQ(part.type(), whole.type());
  for (int64_t k = 0; k < part.dims()[2]; ++k)
    for (int64_t j = 0; j < part.dims()[1]; ++j)
      for (int64_t i = 0; i < part.dims()[0]; ++i)
        ASSERT_EQ(part.value(i, j, k), whole.value(i + box.lo[0], j + box.lo[1], k + box.lo[2]))
            << i << "," << j << "," << k;
  const glm::dvec3 a = part.worldPosition(1, 2, 0);
  const glm::dvec3 b =
      whole.worldPosition(double(box.lo[0] + 1), double(box.lo[1] + 2), double(box.lo[2]));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-9);
}

const VoxelRegion kBoxes[] = {
    {{0, 0, 0}, {7, 5, 6}}, {{2, 1, 3}, {5, 4, 6}}, {{6, 4, 5}, {7, 5, 6}}};

TEST(BrickRead, RawFileBoxesAreTheWholeVolumesVoxels) {
  TempDir dir;
  const std::string file = dir.write("v.raw", bytesOf(ramp(), true));
  RawOptions raw;
  raw.dims = kDims;
  raw.type = FileScalar::Int16;
  raw.spacing = glm::dvec3(0.5, 1.0, 2.0);
  raw.bigEndian = true;
  const Volume whole = loadRawVolume(file, raw);
  const RawPlacement p = rawFilePlacement(file, kDims, FileScalar::Int16, raw.spacing, true);
  ASSERT_TRUE(placementKeepsVoxelOrder(p));
  for (const VoxelRegion& box : kBoxes) expectBoxOf(whole, loadRawRegion(file, p, box), box);
}

TEST(BrickRead, NrrdAttachedAndDetachedBoxesAreTheWholeVolumesVoxels) {
  TempDir dir;
  const std::string header =
      "NRRD0004\ntype: short\ndimension: 3\nsizes: 7 5 6\nendian: little\nencoding: raw\n"
      "space: left-posterior-superior\nspace directions: (0,0.5,0) (-1,0,0) (0,0,2)\n"
      "space origin: (10,-4,3)\n";
  const std::string attached = dir.write("a.nrrd", header + "\n" + bytesOf(ramp()));
  dir.write("d.raw", "skip" + bytesOf(ramp()));
  const std::string detached = dir.write("d.nhdr", header + "byte skip: 4\ndata file: d.raw\n");
  for (const std::string& file : {attached, detached}) {
    SCOPED_TRACE(file);
    const Volume whole = loadVolume(file);
    const std::optional<RawPlacement> p = nrrdRawPlacement(file, DataFileScope::HeaderFolder);
    ASSERT_TRUE(p && placementKeepsVoxelOrder(*p));
    for (const VoxelRegion& box : kBoxes) expectBoxOf(whole, loadRawRegion(file, *p, box), box);
  }
  // Compressed data are not read by offsets.
  const std::string gz = dir.write("g.nhdr",
                                   "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 1 1 1\n"
                                   "encoding: gzip\ndata file: g.raw.gz\n");
  EXPECT_FALSE(nrrdRawPlacement(gz, DataFileScope::HeaderFolder));
}

TEST(BrickRead, MetaImageBoxesAreTheWholeVolumesVoxels) {
  TempDir dir;
  const std::string header =
      "ObjectType = Image\nNDims = 3\nDimSize = 7 5 6\nElementType = MET_SHORT\n"
      "ElementSpacing = 1 0.5 3\nOffset = -2 5 1\nBinaryDataByteOrderMSB = False\n";
  const std::string local =
      dir.write("l.mha", header + "ElementDataFile = LOCAL\n" + bytesOf(ramp()));
  dir.write("s.raw", bytesOf(ramp()));
  const std::string separate = dir.write("s.mhd", header + "ElementDataFile = s.raw\n");
  for (const std::string& file : {local, separate}) {
    SCOPED_TRACE(file);
    const Volume whole = loadVolume(file);
    const std::optional<RawPlacement> p = metaImageRawPlacement(file, DataFileScope::HeaderFolder);
    ASSERT_TRUE(p && placementKeepsVoxelOrder(*p));
    for (const VoxelRegion& box : kBoxes) expectBoxOf(whole, loadRawRegion(file, *p, box), box);
  }
}

TEST(BrickRead, ABoxOutsideTheVolumeOrATruncatedFileFails) {
  TempDir dir;
  const std::string file = dir.write("v.raw", bytesOf(ramp()));
  const RawPlacement p = rawFilePlacement(file, kDims, FileScalar::Int16, glm::dvec3(1.0), false);
  EXPECT_THROW(loadRawRegion(file, p, {{0, 0, 0}, {8, 5, 6}}), LoadError);
  const std::string shorter = dir.write("s.raw", bytesOf(ramp()).substr(0, 100));
  const RawPlacement q =
      rawFilePlacement(shorter, kDims, FileScalar::Int16, glm::dvec3(1.0), false);
  EXPECT_THROW(loadRawRegion(shorter, q, {{0, 0, 5}, {7, 5, 6}}), LoadError);
}

TEST(BrickRead, MarschnerLobbBoxesAreTheWholeVolumesVoxels) {
  const Volume whole = makeSyntheticVolume("marschner-lobb:17").volume;
  const std::optional<SyntheticRegionSource> source = syntheticRegionSource("marschner-lobb:17");
  ASSERT_TRUE(source);
  EXPECT_EQ(source->dims, (std::array<int64_t, 3>{17, 17, 17}));
  for (const VoxelRegion& box :
       {VoxelRegion{{0, 0, 0}, {17, 17, 17}}, VoxelRegion{{3, 9, 1}, {11, 17, 8}}})
    expectBoxOf(whole, source->make(box.lo, box.hi).volume, box);
  EXPECT_FALSE(syntheticRegionSource("sphere:8"));
}

TEST(BrickRead, BricksHistogramsOverTheWholeRangeAddUpToTheWholes) {
  const Volume whole = makeSyntheticVolume("marschner-lobb:17").volume;
  std::vector<uint64_t> sum(size_t(Volume::histogramBins()), 0);
  // Two bricks split at z = 7, each with ghost voxels that its histogram leaves out.
  for (const auto& [lo, hi, ghostLo, ghostHi] :
       {std::array<int64_t, 4>{0, 7, 0, 9}, std::array<int64_t, 4>{7, 17, 5, 17}}) {
    const Volume part =
        syntheticRegionSource("marschner-lobb:17")->make({0, 0, ghostLo}, {17, 17, ghostHi}).volume;
    const std::vector<uint64_t> h = part.histogramOf({0, 0, lo - ghostLo}, {17, 17, hi - ghostLo},
                                                     whole.minValue(), whole.maxValue());
    for (size_t b = 0; b < sum.size(); ++b) sum[b] += h[b];
  }
  EXPECT_EQ(sum, whole.histogram());
  Volume part = syntheticRegionSource("marschner-lobb:17")->make({0, 0, 0}, {4, 4, 4}).volume;
  part.setValueStatistics(whole.minValue(), whole.maxValue(), whole.histogram());
  EXPECT_EQ(part.minValue(), whole.minValue());
  EXPECT_EQ(part.histogram(), whole.histogram());
  EXPECT_THROW(part.setValueStatistics(1.0, 0.0, whole.histogram()), std::invalid_argument);
}

}  // namespace
}  // namespace ewa
