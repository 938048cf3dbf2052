// Copies of a DICOM series' files beside it: each image kept once, with a note.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "io/volume_loader.h"
#include "medical_test_files.h"

namespace ewa {
namespace {

using testing::allNotes;
using testing::dicomSeries;
using testing::editDicom;
using testing::TempDir;

size_t notesWith(const Volume& v, const std::string& text) {
  return size_t(std::count_if(v.notes().begin(), v.notes().end(), [&](const std::string& n) {
    return n.find(text) != std::string::npos;
  }));
}

TEST(DicomCopies, CopiesOfFilesBesideTheirSeriesAreKeptOnce) {
  TempDir dir;
  const std::string series = dicomSeries(dir, "s", 5);
  const Volume whole = loadVolume(series);
  // Two copies of one slice and one of another: without the check, positions holding two
  // and three slices would be an error ("several volumes, unevenly").
  namespace fs = std::filesystem;
  fs::copy_file(series + "/im2.dcm", series + "/im2 (copy).dcm");
  fs::copy_file(series + "/im2.dcm", series + "/im2 (copy 2).dcm");
  fs::copy_file(series + "/im4.dcm", series + "/im4 (copy).dcm");
  const Volume v = loadVolume(series);
  EXPECT_EQ(v.bytes(), whole.bytes());
  EXPECT_EQ(v.spacing(), whole.spacing());
  EXPECT_EQ(notesWith(v, "skipped " + series + "/im2.dcm: the same image as " + series +
                             "/im2 (copy 2).dcm (SOPInstanceUID "),
            1u)
      << allNotes(v);  // the first by path is kept: "im2 (copy 2).dcm" sorts before "im2.dcm"
  EXPECT_EQ(notesWith(v, "skipped "), 3u) << allNotes(v);
  EXPECT_EQ(notesWith(v, "warning: "), 0u) << allNotes(v);
  // The file named is the one kept of its copies, and its series is the one opened.
  const Volume named = loadVolume(series + "/im4.dcm");
  EXPECT_EQ(named.bytes(), whole.bytes());
  EXPECT_EQ(notesWith(named, "skipped " + series + "/im4 (copy).dcm: the same image as " + series +
                                 "/im4.dcm"),
            1u)
      << allNotes(named);
}

// One SOPInstanceUID on every image (as some anonymizers leave them) at different positions:
// different images, all kept.
TEST(DicomCopies, OneUidOnImagesAtDifferentPositionsIsNoCopy) {
  TempDir dir;
  const std::string series = dicomSeries(dir, "s", 4);
  const Volume whole = loadVolume(series);
  for (int n = 0; n < 4; ++n)
    ASSERT_TRUE(editDicom(series + "/im" + std::to_string(n) + ".dcm", [](gdcm::DataSet& ds) {
      gdcm::Attribute<0x0008, 0x0018> uid;
      uid.SetValue("1.2.3.4");
      ds.Replace(uid.GetAsDataElement());
    }));
  const Volume v = loadVolume(series);
  EXPECT_EQ(v.bytes(), whole.bytes());
  EXPECT_EQ(notesWith(v, "skipped "), 0u) << allNotes(v);
}

}  // namespace
}  // namespace ewa
