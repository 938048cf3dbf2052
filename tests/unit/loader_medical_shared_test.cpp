// Loads the shared NIfTI, DICOM and SLC volumes and checks dims, spacing, type, range and where
// each checked voxel lands in world (LPS) space.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <string>

#include "core/volume_orientation.h"
#include "io/volume_loader.h"
#include "loader_test_files.h"
#include "medical_test_files.h"

// Expected values come from a python3 script that parsed the files with struct and zlib (DICOM
// element by element, NIfTI header by offset; positions from IPP/IOP/PixelSpacing and the
// sform turned from RAS to LPS), not from this code.

namespace ewa {
namespace {

// A voxel of the file, given by where it lies in world space and its value there.
struct WorldVoxel {
  glm::dvec3 lps;
  double value;
};

struct Expected {
  std::array<int64_t, 3> dims;
  ScalarType type;
  glm::dvec3 spacing;
  double min, max;
  std::vector<WorldVoxel> voxels;
  bool patientFrame = true;
};

std::string data(const std::string& relative) {
  return std::string(EWA_SHARED_DATA) + "/" + relative;
}

// The value of the voxel whose world position is `p` (it must be a voxel centre).
double valueAtWorld(const Volume& v, const glm::dvec3& p) {
  const glm::dvec3 ijk = (glm::transpose(v.direction()) * (p - v.origin())) / v.spacing();
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(ijk[a], std::round(ijk[a]), 1e-3) << "not a voxel centre on axis " << a;
    EXPECT_GE(std::round(ijk[a]), 0.0);
    EXPECT_LT(std::round(ijk[a]), double(v.dims()[size_t(a)]));
  }
  return v.value(int64_t(std::round(ijk.x)), int64_t(std::round(ijk.y)),
                 int64_t(std::round(ijk.z)));
}

void check(const Volume& v, const Expected& e) {
  EXPECT_EQ(v.dims(), e.dims);
  EXPECT_EQ(v.type(), e.type) << scalarName(v.type());
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(v.spacing()[a], e.spacing[a], 1e-5) << "axis " << a;
  const double tol = v.type() == ScalarType::Float32 ? 1e-6 * std::max(1.0, e.max) : 0.0;
  EXPECT_NEAR(v.minValue(), e.min, tol);
  EXPECT_NEAR(v.maxValue(), e.max, tol);
  EXPECT_EQ(v.patientFrame(), e.patientFrame);
  EXPECT_TRUE(isOrthonormal(v.direction(), 1e-9));
  EXPECT_GT(glm::determinant(v.direction()), 0.0);
  for (const WorldVoxel& w : e.voxels)
    EXPECT_NEAR(valueAtWorld(v, w.lps), w.value, tol)
        << w.lps.x << "," << w.lps.y << "," << w.lps.z;
}

class MedicalData : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::is_directory(EWA_SHARED_DATA))
      GTEST_SKIP() << "shared data folder " << EWA_SHARED_DATA << " is absent";
  }
};

TEST_F(MedicalData, NiftiAnatomicalBigEndianWithReflectedSform) {
  const Volume v = loadVolume(data("nifti/anatomical.nii"));
  check(v, {{33, 41, 25},
            ScalarType::Int16,
            glm::dvec3(2.0),
            -610,
            30393,
            {{{-32, 40, -16}, 10712},
             {{0, 0, 8}, 11881},
             {{32, 14, 32}, 9545},
             {{-30, -40, -16}, 3966}}});
}

TEST_F(MedicalData, Nifti4dObliqueFramesAndNifti2) {
  const Expected first{{128, 96, 24},
                       ScalarType::Int16,
                       {2.0, 2.0, 2.2},
                       0,
                       1162,
                       {{{10.1448974609375, -54.74887037277222, 34.318148612976074}, 265}}};
  const Volume v = loadVolume(data("nifti/example4d.nii.gz"));
  check(v, first);
  // The oblique sform: a tilt of about 9.3 degrees about x survives as the direction.
  EXPECT_NEAR(v.direction()[1].z, 0.3232076168060303 / 2.0, 1e-6);
  EXPECT_EQ(loadVolume(data("nifti/example4d.nii.gz"), {"", 1, 0, {}}).dims(), first.dims);
  EXPECT_NE(loadVolume(data("nifti/example4d.nii.gz"), {"", 1, 0, {}}).bytes(), v.bytes());
  testing::expectLoadError(
      [] {
        loadVolume(data("nifti/example4d.nii.gz"), {"", 2, 0, {}});
      },
      data("nifti/example4d.nii.gz"), "out of range (the file has 2 frames)");
  check(loadVolume(data("nifti/example_nifti2.nii.gz")),
        {{32, 20, 12},
         ScalarType::Int16,
         {2.0, 2.0, 2.2},
         49,
         742,
         {{{-117.8551025390625, 35.72294235229492, -7.248798370361328}, 424},
          {{-85.8551025390625, 18.1189968585968, 9.00976848602295}, 265},
          {{-55.8551025390625, 27.791483998298645, 18.572346925735474}, 553}}});
}

