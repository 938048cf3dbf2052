// DICOM without the Part 10 header (ACR-NEMA files) and slices without ImagePositionPatient.
#include <gdcmTrace.h>
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "io/format_loaders.h"
#include "io/volume_loader.h"
#include "medical_test_files.h"

namespace ewa {
namespace {

using testing::allNotes;
using testing::bareDataSet;
using testing::dicomSeries;
using testing::editDicom;
using testing::expectVolumeLoadError;
using testing::TempDir;

// The series of `folder` (dicomSeries' im0.dcm, im1.dcm, ...) rewritten as bare data sets in
// folder `name`, in transfer syntax `syntax` first.
std::string bareSeries(const TempDir& dir, const std::string& folder, const std::string& name,
                       int count, gdcm::TransferSyntax::TSType syntax) {
  gdcm::Trace::WarningOff();  // GDCM's notes on the test's own rewriting
  std::filesystem::create_directories(dir.path(name));
  for (int n = 0; n < count; ++n) {
    const std::string im = "im" + std::to_string(n) + ".dcm";
    const std::string copy = dir.path(name + "/" + im + ".part10");
    std::filesystem::copy_file(folder + "/" + im, copy);
    EXPECT_TRUE(testing::recompressDicom(copy, syntax));
    const std::string bare = bareDataSet(copy);
    EXPECT_FALSE(bare.empty());
    dir.write(name + "/im" + std::to_string(n), bare);  // no extension: found by its start
    std::filesystem::remove(copy);
  }
  return dir.path(name);
}

TEST(DicomBare, DataSetsWithoutThePart10HeaderLoadLikeTheirSeries) {
  TempDir dir;
  testing::DicomSliceSpec spec;
  spec.slope = 2.0;
  spec.intercept = -5.0;
  const std::string folder = dicomSeries(dir, "s", 5, spec);
  const Volume part10 = loadVolume(folder);
  for (const auto syntax : {gdcm::TransferSyntax::ExplicitVRLittleEndian,
                            gdcm::TransferSyntax::ImplicitVRLittleEndian}) {
    SCOPED_TRACE(int(syntax));
    const std::string name = "bare" + std::to_string(int(syntax));
    const std::string bare = bareSeries(dir, folder, name, 5, syntax);
    const std::string first = testing::fileBytes(bare + "/im0");
    ASSERT_GE(first.size(), 8u);
    EXPECT_EQ(first.substr(0, 2), std::string("\x08\x00", 2));  // no preamble: group 0008 first
    const bool explicitVr = syntax == gdcm::TransferSyntax::ExplicitVRLittleEndian;
    EXPECT_EQ(std::isupper(uint8_t(first[4])) && std::isupper(uint8_t(first[5])), explicitVr);
    EXPECT_TRUE(looksLikeDicom(bare + "/im0"));
    for (const std::string& path : {bare, bare + "/im3"}) {
      const Volume v = loadVolume(path);
      EXPECT_EQ(v.dims(), part10.dims());
      EXPECT_EQ(v.spacing(), part10.spacing());
      EXPECT_EQ(v.origin(), part10.origin());
      EXPECT_EQ(v.type(), part10.type());
      EXPECT_EQ(v.bytes(), part10.bytes());
      EXPECT_TRUE(v.patientFrame());
    }
  }
}

TEST(DicomBare, OtherFilesAndBadOnesAreNotTakenForDicom) {
  TempDir dir;
  const std::string folder = dicomSeries(dir, "s", 3);
  const std::string bare = bareDataSet(folder + "/im0.dcm");
  // Bytes that start like group 0008 but hold no second element in tag order.
  const std::string junk =
      dir.write("junk", std::string("\x08\x00\x10\x00", 4) + std::string(300, '\x01'));
  EXPECT_FALSE(looksLikeDicom(junk));
  // (0008,0020) before (0008,0010): out of tag order.
  const std::string element20 = std::string("\x08\x00\x20\x00\x04\x00\x00\x00", 8) + "abcd";
  const std::string element10 = std::string("\x08\x00\x10\x00\x04\x00\x00\x00", 8) + "abcd";
  const std::string reversed = dir.write("reversed", element20 + element10);
  EXPECT_TRUE(looksLikeDicom(dir.write("ordered", element10 + element20)));
  EXPECT_FALSE(looksLikeDicom(reversed));
  // Only in files named as DICOM files are: not in a .raw whose data might start alike.
  EXPECT_FALSE(looksLikeDicom(dir.write("data.raw", bare)));
  EXPECT_TRUE(looksLikeDicom(dir.write("old.ACR", bare)));
  EXPECT_TRUE(looksLikeDicom(dir.write("1.3.12.2.1107", bare)));
  // Cut short in its pixel data: one line naming the file.
  const std::string cut = dir.write("cut.dcm", bare.substr(0, bare.size() - 10));
  expectVolumeLoadError(cut, "corrupt or truncated DICOM data");
  // Big-endian ACR-NEMA is refused in one line, not left to GDCM.
  const std::string big = dir.path("big.dcm");
  std::filesystem::copy_file(folder + "/im1.dcm", big);
  ASSERT_TRUE(testing::recompressDicom(big, gdcm::TransferSyntax::ExplicitVRBigEndian));
  const std::string bigBare = dir.write("big", bareDataSet(big));
  EXPECT_TRUE(looksLikeDicom(bigBare));
  expectVolumeLoadError(bigBare, "big-endian");
  // A bare file beside a series is one of its slices; a broken one is skipped with a warning.
  dir.write("s/extra", bare.substr(0, bare.size() - 10));
  const Volume v = loadVolume(folder);
  EXPECT_EQ(v.dims()[2], 3);
  EXPECT_NE(allNotes(v).find("skipped " + dir.path("s/extra")), std::string::npos) << allNotes(v);
}

// Removes ImagePositionPatient (and, with `orientation`, ImageOrientationPatient) from the
// file, sets its SliceLocation (unless NaN) and InstanceNumber.
void unplace(const std::string& path, bool orientation, double location, int instance) {
  ASSERT_TRUE(editDicom(path, [&](gdcm::DataSet& ds) {
    ds.Remove(gdcm::Tag(0x0020, 0x0032));
    if (orientation) ds.Remove(gdcm::Tag(0x0020, 0x0037));
    if (location == location) {
      gdcm::Attribute<0x0020, 0x1041> at;
      at.SetValue(location);
      ds.Replace(at.GetAsDataElement());
    }
    gdcm::Attribute<0x0020, 0x0013> number;
    number.SetValue(instance);
    ds.Replace(number.GetAsDataElement());
    gdcm::Attribute<0x0018, 0x0050> thickness;
    thickness.SetValue(2.5);
    ds.Replace(thickness.GetAsDataElement());
  }));
}

TEST(DicomBare, SlicesWithoutPositionsArePlacedBySliceLocationThenInstanceNumber) {
  TempDir dir;
  const int count = 5;
  const std::string folder = dicomSeries(dir, "s", count);  // im n at z = 2 ((7 n) mod 5)
  const Volume placed = loadVolume(folder);
  const std::string byLocation = dicomSeries(dir, "location", count);
  const std::string byInstance = dicomSeries(dir, "instance", count);
  for (int n = 0; n < count; ++n) {
    const double z = 2.0 * ((n * 7) % count);
    const std::string im = "/im" + std::to_string(n) + ".dcm";
    // Instance numbers against the slices' order: the location wins where it is given.
    unplace(byLocation + im, false, z, count - int(z / 2));
    unplace(byInstance + im, true, std::nan(""), 1 + int(z / 2));
  }
  const Volume a = loadVolume(byLocation);
  EXPECT_EQ(a.bytes(), placed.bytes());
  EXPECT_EQ(a.spacing(), placed.spacing());
  EXPECT_TRUE(a.patientFrame());  // the orientation is the file's
  EXPECT_TRUE(testing::hasNoteWith(a, "placed by their SliceLocation")) << allNotes(a);

  const Volume b = loadVolume(byInstance);
  EXPECT_EQ(b.bytes(), placed.bytes());
  EXPECT_EQ(b.spacing(), glm::dvec3(0.75, 0.5, 2.5));  // SliceThickness
  EXPECT_EQ(b.origin(), glm::dvec3(0.0));
  EXPECT_FALSE(b.patientFrame());  // no orientation: no anatomical labels
  EXPECT_TRUE(testing::hasNoteWith(b, "InstanceNumber order, 2.5 apart (SliceThickness)"))
      << allNotes(b);
  EXPECT_TRUE(testing::hasNoteWith(b, "no ImageOrientationPatient")) << allNotes(b);

  // Shared locations fall back to the instance numbers.
  for (int n = 0; n < count; ++n)
    unplace(byInstance + "/im" + std::to_string(n) + ".dcm", true, 7.0, 1 + (n * 7) % count);
  const Volume c = loadVolume(byInstance);
  EXPECT_EQ(c.bytes(), placed.bytes());
  EXPECT_TRUE(testing::hasNoteWith(c, "InstanceNumber order")) << allNotes(c);
}

// Sets a DS element to `values` (backslash-separated, at most 16 characters each, padded to an
// even length).
void setNumbers(gdcm::DataSet& ds, const gdcm::Tag& tag, const std::vector<double>& values) {
  std::string text;
  for (double v : values) {
    char number[32];
    std::snprintf(number, sizeof number, "%.9g", v);
    text += (text.empty() ? "" : "\\") + std::string(number);
  }
  if (text.size() % 2) text += ' ';
  gdcm::DataElement e(tag);
  e.SetVR(gdcm::VR::DS);
  e.SetByteValue(text.data(), uint32_t(text.size()));
  ds.Replace(e);
}

// ACR-NEMA's retired Image Position and Orientation place slices that have no
// ImagePositionPatient, in the equipment's axes; positions off the line along the normal do not.
TEST(DicomBare, AcrNemaImagePositionPlacesSlicesAlongItsOrientation) {
  TempDir dir;
  const int count = 5;
  const Volume placed = loadVolume(dicomSeries(dir, "s", count));  // im n at z = 2 ((7 n) mod 5)
  const double c = std::cos(0.3), sn = std::sin(0.3);
  const glm::dvec3 normal(0.0, -sn, c);  // rows along x, columns along (0, c, sn)
  const std::string retired = dicomSeries(dir, "retired", count);
  const auto rewrite = [&](double offAxis) {
    for (int n = 0; n < count; ++n) {
      const double z = 2.0 * ((n * 7) % count);
      const std::string im = retired + "/im" + std::to_string(n) + ".dcm";
      unplace(im, true, std::nan(""), count - int(z / 2));  // instance numbers reversed
      ASSERT_TRUE(editDicom(im, [&](gdcm::DataSet& ds) {
        ds.Remove(gdcm::Tag(0x0020, 0x1041));
        const glm::dvec3 p = glm::dvec3(10.0 + offAxis * n, 20.0, 0.0) + z * normal;
        setNumbers(ds, gdcm::Tag(0x0020, 0x0030), {p.x, p.y, p.z});
        setNumbers(ds, gdcm::Tag(0x0020, 0x0035), {1, 0, 0, 0, c, sn});
      }));
    }
  };
  rewrite(0.0);
  const Volume v = loadVolume(retired);
  EXPECT_EQ(v.bytes(), placed.bytes());
  EXPECT_NEAR(v.spacing().z, 2.0, 1e-6);
  EXPECT_NEAR(glm::length(v.direction()[2] - normal), 0.0, 1e-6);
  EXPECT_NEAR(glm::length(v.origin() - glm::dvec3(10.0, 20.0, 0.0)), 0.0, 1e-6);
  EXPECT_FALSE(v.patientFrame());  // the equipment's axes
  EXPECT_TRUE(testing::hasNoteWith(
      v, "placed by ACR-NEMA's Image Position (0020,0030) and Image Orientation (0020,0035)"))
      << allNotes(v);
  // Positions off that line: the instance numbers (reversed here) order the slices instead.
  rewrite(1.5);
  const Volume off = loadVolume(retired);
  EXPECT_TRUE(testing::hasNoteWith(off, "InstanceNumber order")) << allNotes(off);
  EXPECT_NE(off.bytes(), placed.bytes());
}

}  // namespace
}  // namespace ewa
