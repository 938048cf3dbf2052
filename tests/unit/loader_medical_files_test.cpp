// Hand-made NIfTI, DICOM, TIFF and SLC files: what good ones hold, and one-line errors for bad
// ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <glm/matrix.hpp>
#include <iterator>
#include <string>
#include <tuple>

#include "io/dicom_series.h"
#include "io/volume_loader.h"
#include "medical_test_files.h"

namespace ewa {
namespace {

using testing::allNotes;
using testing::dicomSeries;
using testing::expectLoadError;
using testing::expectVolumeLoadError;
using testing::fileBytes;
using testing::NiftiFields;
using testing::TempDir;

const std::string kVoxels24 = [] {
  std::string s;
  for (int i = 0; i < 24; ++i) s.push_back(char(i * 10));
  return s;
}();

TEST(NiftiFiles, BothByteOrdersPairsAndScaling) {
  TempDir dir;
  for (bool big : {false, true}) {
    const Volume v =
        loadVolume(dir.write(big ? "be.nii" : "le.nii", testing::niftiHeader({}, big) + kVoxels24));
    EXPECT_EQ(v.dims(), (std::array<int64_t, 3>{2, 3, 4}));
    EXPECT_EQ(v.type(), ScalarType::UInt8);
    EXPECT_EQ(v.value(1, 2, 3), 230);
    EXPECT_FALSE(v.patientFrame());
  }
  // int16 big-endian scaled by 0.5 + 1 becomes float32.
  NiftiFields f;
  f.datatype = 4;
  f.bitpix = 16;
  f.sclSlope = 0.5f;
  f.sclInter = 1.0f;
  std::vector<int16_t> values(24);
  for (int i = 0; i < 24; ++i) values[size_t(i)] = int16_t(i - 10);
  const Volume scaled = loadVolume(
      dir.write("s.nii", testing::niftiHeader(f, true) + testing::bytesOf(values, true)));
  EXPECT_EQ(scaled.type(), ScalarType::Float32);
  EXPECT_DOUBLE_EQ(scaled.value(0, 0, 0), -4.0);
  EXPECT_DOUBLE_EQ(scaled.maxValue(), 7.5);
  // A .hdr/.img pair, opened through either name; vox_offset counts in the .img.
  NiftiFields pair;
  pair.voxOffset = 0;
  std::string header = testing::niftiHeader(pair).substr(0, 348);
  header.replace(344, 4, std::string("ni1\0", 4));
  dir.write("pair.hdr", header);
  dir.write("pair.img", kVoxels24);
  EXPECT_EQ(loadVolume(dir.path("pair.hdr")).value(1, 0, 0), 10);
  EXPECT_EQ(loadVolume(dir.path("pair.img")).value(1, 0, 0), 10);
  // Gzip: the whole file compressed.
  const Volume gz =
      loadVolume(dir.write("g.nii.gz", testing::gzipBytes(testing::niftiHeader({}) + kVoxels24)));
  EXPECT_EQ(gz.value(1, 2, 3), 230);
}

TEST(NiftiFiles, AnalyzeHeadersWithoutTheMagicOpenWithTheirSpacing) {
  // NIfTI-1's ancestor: the same 348 bytes without "ni1", its vox_units at byte 56, and bytes
  // where NIfTI keeps qform_code, sform_code and scl_slope holding other things (here nonsense
  // a NIfTI reader would turn into a transform and a scale).
  TempDir dir;
  NiftiFields f;
  f.voxOffset = 0;
  f.pixdim = {0, 0.5f, 2.0f, 3.0f, 0, 0, 0, 0};
  f.qformCode = 1;
  f.sformCode = 2;
  f.sclSlope = 7.0f;
  f.srow = {0, 3, 0, 9, 2, 0, 0, 9, 0, 0, 1, 9};
  std::string header = testing::niftiHeader(f).substr(0, 348);
  header.replace(344, 4, std::string(4, '\0'));
  header.replace(56, 4, std::string("mm\0\0", 4));
  dir.write("old.hdr", header);
  dir.write("old.img", kVoxels24);
  const Volume v = loadVolume(dir.path("old.img"));
  EXPECT_EQ(v.value(1, 2, 3), 230);  // unscaled
  EXPECT_EQ(v.spacing(), glm::dvec3(0.5, 2.0, 3.0));
  EXPECT_EQ(v.origin(), glm::dvec3(0.0));
  EXPECT_EQ(v.direction(), glm::dmat3(1.0));
  EXPECT_FALSE(v.patientFrame());
  EXPECT_EQ(v.unit(), "mm");
  EXPECT_NE(testing::allNotes(v).find("Analyze 7.5 header"), std::string::npos);
  // A single .nii without the magic is still no NIfTI file.
  testing::expectVolumeLoadError(dir.write("bad.nii", header + kVoxels24), "bad NIfTI-1 magic");
}

TEST(NiftiFiles, TheSpatialUnitIsRead) {
  // xyzt_units' low three bits: none, metre, millimetre, micron; the time unit above them is not
  // a length.
  TempDir dir;
  const std::pair<uint8_t, std::string> cases[] = {
      {0, ""}, {1, "m"}, {2, "mm"}, {3, "\xC2\xB5m"}, {2 | 8, "mm"}, {3 | 16, "\xC2\xB5m"}};
  for (const auto& [code, unit] : cases) {
    NiftiFields f;
    f.xyztUnits = code;
    const Volume v = loadVolume(
        dir.write("u" + std::to_string(code) + ".nii", testing::niftiHeader(f) + kVoxels24));
    EXPECT_EQ(v.unit(), unit) << int(code);
  }
}

TEST(NiftiFiles, QformRotationAndReflection) {
  TempDir dir;
  // qform: quaternion (b,c,d) = (0,0,1): 180 degrees about z, so RAS x,y negate: LPS identity.
  NiftiFields f;
  f.qformCode = 1;
  f.pixdim = {1, 2, 3, 4, 0, 0, 0, 0};
  std::string h = testing::niftiHeader(f);
  uint32_t one;
  const float oneF = 1.0f;
  std::memcpy(&one, &oneF, 4);
  h.replace(264, 4, testing::uintBytes(one, 4));  // quatern_d
  const Volume v = loadVolume(dir.write("q.nii", h + kVoxels24));
  EXPECT_TRUE(v.patientFrame());
  EXPECT_NEAR(glm::determinant(v.direction() - glm::dmat3(1.0)), 0.0, 1e-12);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(v.direction()[a][a], 1.0, 1e-6);
  EXPECT_EQ(v.spacing(), glm::dvec3(2, 3, 4));
  // qfac -1 reflects the third axis: the loader reverses the slices, keeping world positions.
  f.pixdim[0] = -1;
  std::string hr = testing::niftiHeader(f);
  hr.replace(264, 4, testing::uintBytes(one, 4));
  const Volume r = loadVolume(dir.write("r.nii", hr + kVoxels24));
  EXPECT_GT(glm::determinant(r.direction()), 0.0);
  // File voxel (1,2,0) (value 50) sits at RAS (1*2, 2*3, -0*4) rotated: LPS (2, 6, 0).
  const glm::dvec3 ijk =
      glm::transpose(r.direction()) * (glm::dvec3(2, 6, 0) - r.origin()) / r.spacing();
  EXPECT_EQ(r.value(int64_t(std::lround(ijk.x)), int64_t(std::lround(ijk.y)),
                    int64_t(std::lround(ijk.z))),
            50);
}

TEST(NiftiFiles, BadFilesFailWithOneLine) {
  TempDir dir;
  const std::string good = testing::niftiHeader({});
  expectVolumeLoadError(dir.write("trunc.nii", good + kVoxels24.substr(0, 20)), "truncated");
  NiftiFields far;
  far.voxOffset = 4096;
  expectVolumeLoadError(dir.write("far.nii", testing::niftiHeader(far) + kVoxels24),
                        "beyond the end of the file");
  NiftiFields huge;
  huge.dim = {3, 32767, 32767, 32767, 1, 1, 1, 1};
  huge.datatype = 64;
  huge.bitpix = 64;
  expectVolumeLoadError(dir.write("huge.nii", testing::niftiHeader(huge) + kVoxels24), "memory");
  NiftiFields five;
  five.dim = {5, 2, 3, 4, 1, 2, 1, 1};
  expectVolumeLoadError(dir.write("five.nii", testing::niftiHeader(five) + kVoxels24),
                        "5D NIfTI data");
  NiftiFields negative;
  negative.dim = {3, 2, -3, 4, 1, 1, 1, 1};
  expectVolumeLoadError(dir.write("neg.nii", testing::niftiHeader(negative) + kVoxels24),
                        "not positive");
  NiftiFields complex;
  complex.datatype = 32;
  expectVolumeLoadError(dir.write("c.nii", testing::niftiHeader(complex) + kVoxels24),
                        "unsupported NIfTI datatype 32");
  expectVolumeLoadError(dir.write("magic.nii", good.substr(0, 344) + "xyz" + good.substr(347)),
                        "magic");
  expectVolumeLoadError(dir.write("size.nii", "garbage that is no header"), "not a NIfTI file");
  expectVolumeLoadError(dir.write("short.nii", good.substr(0, 100)), "truncated");
  expectVolumeLoadError(dir.write("gz.nii.gz", testing::gzipBytes(good + kVoxels24).substr(0, 40)),
                        "NIfTI header is truncated");
  expectVolumeLoadError(dir.write("gzt.nii.gz", testing::gzipBytes(good + kVoxels24.substr(0, 5))),
                        "truncated");
  expectLoadError(
      [&] {
        loadVolume(dir.path("trunc.nii"), {"", 3, 0, {}});
      },
      dir.path("trunc.nii"), "--frame 3 is out of range");
}

TEST(Directions, NrrdSpaceDirectionsAndMetaImageTransformMatrix) {
  TempDir dir;
  // RAS directions and origin become LPS: x and y change sign.
  const Volume n = loadVolume(
      dir.write("ras.nrrd",
                "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 3 4\nencoding: raw\n"
                "space: right-anterior-superior\nspace directions: (0,2,0) (-1,0,0) (0,0,3)\n"
                "space origin: (10,20,30)\n\n" +
                    kVoxels24));
  EXPECT_TRUE(n.patientFrame());
  EXPECT_EQ(n.spacing(), glm::dvec3(2, 1, 3));
  EXPECT_EQ(n.origin(), glm::dvec3(-10, -20, 30));
  EXPECT_EQ(n.direction(),
            glm::dmat3(glm::dvec3(0, -1, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1)));
  // MetaImage lists each axis's direction in turn.
  const Volume m = loadVolume(
      dir.write("m.mha",
                "ObjectType = Image\nNDims = 3\nDimSize = 2 3 4\nElementType = MET_UCHAR\n"
                "TransformMatrix = 0 1 0 -1 0 0 0 0 1\nAnatomicalOrientation = RAI\n"
                "ElementDataFile = LOCAL\n" +
                    kVoxels24));
  EXPECT_TRUE(m.patientFrame());
  EXPECT_EQ(m.direction(),
            glm::dmat3(glm::dvec3(0, 1, 0), glm::dvec3(-1, 0, 0), glm::dvec3(0, 0, 1)));
  // No space field: directions kept, no patient frame.
  const Volume plain =
      loadVolume(dir.write("p.nrrd",
                           "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 3 4\nencoding: raw\n"
                           "space directions: (0,1,0) (-1,0,0) (0,0,1)\n\n" +
                               kVoxels24));
  EXPECT_FALSE(plain.patientFrame());
  EXPECT_EQ(plain.direction()[0], glm::dvec3(0, 1, 0));
}

TEST(DicomFiles, SeriesSortedByPositionWithRescale) {
  TempDir dir;
  testing::DicomSliceSpec spec;
  spec.slope = 2.0;
  spec.intercept = -5.0;
  const std::string folder = dicomSeries(dir, "s", 5, spec);
  const Volume v = loadVolume(folder);
  EXPECT_EQ(v.dims(), (std::array<int64_t, 3>{5, 4, 5}));
  EXPECT_EQ(v.spacing(), glm::dvec3(0.75, 0.5, 2.0));
  EXPECT_EQ(v.origin(), glm::dvec3(10, 20, 0));
  EXPECT_EQ(v.type(), ScalarType::Int16);  // integral rescale that fits
  // Slice k has z = 2k and raw values i + 10 j + 100 z.
  EXPECT_DOUBLE_EQ(v.value(3, 2, 4), 2.0 * (3 + 20 + 800) - 5.0);
  EXPECT_TRUE(v.patientFrame());
  EXPECT_EQ(v.unit(), "mm");  // DICOM's lengths are millimetres
  EXPECT_EQ(loadVolume(folder + "/im3.dcm").bytes(), v.bytes());
}

TEST(DicomFiles, CompressedSlicesLoadLikeTheOthers) {
  TempDir dir;
  const std::string folder = dicomSeries(dir, "c", 4);
  const Volume plain = loadVolume(folder);
  ASSERT_TRUE(testing::recompressDicom(folder + "/im1.dcm", gdcm::TransferSyntax::RLELossless));
  ASSERT_TRUE(
      testing::recompressDicom(folder + "/im2.dcm", gdcm::TransferSyntax::JPEGLosslessProcess14_1));
  // The files really changed (encapsulated now), and the volume did not.
  EXPECT_NE(std::filesystem::file_size(folder + "/im1.dcm"),
            std::filesystem::file_size(folder + "/im0.dcm"));
  EXPECT_EQ(loadVolume(folder).bytes(), plain.bytes());
}

// One 16 x 16 slice of a series in `syntax`: its path.
std::string compressedSlice(TempDir& dir, const std::string& name,
                            gdcm::TransferSyntax::TSType syntax) {
  testing::DicomSliceSpec spec;
  spec.rows = spec.columns = 16;
  const std::string file = dicomSeries(dir, name, 1, spec) + "/im0.dcm";
  EXPECT_TRUE(testing::recompressDicom(file, syntax));
  return file;
}

// Writes `bytes` to `path` with the byte `offset` after the first `pattern` set to `value`.
void writePatched(const std::string& path, std::string bytes, const std::string& pattern,
                  size_t offset, char value) {
  const auto at = std::search(bytes.begin(), bytes.end(), pattern.begin(), pattern.end());
  ASSERT_NE(at, bytes.end()) << "pattern not in " << path;
  *(at + long(offset)) = value;
  std::ofstream(path, std::ios::binary) << bytes;
}

TEST(DicomFiles, JpegHeadersGdcmAbortsOnAreRefusedInOneLine) {
  // A lossless JPEG slice whose frame header says 3 bits: GDCM 3.0's codec asserts (aborts the
  // program) on it, so it is refused before GDCM reads the file; at 12 bits it loads.
  TempDir dir;
  const std::string file = compressedSlice(dir, "p", gdcm::TransferSyntax::JPEGLosslessProcess14_1);
  const std::string good = fileBytes(file);
  writePatched(file, good, "\xFF\xC3", 4, 12);  // SOF3's precision
  EXPECT_EQ(loadVolume(file).dims(), (std::array<int64_t, 3>{16, 16, 1}));
  writePatched(file, good, "\xFF\xC3", 4, 3);
  expectLoadError([&] { loadVolume(file); }, file,
                  "im0.dcm: corrupt or truncated DICOM data: the JPEG header of a pixel data "
                  "fragment: precision of 3 bits");
}

TEST(DicomFiles, EncapsulatedPixelDataIsCheckedBeforeGdcmReadsIt) {
  // A JPEG 2000 slice: its codestream's image size must be the header's (GDCM with OpenJPEG
  // crashed on a wider one), the delimiter ending its fragments must claim no bytes (GDCM
  // allocated the 4 GiB one claimed), and only sequences, UN and pixel data may have an
  // undefined length (GDCM asserts on the others). Found by fuzzing; refused in one line.
  TempDir dir;
  const std::string file = compressedSlice(dir, "j", gdcm::TransferSyntax::JPEG2000Lossless);
  EXPECT_EQ(loadVolume(file).dims(), (std::array<int64_t, 3>{16, 16, 1}));
  const std::string good = fileBytes(file);
  const std::string delimiter("\xFE\xFF\xDD\xE0", 4);
  ASSERT_EQ(good.substr(good.size() - 8, 4), delimiter);
  writePatched(file, good, delimiter + std::string(2, '\0'), 6, char(0xFF));
  expectLoadError([&] { loadVolume(file); }, file, "a delimiter of length 16711680");
  writePatched(file, good, "\xFF\x4F\xFF\x51", 11, 41);  // SIZ's Xsiz: 41 columns
  expectLoadError([&] { loadVolume(file); }, file,
                  "the JPEG 2000 header of a pixel data fragment: image of 41 x 16 (the header "
                  "says 16 x 16)");
  writePatched(file, good, std::string("\xE0\x7F\x10\x00OB", 6), 2, 0x11);  // (7FE0,0011)
  expectLoadError([&] { loadVolume(file); }, file, "an undefined length for VR OB");
}

TEST(DicomFiles, RescaleValuesGdcmAssertsOnAreRefused) {
  // GDCM's rescale helper asserts when it reads a slope of 0 (found by fuzzing with an
  // intercept of "S0"): a slope of 0 and values that are not one number are refused in one line.
  TempDir dir;
  testing::DicomSliceSpec spec;
  const std::pair<uint16_t, std::string> cases[] = {
      {0x1053, "0"}, {0x1052, "S0"}, {0x1053, "1\\2"}, {0x1052, "nan"}};
  int n = 0;
  for (const auto& [element, text] : cases) {
    const std::string file = dicomSeries(dir, "r" + std::to_string(n++), 1, spec) + "/im0.dcm";
    ASSERT_TRUE(testing::editDicom(file, [&](gdcm::DataSet& ds) {
      gdcm::DataElement de(gdcm::Tag(0x0028, element));
      de.SetVR(gdcm::VR::DS);
      const std::string padded = text.size() % 2 ? text + " " : text;
      de.SetByteValue(padded.data(), uint32_t(padded.size()));
      ds.Replace(de);
    }));
    expectLoadError([&] { loadVolume(file); }, file,
                    element == 0x1053 ? "bad RescaleSlope (one number, not 0)"
                                      : "bad RescaleIntercept (one number)");
  }
}

TEST(DicomFiles, PixelModuleElementsOfTheWrongVrAreRefused) {
  // Columns written as SS instead of US: GDCM's typed attribute asserts on it (found by
  // fuzzing), so the walk refuses group 0028 elements whose VR the dictionary does not allow.
  TempDir dir;
  testing::DicomSliceSpec spec;
  const std::string file = dicomSeries(dir, "vr", 1, spec) + "/im0.dcm";
  ASSERT_TRUE(testing::recompressDicom(file, gdcm::TransferSyntax::ExplicitVRLittleEndian));
  const std::string good = fileBytes(file);
  const std::string columns("\x28\x00\x11\x00US", 6);
  writePatched(file, good, columns, 4, 'S');  // "SS"
  expectLoadError([&] { loadVolume(file); }, file, "element (0028,0011) of VR SS");
  writePatched(file, good, columns, 0, 0x28);  // unchanged: loads
  EXPECT_EQ(loadVolume(file).dims()[0], 5);
}

// A tilted gantry: the slices step obliquely (half a millimetre along y for every 2 along z), so
// a rod standing straight along z in the patient crosses each slice one row lower than the one
// before. Resampled within each slice onto an upright grid, it stands in one column of voxels.
TEST(DicomFiles, GantryTiltIsResampledAndSeveralSeriesAreListed) {
  TempDir dir;
  testing::DicomSliceSpec spec;
  std::filesystem::create_directories(dir.path("tilt"));
  for (int n = 0; n < 4; ++n) {
    spec.position = {0.0, 0.5 * n, 2.0 * n};  // slices step obliquely
    spec.values.assign(spec.rows * spec.columns, 0);
    spec.values[size_t(3 - n) * spec.columns + 2] = 100;  // the rod at y = 1.5: row 3 - n
    ASSERT_TRUE(testing::writeDicomSlice(dir.path("tilt/" + std::to_string(n) + ".dcm"), spec));
  }
  spec.seriesUid = "1.2.826.0.1.3680043.2.1125.2";
  for (int n = 0; n < 2; ++n) {
    spec.position = {0.0, 0.0, 3.0 * n};
    ASSERT_TRUE(
        testing::writeDicomSlice(dir.path("tilt/other" + std::to_string(n) + ".dcm"), spec));
  }
  const Volume v = loadVolume(dir.path("tilt"));
  // Rows from y = 0 to 3 (0.5 apart), the slices 2 apart along the normal, not 2.06 along the
  // oblique step; the direction is the patient's axes.
  EXPECT_EQ(v.dims(), (std::array<int64_t, 3>{5, 7, 4}));
  EXPECT_DOUBLE_EQ(v.spacing().z, 2.0);
  EXPECT_EQ(v.direction(), glm::dmat3(1.0));
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 7; ++j) EXPECT_EQ(v.value(2, j, k), j == 3 ? 100.0 : 0.0) << j << k;
  const std::string notes = allNotes(v);
  EXPECT_NE(notes.find("the grid is sheared 14.0 degrees (gantry tilt or skewed axes): "
                       "resampled within each slice onto 5 x 7 x 4 upright voxels"),
            std::string::npos)
      << notes;
  EXPECT_EQ(notes.find("warning:"), std::string::npos) << notes;
  EXPECT_NE(notes.find("series 1.2.826.0.1.3680043.2.1125.2: 2 slices"), std::string::npos)
      << notes;
  const Volume other = loadVolume(dir.path("tilt"), {"1.2.826.0.1.3680043.2.1125.2", 0, 0, {}});
  EXPECT_EQ(other.dims()[2], 2);
  EXPECT_DOUBLE_EQ(other.spacing().z, 3.0);
}

// A CD's tree: a DICOMDIR and no image at the top, the series in folders below. The folder (or
// its DICOMDIR) opens the largest series, the notes say where each lies; a folder with images of
// its own keeps to them; images deeper than kDicomMaxDepth levels are not looked for.
TEST(DicomFiles, SeriesInFoldersBelowAFolderWithoutImages) {
  TempDir dir;
  const std::string cd = dir.path("cd");
  const std::string first = dicomSeries(dir, "cd/PAT1/STU1/SER1", 5);
  testing::DicomSliceSpec other;
  other.seriesUid = "1.2.826.0.1.3680043.2.1125.7";
  dicomSeries(dir, "cd/PAT1/STU1/SER2", 2, other);
  dir.write("cd/README.TXT", "a CD");
  // The DICOMDIR: a DICOM file (the Part 10 preamble) that is no image.
  ASSERT_TRUE(testing::editDicom(
      first + "/im0.dcm",
      [](gdcm::DataSet& ds) {
        for (const gdcm::Tag& tag :
             {gdcm::Tag(0x0028, 0x0010), gdcm::Tag(0x0028, 0x0011), gdcm::Tag(0x7fe0, 0x0010)})
          ds.Remove(tag);
      },
      cd + "/DICOMDIR"));
  const Volume v = loadVolume(cd);
  EXPECT_EQ(v.dims(), (std::array<int64_t, 3>{5, 4, 5}));
  EXPECT_EQ(v.bytes(), loadVolume(first).bytes());
  const std::string notes = allNotes(v);
  EXPECT_NE(notes.find("series 1.2.826.0.1.3680043.2.1125.7: 2 slices in 'PAT1/STU1/SER2' "
                       "(--series UID opens it)"),
            std::string::npos)
      << notes;
  EXPECT_NE(notes.find("5 slices in 'PAT1/STU1/SER1' (open)"), std::string::npos) << notes;
  EXPECT_EQ(loadVolume(cd + "/DICOMDIR").bytes(), v.bytes());
  EXPECT_EQ(loadVolume(cd, {other.seriesUid, 0, 0, {}}).dims()[2], 2);
  // Images of its own: the folder's, not those below.
  const std::string own = dicomSeries(dir, "own", 3);
  dicomSeries(dir, "own/sub", 6);
  EXPECT_EQ(loadVolume(own).dims()[2], 3);
  // Nine levels down: out of reach.
  std::string deep = "deep";
  for (int level = 0; level < kDicomMaxDepth + 1; ++level) deep += "/d" + std::to_string(level);
  dicomSeries(dir, deep, 2);
  expectVolumeLoadError(dir.path("deep"), "no DICOM image or TIFF file, in it or below it");
}

// An enhanced multi-frame file: its frames stacked by the positions its functional groups give
// (stored out of order here), spacing, orientation and rescale from the shared groups. Frames at
// one place (a time series) and groups that do not cover every frame keep the file whole.
TEST(DicomFiles, EnhancedMultiFrameFilesTakeTheirFramesGeometry) {
  TempDir dir;
  testing::EnhancedDicomSpec spec;
  spec.frameZ = {4.0, 0.0, 6.0, 2.0};
  ASSERT_TRUE(testing::writeEnhancedDicom(dir.path("enhanced.dcm"), spec));
  const Volume v = loadVolume(dir.path("enhanced.dcm"));
  EXPECT_EQ(v.dims(), (std::array<int64_t, 3>{5, 4, 4}));
  EXPECT_EQ(v.spacing(), glm::dvec3(0.75, 0.5, 2.0));
  EXPECT_EQ(v.origin(), glm::dvec3(10, 20, 0));
  EXPECT_TRUE(v.patientFrame());
  for (int k = 0; k < 4; ++k) EXPECT_EQ(v.value(3, 2, k), 3 + 20 + 200 * k) << "slice " << k;
  EXPECT_TRUE(v.notes().empty()) << v.notes().front();
  // Rescaled by the shared groups' Pixel Value Transformation.
  spec.slope = 2.0;
  spec.intercept = -5.0;
  ASSERT_TRUE(testing::writeEnhancedDicom(dir.path("rescaled.dcm"), spec));
  const Volume rescaled = loadVolume(dir.path("rescaled.dcm"));
  EXPECT_EQ(rescaled.value(3, 2, 1), 2.0 * (3 + 20 + 200) - 5.0);
  spec.slope = 1.0;
  spec.intercept = 0.0;
  // A time series: four frames at z = 2.
  spec.frameZ = {2.0, 2.0, 2.0, 2.0};
  ASSERT_TRUE(testing::writeEnhancedDicom(dir.path("time.dcm"), spec));
  const Volume time = loadVolume(dir.path("time.dcm"));
  EXPECT_EQ(time.dims()[2], 4);
  EXPECT_EQ(time.spacing().z, 1.0);
  std::string notes = allNotes(time);
  EXPECT_NE(notes.find("frames kept in stored order, not a stack of slices: two slices share one "
                       "position"),
            std::string::npos)
      << notes;
  // Positions for two of three frames.
  spec.frameZ = {0.0, 2.0, 4.0};
  spec.perFrameItems = 2;
  ASSERT_TRUE(testing::writeEnhancedDicom(dir.path("partial.dcm"), spec));
  const Volume partial = loadVolume(dir.path("partial.dcm"));
  EXPECT_EQ(partial.dims()[2], 3);
  EXPECT_EQ(partial.value(0, 0, 2), 400);  // stored order
  notes = allNotes(partial);
  EXPECT_NE(notes.find("multi-frame file: slice spacing 1 assumed"), std::string::npos) << notes;
}

// One SeriesInstanceUID holding several volumes: a stack, a localizer's slices in another
// orientation, an image of another size; or two multi-frame files. Each opens as a series of its
// own, the largest under the UID, the others as UID#2, UID#3, named in the notes.
TEST(DicomFiles, SeriesMixingSizesOrientationsAndMultiFrameFilesAreSplit) {
  TempDir dir;
  const std::string uid = "1.2.826.0.1.3680043.2.1125.1";
  const std::string mixed = dicomSeries(dir, "mixed", 3);
  testing::DicomSliceSpec big;
  big.rows = 6;
  big.position = {10, 20, 10};
  ASSERT_TRUE(testing::writeDicomSlice(mixed + "/big.dcm", big));
  testing::DicomSliceSpec coronal;
  coronal.orientation = {1, 0, 0, 0, 0, -1};
  for (int n = 0; n < 2; ++n) {
    coronal.position = {10.0, 3.0 * n, 40.0};
    ASSERT_TRUE(testing::writeDicomSlice(mixed + "/loc" + std::to_string(n) + ".dcm", coronal));
  }
  const Volume stack = loadVolume(mixed);
  EXPECT_EQ(stack.dims(), (std::array<int64_t, 3>{5, 4, 3}));
  std::string notes = allNotes(stack);
  for (const std::string& line :
       {"series " + uid + ": 3 slices (open)",
        "series " + uid + "#2: 2 slices (part of " + uid +
            ": another orientation) (--series UID opens it)",
        "series " + uid + "#3: 1 slice (part of " + uid + ": 5 x 6) (--series UID opens it)"})
    EXPECT_NE(notes.find(line + "\n"), std::string::npos) << line << "\n" << notes;
  // The same as choices for the window's list: the --series argument, a label, the open one.
  const std::vector<SeriesChoice>& choices = stack.seriesChoices();
  ASSERT_EQ(choices.size(), 3u);
  EXPECT_EQ(choices[0].id, uid);
  EXPECT_EQ(choices[0].label, "3 slices");
  EXPECT_TRUE(choices[0].open);
  EXPECT_EQ(choices[2].id, uid + "#3");
  EXPECT_EQ(choices[2].label, "1 slice (part of " + uid + ": 5 x 6)");
  EXPECT_FALSE(choices[2].open);
  EXPECT_TRUE(loadVolume(mixed + "/big.dcm").seriesChoices()[2].open);
  // The file named opens its own part; --series opens any.
  const Volume one = loadVolume(mixed + "/big.dcm");
  EXPECT_EQ(one.dims(), (std::array<int64_t, 3>{5, 6, 1}));
  EXPECT_NE(allNotes(one).find(uid + "#3: 1 slice (part of " + uid + ": 5 x 6) (open)"),
            std::string::npos)
      << allNotes(one);
  const Volume localizer = loadVolume(mixed, {uid + "#2", 0, 0, {}});
  EXPECT_EQ(localizer.dims(), (std::array<int64_t, 3>{5, 4, 2}));
  EXPECT_EQ(localizer.direction()[1], glm::dvec3(0, 0, -1));
  expectLoadError(
      [&] {
        loadVolume(mixed, {uid + "#4", 0, 0, {}});
      },
      mixed, "no series '" + uid + "#4' here");

  // Two multi-frame files of one series: each a volume.
  testing::EnhancedDicomSpec spec;
  std::filesystem::create_directories(dir.path("frames"));
  for (const char* name : {"a.dcm", "b.dcm"}) {
    const std::string file = dir.path(std::string("frames/") + name);
    ASSERT_TRUE(testing::writeEnhancedDicom(file, spec));
    ASSERT_TRUE(testing::editDicom(file, [&](gdcm::DataSet& ds) {
      gdcm::Attribute<0x0020, 0x000e> series;
      series.SetValue(uid);
      ds.Replace(series.GetAsDataElement());
    }));
    spec.frameZ = {0.0, 2.0, 4.0};
  }
  const Volume b = loadVolume(dir.path("frames/b.dcm"));
  EXPECT_EQ(b.dims()[2], 3);
  notes = allNotes(b);
  EXPECT_NE(notes.find("series " + uid + "#2: 3 frames (part of " + uid +
                       ": another multi-frame file) (open)"),
            std::string::npos)
      << notes;
  EXPECT_EQ(loadVolume(dir.path("frames")).dims()[2], 2);
}

// A diffusion or multi-echo series: three volumes at the same four positions, InstanceNumbers
// slice by slice (file names against that order), volume v's values 1000 v + 10 z. --frame
// picks one; with files missing, the numbers still tell the volumes apart. An enhanced file of
// two volumes too.
TEST(DicomFiles, SeveralVolumesAtTheSamePositionsOpenOneByOne) {
  TempDir dir;
  std::filesystem::create_directories(dir.path("dwi"));
  testing::DicomSliceSpec spec;
  for (int z = 0; z < 4; ++z)
    for (int v = 0; v < 3; ++v) {
      spec.position = {0.0, 0.0, 2.0 * z};
      // One file's cosines off by rounding (within the 1e-3 a series allows).
      spec.orientation = {1, z == 1 && v == 1 ? 0.0005 : 0.0, 0, 0, 1, 0};
      spec.values.assign(spec.rows * spec.columns, int16_t(1000 * v + 10 * z));
      const std::string file = dir.path("dwi/f" + std::to_string(11 - (3 * z + v)) + ".dcm");
      ASSERT_TRUE(testing::writeDicomSlice(file, spec));
      ASSERT_TRUE(testing::editDicom(file, [&](gdcm::DataSet& ds) {
        gdcm::Attribute<0x0020, 0x0013> instance;
        instance.SetValue(3 * z + v + 1);
        ds.Replace(instance.GetAsDataElement());
      }));
    }
  const Volume first = loadVolume(dir.path("dwi"));
  EXPECT_EQ(first.dims(), (std::array<int64_t, 3>{5, 4, 4}));
  EXPECT_DOUBLE_EQ(first.spacing().z, 2.0);
  for (int z = 0; z < 4; ++z) EXPECT_EQ(first.value(0, 0, z), 10 * z) << z;
  EXPECT_NE(allNotes(first).find("3 volumes at the same 4 positions (diffusion directions, "
                                 "echoes or time points): volume 0 open (--frame N opens "
                                 "another, 0 to 2)"),
            std::string::npos)
      << allNotes(first);
  const Volume third = loadVolume(dir.path("dwi/f5.dcm"), {"", 2, 0, {}});
  for (int z = 0; z < 4; ++z) EXPECT_EQ(third.value(1, 1, z), 2000 + 10 * z) << z;
  expectLoadError(
      [&] {
        loadVolume(dir.path("dwi"), {"", 3, 0, {}});
      },
      dir.path("dwi"), "--frame 3 is out of range (the series has 3 volumes at its positions)");
  const std::string plain = dicomSeries(dir, "plain", 3);
  expectLoadError(
      [&] {
        loadVolume(plain, {"", 1, 0, {}});
      },
      plain, "--frame 1 is out of range (the series has 1 volume at its positions)");
  // The last file missing (instance 12: volume 2 at 6 mm): positions hold 2 to 3 slices, and
  // the numbers, a block of three at each position, still tell the volumes apart.
  std::filesystem::remove(dir.path("dwi/f0.dcm"));
  EXPECT_NE(allNotes(loadVolume(dir.path("dwi"))).find("with the positions each holds: 2 (3)"),
            std::string::npos);
  const Volume cut = loadVolume(dir.path("dwi"), {"", 2, 0, {}});
  ASSERT_EQ(cut.dims()[2], 3);
  for (int z = 0; z < 3; ++z) EXPECT_EQ(cut.value(1, 1, z), 2000 + 10 * z) << z;
  // And one inside (instance 5: volume 1 at 2 mm), filled in between its neighbours.
  std::filesystem::remove(dir.path("dwi/f7.dcm"));
  const Volume holed = loadVolume(dir.path("dwi"), {"", 1, 0, {}});
  ASSERT_EQ(holed.dims()[2], 4);
  for (int z = 0; z < 4; ++z) EXPECT_EQ(holed.value(1, 1, z), 1000 + 10 * z) << z;
  EXPECT_NE(allNotes(holed).find("warning: 1 missing slice"), std::string::npos) << allNotes(holed);

  testing::EnhancedDicomSpec enhanced;
  enhanced.frameZ = {0.0, 2.0, 4.0, 0.0, 2.0, 4.0};
  ASSERT_TRUE(testing::writeEnhancedDicom(dir.path("two.dcm"), enhanced));
  const Volume second = loadVolume(dir.path("two.dcm"), {"", 1, 0, {}});
  EXPECT_EQ(second.dims()[2], 3);
  EXPECT_DOUBLE_EQ(second.spacing().z, 2.0);
  EXPECT_NE(allNotes(second).find("2 volumes at the same 3 positions"), std::string::npos)
      << allNotes(second);
}

// A cine: four images at one position, coronal, InstanceNumbers against the file names. They
// stack in InstanceNumber order, 1 apart along the slice normal, with a note.
TEST(DicomFiles, ImagesAtOnePositionStackAsACine) {
  TempDir dir;
  std::filesystem::create_directories(dir.path("cine"));
  testing::DicomSliceSpec spec;
  spec.orientation = {1, 0, 0, 0, 0, -1};
  spec.position = {5.0, 7.0, 9.0};
  for (int t = 0; t < 4; ++t) {
    spec.values.assign(spec.rows * spec.columns, int16_t(10 * t));
    const std::string file = dir.path("cine/im" + std::to_string(3 - t) + ".dcm");
    ASSERT_TRUE(testing::writeDicomSlice(file, spec));
    ASSERT_TRUE(testing::editDicom(file, [&](gdcm::DataSet& ds) {
      gdcm::Attribute<0x0020, 0x0013> instance;
      instance.SetValue(t + 1);
      ds.Replace(instance.GetAsDataElement());
    }));
  }
  const Volume v = loadVolume(dir.path("cine"));
  ASSERT_EQ(v.dims()[2], 4);
  for (int t = 0; t < 4; ++t) EXPECT_EQ(v.value(1, 1, t), 10 * t) << t;
  EXPECT_DOUBLE_EQ(v.spacing().z, 1.0);
  EXPECT_EQ(v.direction()[2], glm::dvec3(0, 1, 0));  // row x column: (1,0,0) x (0,0,-1)
  EXPECT_NE(allNotes(v).find("4 images at one position (a cine or a time series): stacked in "
                             "InstanceNumber order, 1 apart"),
            std::string::npos)
      << allNotes(v);
}

TEST(DicomFiles, BadSeriesFailWithOneLine) {
  TempDir dir;
  std::filesystem::create_directories(dir.path("empty"));
  dir.write("empty/notes.txt", "no images here");
  expectVolumeLoadError(dir.path("empty"), "no DICOM image");
  // Two images at one place (not copies of one: another SOPInstanceUID).
  const std::string twice = dicomSeries(dir, "twice", 3);
  ASSERT_TRUE(testing::editDicom(
      twice + "/im0.dcm",
      [](gdcm::DataSet& ds) {
        gdcm::Attribute<0x0008, 0x0018> uid;
        uid.SetValue("1.2.826.0.1.3680043.2.1125.77");
        ds.Replace(uid.GetAsDataElement());
      },
      twice + "/other.dcm"));
  expectVolumeLoadError(twice, "share one position");
  // Truncated pixel data in the file named (a folder skips it: below).
  const std::string cut = dicomSeries(dir, "cut", 3);
  std::filesystem::resize_file(cut + "/im1.dcm", std::filesystem::file_size(cut + "/im1.dcm") - 9);
  expectLoadError([&] { loadVolume(cut + "/im1.dcm"); }, cut + "/im1.dcm",
                  "corrupt or truncated DICOM data");
  // Rows and Columns that claim far more pixels than the file holds: refused before any buffer.
  const std::string liar = dicomSeries(dir, "liar", 1);
  ASSERT_TRUE(testing::editDicom(liar + "/im0.dcm", [](gdcm::DataSet& ds) {
    gdcm::Attribute<0x0028, 0x0010> rows{40000};
    gdcm::Attribute<0x0028, 0x0011> columns{40000};
    ds.Replace(rows.GetAsDataElement());
    ds.Replace(columns.GetAsDataElement());
  }));
  expectLoadError([&] { loadVolume(liar); }, liar, "cannot hold a 40000 x 40000 image");
  // A file that is not DICOM but says .dcm.
  expectVolumeLoadError(dir.write("fake.dcm", std::string(200, 'x')), "not a DICOM file");
}

// A broken file beside a series (an interrupted copy, a truncated download) does not stop the
// series from opening: it is left out with a warning naming it, as viewers do.
TEST(DicomFiles, CorruptFilesBesideASeriesAreSkippedWithAWarning) {
  TempDir dir;
  const auto cutCopy = [](const std::string& from, const std::string& to, uintmax_t keep) {
    std::filesystem::copy_file(from, to);
    std::filesystem::resize_file(to, keep);
  };
  const auto noteWith = [](const Volume& v, const std::string& text) {
    return std::count_if(v.notes().begin(), v.notes().end(), [&](const std::string& n) {
      return n.rfind("warning: ", 0) == 0 && n.find(text) != std::string::npos;
    });
  };
  // A cut short copy of a slice: the series is whole without it.
  const std::string series = dicomSeries(dir, "copy", 5);
  const Volume whole = loadVolume(series);
  const uintmax_t size = std::filesystem::file_size(series + "/im2.dcm");
  cutCopy(series + "/im2.dcm", series + "/im2 (copy).dcm", size - 9);
  const Volume v = loadVolume(series);
  EXPECT_EQ(v.bytes(), whole.bytes());
  EXPECT_EQ(v.spacing(), whole.spacing());
  EXPECT_EQ(noteWith(v, "skipped " + series + "/im2 (copy).dcm: corrupt or truncated"), 1)
      << ::testing::PrintToString(v.notes());
  // Opening another file of the series skips it too; naming the broken one fails on it.
  EXPECT_EQ(loadVolume(series + "/im0.dcm").bytes(), whole.bytes());
  expectLoadError([&] { loadVolume(series + "/im2 (copy).dcm"); }, series + "/im2 (copy).dcm",
                  "corrupt or truncated DICOM data");
  // A broken slice of the series itself: the rest opens, the gap it leaves is warned about and
  // filled in (MissingSlicesAreFilledIn).
  const std::string holed = dicomSeries(dir, "holed", 5);
  for (int n = 0; n < 5; ++n) {  // the file at z = 4, the middle
    const std::string file = holed + "/im" + std::to_string(n) + ".dcm";
    if ((n * 7) % 5 == 2) std::filesystem::resize_file(file, std::filesystem::file_size(file) - 9);
  }
  const Volume four = loadVolume(holed);
  EXPECT_EQ(four.dims()[2], 5);
  EXPECT_EQ(noteWith(four, "corrupt or truncated"), 1) << ::testing::PrintToString(four.notes());
  EXPECT_EQ(noteWith(four, "warning: 1 missing slice (gaps of whole multiples of the step"), 1)
      << ::testing::PrintToString(four.notes());
  // Many broken files: three named, then a count, not a line each.
  const std::string many = dicomSeries(dir, "many", 3);
  for (int n = 0; n < 6; ++n)
    cutCopy(many + "/im0.dcm", many + "/broken" + std::to_string(n) + ".dcm", size / 2);
  const Volume three = loadVolume(many);
  EXPECT_EQ(three.dims()[2], 3);
  EXPECT_EQ(noteWith(three, "corrupt or truncated DICOM data"), 3);
  EXPECT_EQ(noteWith(three, "skipped 3 more corrupt or truncated files"), 1)
      << ::testing::PrintToString(three.notes());
  // A CD's tree with a broken file at its top: the series below still opens.
  const std::string inCd = dicomSeries(dir, "cd/series", 3);
  cutCopy(inCd + "/im0.dcm", dir.path("cd/stray.dcm"), size / 2);
  const Volume cd = loadVolume(dir.path("cd"));
  EXPECT_EQ(cd.dims()[2], 3);
  EXPECT_EQ(noteWith(cd, "skipped " + dir.path("cd/stray.dcm")), 1)
      << ::testing::PrintToString(cd.notes());
  // Nothing readable at all: one line naming the first broken file.
  std::filesystem::create_directories(dir.path("none"));
  for (int n = 0; n < 2; ++n)
    cutCopy(inCd + "/im0.dcm", dir.path("none/b" + std::to_string(n) + ".dcm"), size / 2);
  expectLoadError(
      [&] { loadVolume(dir.path("none")); }, dir.path("none"),
      "no readable DICOM image: " + dir.path("none/b0.dcm") + ": corrupt or truncated DICOM data");
}

// Slices 2 mm apart but for a gap of 4 mm: the missing slice is filled in, linear between its
// neighbours (the test slices' values are linear in z), so the volume keeps its true extent. A
// gap of 2.5 steps is no missing slice: the stack is resampled onto regular steps, with a
// warning (before 2026-12-03 it was drawn evenly spaced, squeezing the gap).
TEST(DicomFiles, MissingSlicesAreFilledIn) {
  TempDir dir;
  testing::DicomSliceSpec spec;
  auto write = [&](const std::string& name, std::initializer_list<int> zs) {
    std::filesystem::create_directories(dir.path(name));
    for (int z : zs) {
      spec.position = {0, 0, double(z)};
      ASSERT_TRUE(
          testing::writeDicomSlice(dir.path(name + "/" + std::to_string(z) + ".dcm"), spec));
    }
  };
  write("gap", {0, 2, 4, 8, 10});
  const Volume v = loadVolume(dir.path("gap"));
  ASSERT_EQ(v.dims()[2], 6);
  EXPECT_DOUBLE_EQ(v.spacing().z, 2.0);
  EXPECT_EQ(v.type(), ScalarType::Int16);
  for (int k = 0; k < 6; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 5; ++i)
        ASSERT_EQ(v.value(i, j, k), i + 10 * j + 100 * 2 * k) << i << " " << j << " " << k;
  ASSERT_FALSE(v.notes().empty());
  EXPECT_NE(v.notes()[0].find("warning: 1 missing slice (gaps of whole multiples of the step, "
                              "2.000000): filled in by linear interpolation between their "
                              "neighbours"),
            std::string::npos)
      << v.notes()[0];
  // Three missing after the first: a third and two thirds of the way, rounded (int16 stays).
  write("run", {0, 8, 10, 12, 14});
  const Volume run = loadVolume(dir.path("run"));
  ASSERT_EQ(run.dims()[2], 8);
  for (int k = 0; k < 8; ++k) EXPECT_EQ(run.value(0, 0, k), 200 * k) << k;
  EXPECT_NE(run.notes()[0].find("warning: 3 missing slices"), std::string::npos) << run.notes()[0];
  // Not a whole multiple: resampled onto 6 steps of 11/6 mm from the first slice to the last,
  // each plane linear between the slices either side (the values are linear in z), rounded.
  write("odd", {0, 2, 4, 9, 11});
  const Volume odd = loadVolume(dir.path("odd"));
  ASSERT_EQ(odd.dims()[2], 7);
  EXPECT_NEAR(odd.spacing().z, 11.0 / 6.0, 1e-9);
  EXPECT_EQ(odd.type(), ScalarType::Int16);
  for (int k = 0; k < 7; ++k)
    EXPECT_EQ(odd.value(1, 2, k), std::round(1 + 20 + 100 * 11.0 * k / 6.0)) << k;
  EXPECT_NE(odd.notes()[0].find("warning: a gap of 5.000000 between slices where most are "
                                "2.000000: missing slices? resampled onto 7 slices 1.833333 "
                                "apart, each linear between the slices either side"),
            std::string::npos)
      << odd.notes()[0];
  // More missing than stored: still resampled, to at most twice the slices stored.
  write("far", {0, 2, 4, 40});
  const Volume far = loadVolume(dir.path("far"));
  EXPECT_EQ(far.dims()[2], 8);
  EXPECT_NEAR(far.spacing().z, 40.0 / 7.0, 1e-9);
  // Positions a hair off a regular step (rounded in the files): drawn evenly spaced, unblurred.
  spec.position = {0, 0, 0};
  std::filesystem::create_directories(dir.path("hair"));
  for (int k = 0; k < 5; ++k) {
    spec.position = {0, 0, 2.0 * k + (k == 2 ? 0.05 : 0.0)};
    ASSERT_TRUE(testing::writeDicomSlice(dir.path("hair/" + std::to_string(k) + ".dcm"), spec));
  }
  const Volume hair = loadVolume(dir.path("hair"));
  EXPECT_EQ(hair.dims()[2], 5);
  EXPECT_TRUE(testing::hasNoteWith(hair, "uneven slice spacing")) << hair.notes()[0];
  EXPECT_TRUE(testing::hasNoteWith(hair, "drawn evenly spaced"));
}

TEST(TiffFiles, MultiPageTypesChannelsAndImageJSpacing) {
  TempDir dir;
  std::vector<std::vector<uint16_t>> pages(3, std::vector<uint16_t>(6));
  for (int p = 0; p < 3; ++p)
    for (int i = 0; i < 6; ++i) pages[size_t(p)][size_t(i)] = uint16_t(1000 * p + i);
  ASSERT_TRUE(testing::writeTiff(dir.path("u16.tif"), 3, 2, pages, SAMPLEFORMAT_UINT, 1,
                                 "ImageJ=1.53\nimages=3\nslices=3\nunit=micron\nspacing=2.5\n"));
  const Volume v = loadVolume(dir.path("u16.tif"));
  EXPECT_EQ(v.dims(), (std::array<int64_t, 3>{3, 2, 3}));
  EXPECT_EQ(v.type(), ScalarType::UInt16);
  EXPECT_EQ(v.value(2, 1, 2), 2005);
  EXPECT_EQ(v.spacing(), glm::dvec3(0.25, 0.5, 2.5));  // resolution tags and spacing=
  EXPECT_FALSE(testing::hasNoteWith(v, "no pixel size") ||
               testing::hasNoteWith(v, "no slice spacing"));
  // 72 dpi in a plain TIFF is a print size, not the sample's: spacing 1, with notes.
  std::vector<std::vector<float>> fpages(2, std::vector<float>(4, 0.25f));
  ASSERT_TRUE(testing::writeTiff(dir.path("f.tiff"), 2, 2, fpages, SAMPLEFORMAT_IEEEFP));
  EXPECT_EQ(loadVolume(dir.path("f.tiff")).type(), ScalarType::Float32);
  EXPECT_EQ(loadVolume(dir.path("f.tiff")).spacing(), glm::dvec3(1.0));
  const Volume plain = loadVolume(dir.path("f.tiff"));
  EXPECT_TRUE(testing::hasNoteWith(plain, "no pixel size in the file: 1 assumed"));
  EXPECT_TRUE(testing::hasNoteWith(plain, "no slice spacing in the file: 1 assumed"));
  // 32- and 64-bit samples become float32.
  std::vector<std::vector<int32_t>> ipages = {{-70000, 1, 2, 3}, {4, 5, 6, 70000}};
  ASSERT_TRUE(testing::writeTiff(dir.path("i32.tif"), 2, 2, ipages, SAMPLEFORMAT_INT));
  const Volume i32 = loadVolume(dir.path("i32.tif"));
  EXPECT_EQ(i32.type(), ScalarType::Float32);
  EXPECT_EQ(i32.value(0, 0, 0), -70000.0);
  EXPECT_EQ(i32.value(1, 1, 1), 70000.0);
  std::vector<std::vector<double>> dpages = {{0.5, 1.5, 2.5, 3.5}};
  ASSERT_TRUE(testing::writeTiff(dir.path("f64.tif"), 2, 2, dpages, SAMPLEFORMAT_IEEEFP));
  EXPECT_EQ(loadVolume(dir.path("f64.tif")).value(1, 1, 0), 3.5);
  // Three interleaved channels: channel 2 holds 100 + pixel index.
  std::vector<std::vector<uint8_t>> rgb(2, std::vector<uint8_t>(4 * 3));
  for (int p = 0; p < 2; ++p)
    for (int i = 0; i < 4; ++i)
      for (int c = 0; c < 3; ++c) rgb[size_t(p)][size_t(3 * i + c)] = uint8_t(50 * c + i + p);
  ASSERT_TRUE(testing::writeTiff(dir.path("rgb.tif"), 2, 2, rgb, SAMPLEFORMAT_UINT, 3));
  EXPECT_EQ(loadVolume(dir.path("rgb.tif"), {"", 0, 2, {}}).value(1, 1, 1), 100 + 3 + 1);
  expectLoadError(
      [&] {
        loadVolume(dir.path("rgb.tif"), {"", 0, 3, {}});
      },
      dir.path("rgb.tif"), "--channel 3 is out of range (3 channels)");
}

TEST(TiffFiles, FolderInNaturalOrder) {
  TempDir dir;
  std::filesystem::create_directories(dir.path("stack"));
  for (int n : {1, 2, 10}) {
    std::vector<std::vector<uint8_t>> page(1, std::vector<uint8_t>(4, uint8_t(n)));
    ASSERT_TRUE(testing::writeTiff(dir.path("stack/z" + std::to_string(n) + ".tif"), 2, 2, page,
                                   SAMPLEFORMAT_UINT));
  }
  dir.write("stack/._z1.tif", "macOS's resource fork of z1.tif, not a TIFF");
  const Volume v = loadVolume(dir.path("stack"));
  EXPECT_EQ(v.dims()[2], 3);
  EXPECT_EQ(v.value(0, 0, 0), 1);
  EXPECT_EQ(v.value(0, 0, 1), 2);
  EXPECT_EQ(v.value(0, 0, 2), 10);
  // One-page files are read on every core; a file of two pages among them is read the general
  // way, every page of every file in turn, to the same result.
  std::vector<std::vector<uint8_t>> two = {std::vector<uint8_t>(4, 20),
                                           std::vector<uint8_t>(4, 21)};
  ASSERT_TRUE(testing::writeTiff(dir.path("stack/z20.tif"), 2, 2, two, SAMPLEFORMAT_UINT));
  const Volume mixed = loadVolume(dir.path("stack"));
  ASSERT_EQ(mixed.dims()[2], 5);
  EXPECT_EQ(mixed.value(1, 1, 3), 20);
  EXPECT_EQ(mixed.value(1, 1, 4), 21);
  // Many one-page files (more than cores): each slice in its place.
  std::filesystem::create_directories(dir.path("many"));
  for (int n = 0; n < 40; ++n) {
    std::vector<std::vector<uint16_t>> page(1, std::vector<uint16_t>(4, uint16_t(1000 + n)));
    ASSERT_TRUE(testing::writeTiff(dir.path("many/s" + std::to_string(n) + ".tif"), 2, 2, page,
                                   SAMPLEFORMAT_UINT));
  }
  const Volume many = loadVolume(dir.path("many"));
  ASSERT_EQ(many.dims()[2], 40);
  for (int n = 0; n < 40; ++n) ASSERT_EQ(many.value(1, 0, n), 1000 + n) << n;
}

// Tiled pages (microscopy's big planes): tiles overhanging the page's right and bottom edges,
// interleaved and planar samples, uncompressed and compressed, give the strips' volume; a cut
// tiled file fails with one line.
TEST(TiffFiles, TiledPagesReadAsStripsDo) {
  TempDir dir;
  const uint32_t width = 37, height = 21;  // not multiples of the 16-pixel tiles
  const uint16_t samples = 3;
  std::vector<std::vector<uint16_t>> pages(2,
                                           std::vector<uint16_t>(size_t(width) * height * samples));
  for (size_t p = 0; p < pages.size(); ++p)
    for (size_t i = 0; i < pages[p].size(); ++i) pages[p][i] = uint16_t(7919 * i + 1000 * p);
  ASSERT_TRUE(
      testing::writeTiff(dir.path("strips.tif"), width, height, pages, SAMPLEFORMAT_UINT, samples));
  for (const auto& [name, planar, compression] :
       {std::tuple{"contig.tif", false, COMPRESSION_NONE},
        std::tuple{"planar.tif", true, COMPRESSION_NONE},
        std::tuple{"deflate.tif", false, COMPRESSION_ADOBE_DEFLATE},
        std::tuple{"planar_lzw.tif", true, COMPRESSION_LZW}}) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(testing::writeTiledTiff(dir.path(name), width, height, pages, SAMPLEFORMAT_UINT,
                                        samples, 16, planar, uint16_t(compression)));
    for (int channel = 0; channel < samples; ++channel) {
      const Volume strips = loadVolume(dir.path("strips.tif"), {"", 0, channel, {}});
      const Volume tiles = loadVolume(dir.path(name), {"", 0, channel, {}});
      ASSERT_EQ(tiles.dims(), (std::array<int64_t, 3>{width, height, 2}));
      EXPECT_EQ(tiles.bytes(), strips.bytes()) << "channel " << channel;
      // One value by hand: the last pixel of the second page, past the last tile's seam.
      EXPECT_EQ(tiles.value(width - 1, height - 1, 1),
                double(uint16_t(7919 * ((size_t(width) * height - 1) * samples + channel) + 1000)));
    }
  }
  // A header whose tiles are far bigger than the page (TileWidth and TileLength patched to
  // 4096 in the directory, which libtiff writes after the tiles) fails before a tile buffer is
  // sized from it.
  std::vector<std::vector<uint8_t>> small(1, std::vector<uint8_t>(64 * 64, 7));
  ASSERT_TRUE(testing::writeTiledTiff(dir.path("tiled.tif"), 64, 64, small, SAMPLEFORMAT_UINT, 1,
                                      16, false));
  std::string bytes = fileBytes(dir.path("tiled.tif"));
  ASSERT_EQ(bytes.substr(0, 2), "II");
  const auto u32 = [&](size_t at) {
    return uint32_t(uint8_t(bytes[at])) | uint32_t(uint8_t(bytes[at + 1])) << 8 |
           uint32_t(uint8_t(bytes[at + 2])) << 16 | uint32_t(uint8_t(bytes[at + 3])) << 24;
  };
  const size_t ifd = u32(4);
  ASSERT_LT(ifd + 2, bytes.size());
  const size_t entries = uint8_t(bytes[ifd]) | size_t(uint8_t(bytes[ifd + 1])) << 8;
  int patched = 0;
  for (size_t e = 0; e < entries; ++e) {
    const size_t at = ifd + 2 + 12 * e;
    const unsigned tag = uint8_t(bytes[at]) | unsigned(uint8_t(bytes[at + 1])) << 8;
    if (tag != TIFFTAG_TILEWIDTH && tag != TIFFTAG_TILELENGTH) continue;
    const unsigned type = uint8_t(bytes[at + 2]);
    bytes[at + 8] = 0;  // 4096, as SHORT or LONG
    bytes[at + 9] = 0x10;
    if (type == TIFF_LONG) bytes[at + 10] = bytes[at + 11] = 0;
    ++patched;
  }
  ASSERT_EQ(patched, 2);
  expectVolumeLoadError(dir.write("huge_tiles.tif", bytes),
                        "tiles of 4096 x 4096 for a page of 64 x 64");
}

