// Detached headers that name hostile data files: devices, FIFOs, folders, /proc files and
// the header itself. Outside the header's folder they are refused by default; with
// --allow-outside-data (any path, as NRRD allows) these must still fail fast with one line,
// never block, and never write anything.
#include <sys/stat.h>

#include "loader_test_files.h"

namespace ewa {
namespace {

using testing::expectLoadError;
using testing::TempDir;

// Loads as --allow-outside-data does, so that the data file's own checks are what refuses it.
void expectVolumeLoadError(const std::string& path, const std::string& fragment) {
  LoadOptions anywhere;
  anywhere.dataFiles = DataFileScope::Anywhere;
  expectLoadError([&] { loadVolume(path, anywhere); }, path, fragment);
}

std::string nhdr(const std::string& dataFile) {
  return "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 4 4 4\nencoding: raw\ndata file: " +
         dataFile + "\n";
}

TEST(LoaderHostilePaths, DevicesFifosFoldersAndProcFilesAreRefused) {
  TempDir dir;
  // By default a header may not name them at all.
  testing::expectVolumeLoadError(dir.write("etc.nhdr", nhdr("/dev/zero")),
                                 "outside its own folder");
  expectVolumeLoadError(dir.write("zero.nhdr", nhdr("/dev/zero")), "not a regular file");
  expectVolumeLoadError(dir.write("null.nhdr", nhdr("/dev/null")), "not a regular file");
  ASSERT_EQ(mkfifo(dir.path("pipe").c_str(), 0600), 0);
  expectVolumeLoadError(dir.write("fifo.nhdr", nhdr("pipe")), "not a regular file");
  expectVolumeLoadError(dir.write("dir.nhdr", nhdr("/")), "directory");
  // /proc files say they are empty: the data is not there.
  expectVolumeLoadError(dir.write("proc.nhdr", nhdr("/proc/self/status")), "bytes");
  // The same checks for MetaImage and .dat data files.
  expectVolumeLoadError(dir.write("zero.mhd",
                                  "NDims = 3\nDimSize = 4 4 4\nElementType = "
                                  "MET_UCHAR\nElementDataFile = /dev/zero\n"),
                        "not a regular file");
  expectVolumeLoadError(
      dir.write("zero.dat", "ObjectFileName: /dev/zero\nResolution: 4 4 4\nFormat: UCHAR\n"),
      "not a regular file");
  // A header naming itself as its data is read (its first 64 bytes are the voxels), not changed.
  const std::string self = dir.write("self.nhdr", nhdr("self.nhdr"));
  EXPECT_EQ(loadVolume(self).voxelCount(), 64);
  std::ifstream in(self);
  std::string first;
  std::getline(in, first);
  EXPECT_EQ(first, "NRRD0004");
}

}  // namespace
}  // namespace ewa