TEST_F(MedicalData, NiftiScaledFunctionalAndSformOnly) {
  const Volume f = loadVolume(data("nifti/functional.nii"));
  check(f, {{17, 21, 3},
            ScalarType::Float32,
            {4, 4, 8},
            762.5424365997314,
            5538.065757632256,
            {{{-32, 40, 0}, 4004.137202501297},
             {{0, 0, 8}, 3865.7654151320457},
             {{32, 12, 16}, 3669.9335176944733}}});
  check(loadVolume(data("nifti/standard.nii.gz")),
        {{4, 5, 7},
         ScalarType::UInt8,
         {1, 3, 2},
         0,
         255,
         {{{0, 0, 0}, 0}, {{-3, -3, 12}, 255}, {{-2, -6, 6}, 0}}});
}

TEST_F(MedicalData, DicomPetFolderAndAnyFileSortedByPosition) {
  const Expected e{{128, 128, 299},
                   ScalarType::Float32,
                   {3.5378182, 3.5378182, 3.375},
                   0.0,
                   66260.7617124,
                   {{{-226.13246, -425.88375, -1259.459}, 4.0444828},
                    {{0.2879047999999784, -199.46338520000003, -756.584}, 10669.3456264},
                    {{-13.863368000000008, -178.23647600000004, -651.959}, 6359.949203},
                    {{0.2879047999999784, -248.99284000000003, -921.959}, 4806.8678078}}};
  const Volume folder = loadVolume(data("dicom-pet"));
  check(folder, e);
  EXPECT_EQ(folder.origin(), glm::dvec3(-226.13246, -425.88375, -1259.459));
  const Volume one = loadVolume(data("dicom-pet/000123.dcm"));
  EXPECT_EQ(one.bytes(), folder.bytes());
  testing::expectLoadError(
      [] {
        loadVolume(data("dicom-pet"), {"1.2.3", 0, 0, {}});
      },
      data("dicom-pet"), "no series '1.2.3'");
}

// The PET series' files without their Part 10 header (bare implicit little-endian data sets,
// as ACR-NEMA files come): the same volume, placed by the same positions.
TEST_F(MedicalData, DicomPetAsBareDataSets) {
  testing::TempDir dir;
  std::filesystem::create_directories(dir.path("bare"));
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(data("dicom-pet"))) {
    const std::string bare = testing::bareDataSet(entry.path().string());
    ASSERT_FALSE(bare.empty()) << entry.path();
    dir.write("bare/" + entry.path().stem().string(), bare);
    ++files;
  }
  EXPECT_EQ(files, 299);
  const Volume part10 = loadVolume(data("dicom-pet"));
  const Volume bare = loadVolume(dir.path("bare"));
  EXPECT_EQ(bare.dims(), part10.dims());
  EXPECT_EQ(bare.spacing(), part10.spacing());
  EXPECT_EQ(bare.origin(), part10.origin());
  EXPECT_EQ(bare.bytes(), part10.bytes());
  EXPECT_EQ(bare.notes(), part10.notes());
}

TEST_F(MedicalData, DicomMrStackFromTheZip) {
  // Opened as it comes, and unpacked (by unzip, not our reader): the same volume.
  const Volume zipped = loadVolume(data("dicom-mr-stack/data.zip"));
  testing::TempDir dir;
  const std::string command = "unzip -q -o '" + data("dicom-mr-stack/data.zip") + "' -d '" +
                              dir.path("mr") + "' >/dev/null 2>&1";
  if (std::system(command.c_str()) != 0) GTEST_SKIP() << "unzip is not available";
  // Slices are 8 mm thick but 12 mm apart: the spacing comes from the positions. File 1-1 is the
  // top slice: the order is by position, not by name.
  check(loadVolume(dir.path("mr/data")),
        {{512, 512, 3},
         ScalarType::UInt16,
         {0.9765625, 0.9765625, 12.0},
         0,
         346,
         {{{-250, -250, -12}, 0},
          {{-250 + 261 * 0.9765625, -250 + 274 * 0.9765625, 12}, 346},
          {{-250 + 250 * 0.9765625, -250 + 300 * 0.9765625, 0}, 93},
          {{-250 + 250 * 0.9765625, -250 + 300 * 0.9765625, -12}, 96}}});
  const Volume unzipped = loadVolume(dir.path("mr/data"));
  ASSERT_EQ(zipped.dims(), unzipped.dims());
  EXPECT_EQ(zipped.spacing(), unzipped.spacing());
  EXPECT_EQ(zipped.origin(), unzipped.origin());
  for (int64_t n = 0; n < zipped.voxelCount(); ++n)
    ASSERT_EQ(zipped.valueAt(n), unzipped.valueAt(n)) << "voxel " << n;
}

TEST_F(MedicalData, NeghipSlc) {
  const Volume v = loadVolume(data("neghip/neghip.slc"));
  check(v, {{66, 66, 66},
            ScalarType::UInt8,
            glm::dvec3(1.0),
            0,
            255,
            {{{0, 0, 0}, 0}, {{10, 40, 20}, 20}, {{33, 33, 33}, 0}},
            false});
}

}  // namespace
}  // namespace ewa