TEST(TiffFiles, PagesThatDisagreeFailWithOneLine) {
  TempDir dir;
  std::vector<std::vector<uint8_t>> pages{std::vector<uint8_t>(4), std::vector<uint8_t>(4)};
  ASSERT_TRUE(testing::writeTiff(dir.path("a.tif"), 2, 2, pages, SAMPLEFORMAT_UINT));
  // Mixed sizes: a folder whose second file is 3 x 2.
  std::filesystem::create_directories(dir.path("mixed"));
  std::vector<std::vector<uint8_t>> small(1, std::vector<uint8_t>(4)),
      wide(1, std::vector<uint8_t>(6));
  ASSERT_TRUE(testing::writeTiff(dir.path("mixed/1.tif"), 2, 2, small, SAMPLEFORMAT_UINT));
  ASSERT_TRUE(testing::writeTiff(dir.path("mixed/2.tif"), 3, 2, wide, SAMPLEFORMAT_UINT));
  expectLoadError([&] { loadVolume(dir.path("mixed")); }, dir.path("mixed"),
                  "2.tif: page 1 is 3 x 2, 8-bit, 1 sample(s), the first 2 x 2");
  // Mixed types in one file: write 8-bit then a 16-bit page by hand.
  {
    TIFF* t = TIFFOpen(dir.path("types.tif").c_str(), "w");
    ASSERT_NE(t, nullptr);
    for (uint16_t bits : {8, 16}) {
      TIFFSetField(t, TIFFTAG_IMAGEWIDTH, 2u);
      TIFFSetField(t, TIFFTAG_IMAGELENGTH, 1u);
      TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, bits);
      TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, uint16_t(1));
      TIFFSetField(t, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK);
      uint8_t row[4] = {1, 2, 3, 4};
      TIFFWriteScanline(t, row, 0, 0);
      TIFFWriteDirectory(t);
    }
    TIFFClose(t);
  }
  expectVolumeLoadError(dir.path("types.tif"), "all pages must agree");
  // Truncated strips.
  std::vector<std::vector<uint8_t>> big(1, std::vector<uint8_t>(64 * 64, 7));
  ASSERT_TRUE(testing::writeTiff(dir.path("cut.tif"), 64, 64, big, SAMPLEFORMAT_UINT));
  const std::string bytes = fileBytes(dir.path("cut.tif"));
  expectVolumeLoadError(dir.write("cut2.tif", bytes.substr(0, 2000) + bytes.substr(4000)),
                        "not a readable TIFF file");
  expectVolumeLoadError(dir.write("junk.tif", "II*\0junk"), "not a readable TIFF file");
}

