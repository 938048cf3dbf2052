// HDF5 files written by h5py: the dataset chosen (the only 3D one, or --dataset), integer and
// float types read exactly, spacing from element_size_um or spacing, hyperslab regions, and bad
// files and names failing in one line.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "ci_skip.h"
#include "io/region_read.h"
#include "io/volume_loader.h"
#include "loader_test_files.h"
#include "python_fixtures.h"

namespace ewa {
namespace {

using testing::expectLoadError;
using testing::expectVolumeLoadError;
using testing::TempDir;

// Datasets of 7 x 6 x 5 voxels (numpy shape 5, 6, 7); ramp = x + 10 y + 100 z.
constexpr const char* kScript = R"PY(
import os, sys
import numpy as np
import h5py
out = sys.argv[1]
z, y, x = np.meshgrid(np.arange(5), np.arange(6), np.arange(7), indexing='ij')
ramp = x + 10 * y + 100 * z
with h5py.File(os.path.join(out, 'two.h5'), 'w') as f:
    a = f.create_dataset('raw', data=ramp.astype('<u2'))
    a.attrs['element_size_um'] = np.array([2.0, 0.5, 0.25])
    g = f.create_group('group')
    g.create_dataset('probability', data=(ramp * 0.125).astype('>f4'), chunks=(2, 3, 4),
                     compression='gzip')
    f.create_dataset('flat', data=np.zeros((3, 4), 'u1'))
with h5py.File(os.path.join(out, 'one.hdf5'), 'w') as f:
    d = f.create_dataset('volume', data=(ramp % 200 - 100).astype('i1'))
    d.attrs['spacing'] = np.array([3, 2, 1], 'i4')
    f.create_dataset('wide', data=np.zeros((2, 2), 'i4'))
with h5py.File(os.path.join(out, 'wide.h5'), 'w') as f:
    f.create_dataset('v', data=(ramp * 70000).astype('<i4'))
    f.create_dataset('complex', data=np.zeros((2, 2, 2), 'c8'))
    f.create_dataset('u8', data=(ramp * 3).astype('<u8'))
with h5py.File(os.path.join(out, 'none.h5'), 'w') as f:
    f.create_dataset('flat', data=np.zeros((3, 4), 'u1'))
)PY";

class Hdf5Files : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::make_unique<TempDir>();
    lacking_ = testing::pythonLacks("h5py, numpy");
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
std::unique_ptr<TempDir> Hdf5Files::dir_;
std::string Hdf5Files::lacking_, Hdf5Files::failed_;

double ramp(int64_t x, int64_t y, int64_t z) {
  return double(x + 10 * y + 100 * z);
}

template <typename F>
void expectVoxels(const Volume& v, F expected, std::array<int64_t, 3> lo = {0, 0, 0}) {
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

Volume load(const std::string& path, const std::string& dataset) {
  LoadOptions o;
  o.dataset = dataset;
  return loadVolume(path, o);
}

TEST_F(Hdf5Files, DatasetsTypesAndSpacing) {
  const Volume raw = load(path("two.h5"), "raw");
  EXPECT_EQ(raw.dims(), (std::array<int64_t, 3>{7, 6, 5}));
  EXPECT_EQ(raw.type(), ScalarType::UInt16);
  EXPECT_EQ(raw.spacing(), glm::dvec3(0.25, 0.5, 2.0));  // element_size_um is z, y, x
  EXPECT_EQ(raw.unit(), "\xC2\xB5m");
  expectVoxels(raw, ramp);

  // Big-endian float32, chunked and deflated, in a group; the leading slash is optional.
  const Volume p = load(path("two.h5"), "/group/probability");
  EXPECT_EQ(p.type(), ScalarType::Float32);
  EXPECT_EQ(p.spacing(), glm::dvec3(1.0));
  expectVoxels(p, [](auto x, auto y, auto z) { return ramp(x, y, z) * 0.125; });

  // The file's only 3D dataset (a 2D one beside it), int8 widened, spacing from "spacing".
  const Volume one = loadVolume(path("one.hdf5"));
  EXPECT_EQ(one.type(), ScalarType::Int16);
  EXPECT_EQ(one.spacing(), glm::dvec3(1, 2, 3));
  EXPECT_EQ(one.unit(), "");
  expectVoxels(one, [](auto x, auto y, auto z) { return std::fmod(ramp(x, y, z), 200.0) - 100; });

  expectVoxels(load(path("wide.h5"), "v"), [](auto x, auto y, auto z) {
    return double(float(ramp(x, y, z) * 70000));  // int32 made float32
  });
  expectVoxels(load(path("wide.h5"), "u8"),
               [](auto x, auto y, auto z) { return ramp(x, y, z) * 3; });
}

TEST_F(Hdf5Files, RegionsAreHyperslabsOfTheWhole) {
  const RegionSourceShape shape = hdf5Shape(path("two.h5"), "raw");
  EXPECT_EQ(shape.dims, (std::array<int64_t, 3>{7, 6, 5}));
  EXPECT_EQ(shape.spacing, glm::dvec3(0.25, 0.5, 2.0));
  const VoxelRegion box{{2, 1, 3}, {7, 5, 5}};
  const Volume part = loadHdf5Region(path("two.h5"), "raw", box);
  EXPECT_EQ(part.dims(), (std::array<int64_t, 3>{5, 4, 2}));
  EXPECT_EQ(part.origin(), glm::dvec3(0.5, 0.5, 6.0));
  expectVoxels(part, ramp, box.lo);
  expectVoxels(
      loadHdf5Region(path("two.h5"), "group/probability", box),
      [](auto x, auto y, auto z) { return ramp(x, y, z) * 0.125; }, box.lo);
  const std::string p = path("two.h5");
  expectLoadError(
      [&] {
        loadHdf5Region(p, "raw", VoxelRegion{{0, 0, 0}, {7, 6, 6}});
      },
      p, "region is empty or not inside the dataset's 7 x 6 x 5");
}

TEST_F(Hdf5Files, WrongNamesAndFilesFailInOneLine) {
  const std::string two = path("two.h5");
  expectVolumeLoadError(two,
                        "holds several 3D datasets; choose one with --dataset: "
                        "'/group/probability', '/raw'");
  expectLoadError([&] { load(two, "nothing"); }, two,
                  "has no dataset 'nothing' (3D datasets: '/group/probability', '/raw')");
  expectLoadError([&] { load(two, "no/such/group"); }, two, "has no dataset 'no/such/group'");
  expectLoadError([&] { load(two, "flat"); }, two, "dataset 'flat' has 2 dimensions");
  expectLoadError([&] { load(two, "group"); }, two, "group");
  expectLoadError([&] { load(path("wide.h5"), "complex"); }, path("wide.h5"),
                  "holds values that are not read");
  expectVolumeLoadError(path("none.h5"), "holds no 3D dataset");

  TempDir scratch;
  expectVolumeLoadError(scratch.write("text.h5", "just some text, not HDF5"), "not an HDF5 file");
  // The file cut short: its superblock is there, the data and object headers are not.
  const std::string whole = testing::fileBytes(two);
  const std::string cut = scratch.write("cut.h5", whole.substr(0, 1200));
  try {
    load(cut, "raw");
    ADD_FAILURE() << "a cut file loaded";
  } catch (const LoadError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(cut + ": ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace ewa