TEST(SlcFiles, RawAndRunLengthSlicesAndBadOnes) {
  TempDir dir;
  const std::string head = "11111\n2 2 2 8\n1.0 2.0 3.0\n1 6 0 ";
  const std::string icon = "1 1 X" + std::string(3, '\0');
  const Volume raw = loadVolume(dir.write("raw.slc", head + "0\n" + icon + "abcdefgh"));
  EXPECT_EQ(raw.value(1, 1, 1), 'h');
  EXPECT_EQ(raw.spacing(), glm::dvec3(1, 2, 3));
  // Run-length: slice 0 = four 9s, slice 1 = literal 1 2 3 4.
  const std::string rle =
      "3 X" + std::string("\x04\x09\x00", 3) + "6 X" + std::string("\x84\x01\x02\x03\x04\x00", 6);
  const Volume packed = loadVolume(dir.write("rle.slc", head + "1\n" + icon + rle));
  EXPECT_EQ(packed.value(1, 1, 0), 9);
  EXPECT_EQ(packed.value(1, 1, 1), 4);
  expectVolumeLoadError(dir.write("magic.slc", "12345\n"), "magic");
  expectVolumeLoadError(dir.write("cut.slc", head + "0\n" + icon + "abc"), "truncated");
  expectVolumeLoadError(
      dir.write("over.slc", head + "1\n" + icon + "3 X" + std::string("\x7f\x09\x00", 3)),
      "more than a slice");
  expectVolumeLoadError(dir.write("huge.slc", "11111\n100000 100000 100000 8\n1 1 1\n1 6 0 0\n"),
                        "more than this machine's memory");
  expectVolumeLoadError(dir.write("bits.slc", "11111\n2 2 2 16\n1 1 1\n1 6 0 0\n"), "16 bits");
}

}  // namespace
}  // namespace ewa
