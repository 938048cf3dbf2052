// Hostile inputs that once read secrets or blew up memory, disk or time: data files outside a
// header's folder, bzip2 and archive bombs, limits set on the process, frames late in a gzip file,
// and scratch folders left by a killed process.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>

#include "io/archive_extract.h"
#include "io/decompress.h"
#include "io/memory_limit.h"
#include "io/scratch_cleanup.h"
#include "io/volume_loader.h"
#include "loader_test_files.h"

namespace ewa {
namespace {

namespace fs = std::filesystem;
using testing::bzip2Bytes;
using testing::expectLoadError;
using testing::expectVolumeLoadError;
using testing::gzipBytes;
using testing::TempDir;

// A tar of regular files (ustar headers), for archives whose contents the test sizes exactly.
std::string tarBytes(const std::vector<std::pair<std::string, std::string>>& files) {
  std::string out;
  for (const auto& [name, bytes] : files) {
    std::string h(512, '\0');
    name.copy(h.data(), 99);
    std::snprintf(h.data() + 100, 8, "%07o", 0644);
    std::snprintf(h.data() + 108, 8, "%07o", 0);
    std::snprintf(h.data() + 116, 8, "%07o", 0);
    std::snprintf(h.data() + 124, 12, "%011llo", static_cast<unsigned long long>(bytes.size()));
    std::snprintf(h.data() + 136, 12, "%011o", 0);
    h[156] = '0';
    std::memcpy(h.data() + 257,
                "ustar\0"
                "00",
                8);
    std::memset(h.data() + 148, ' ', 8);
    unsigned sum = 0;
    for (const char c : h) sum += static_cast<unsigned char>(c);
    std::snprintf(h.data() + 148, 8, "%06o", sum);
    out += h + bytes + std::string((512 - bytes.size() % 512) % 512, '\0');
  }
  return out + std::string(1024, '\0');
}

std::string mhd(const std::string& data) {
  return "ObjectType = Image\nNDims = 3\nDimSize = 4 4 4\nElementType = MET_UCHAR\n"
         "ElementDataFile = " +
         data + "\n";
}

TEST(HostileHeaders, ADetachedHeaderReadsDataOnlyFromItsOwnFolder) {
  TempDir dir;
  const std::string secret = dir.write("secret.raw", std::string(64, 's'));
  fs::create_directory(dir.path("case"));
  fs::create_directory(dir.path("case/data"));
  dir.write("case/data/own.raw", std::string(64, 'o'));
  fs::create_symlink(secret, dir.path("case/link.raw"));
  const std::string up = dir.write("case/up.mhd", mhd("../secret.raw"));
  const std::string absolute = dir.write("case/abs.mhd", mhd(secret));
  const std::string linked = dir.write("case/linked.mhd", mhd("link.raw"));
  const std::string etc = dir.write("case/etc.mhd", mhd("/etc/passwd"));
  for (const std::string& header : {up, absolute, linked, etc})
    expectVolumeLoadError(header, "outside its own folder (--allow-outside-data opens it)");
  const std::string nhdr =
      dir.write("case/up.nhdr",
                "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 4 4 4\nencoding: raw\ndata file: "
                "../secret.raw\n");
  expectVolumeLoadError(nhdr, "outside its own folder");
  const std::string dat =
      dir.write("case/up.dat", "ObjectFileName: ../secret.raw\nResolution: 4 4 4\nFormat: UCHAR\n");
  expectVolumeLoadError(dat, "outside its own folder");
  // Below its folder is fine, and the option opens the others.
  EXPECT_EQ(loadVolume(dir.write("case/own.mhd", mhd("data/own.raw"))).valueAt(0), 'o');
  LoadOptions anywhere;
  anywhere.dataFiles = DataFileScope::Anywhere;
  EXPECT_EQ(loadVolume(up, anywhere).valueAt(0), 's');
  EXPECT_EQ(loadVolume(linked, anywhere).valueAt(0), 's');
}

TEST(HostileHeaders, ABzip2PromiseBeyondAnyRealRatioIsRefusedBeforeDecompressing) {
  TempDir dir;
  // 2 GiB promised by a few hundred bytes: refused at once, not decompressed to find out.
  const std::string packed = bzip2Bytes(std::string(1 << 20, '\0'));
  const std::string path = dir.write(
      "bomb.nrrd",
      "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 1024 1024 2048\nencoding: bzip2\n\n" + packed);
  expectVolumeLoadError(path, "a decompression bomb?");
  // A byte skip counts decompressed bytes: the same bound holds for it.
  const std::string skip =
      dir.write("skip.nrrd",
                "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 4 4 4\nencoding: bzip2\n"
                "byte skip: 21474836480\n\n" +
                    packed);
  expectVolumeLoadError(skip, "bzip2 data");
  // Real ratios still load.
  const std::string fine = dir.write(
      "fine.nrrd", "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 64 64 64\nencoding: bzip2\n\n" +
                       bzip2Bytes(std::string(64 * 64 * 64, '\3')));
  EXPECT_EQ(loadVolume(fine).valueAt(1000), 3.0);
}

TEST(HostileHeaders, AnAddressSpaceLimitBoundsWhatAHeaderMayAllocate) {
#if defined(__SANITIZE_ADDRESS__)
  // AddressSanitizer reserves terabytes of address space for its shadow: under a 3 GiB limit
  // its allocator cannot map the exception the check throws.
  GTEST_SKIP() << "not under AddressSanitizer";
#endif
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    rlimit limit{uint64_t(3) << 30, uint64_t(3) << 30};
    setrlimit(RLIMIT_AS, &limit);
    bool ok = usableMemoryBytes() == (uint64_t(3) << 30);
    try {
      checkAllocation("x.nrrd", uint64_t(4) << 30, "data");
      ok = false;
    } catch (const std::exception& e) {
      ok = ok && std::string(e.what()).find("under this process's limit") != std::string::npos;
    }
    _exit(ok ? 0 : 1);
  }
  int status = 0;
  waitpid(child, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
}

TEST(HostileHeaders, AFrameLateInAGzipStreamKeepsOnlyThatFrame) {
  std::string data;
  for (int n = 0; n < 3 << 20; ++n) data.push_back(char(n * 7 + n / 4096));
  const std::string packed = gzipBytes(data);
  const auto* bytes = reinterpret_cast<const uint8_t*>(packed.data());
  const std::vector<uint8_t> window =
      inflateWindow("f.nii.gz", bytes, packed.size(), 2 << 20, (2 << 20) + 5000, "data");
  ASSERT_EQ(window.size(), 5000u);
  EXPECT_EQ(std::string(window.begin(), window.end()), data.substr(2 << 20, 5000));
  // Past the stream's end: what there is.
  const std::vector<uint8_t> tail =
      inflateWindow("f.nii.gz", bytes, packed.size(), (3 << 20) - 10, 4 << 20, "data");
  EXPECT_EQ(std::string(tail.begin(), tail.end()), data.substr((3 << 20) - 10));
}

TEST(HostileArchives, AnArchiveUnpacksToAtMostItsRatioBeyondTheFloor) {
  TempDir dir;
  const std::string path = dir.path("bomb.tar.gz");
  {
    // 8 MiB of zeros packs into a few kilobytes: over 100 times its size beyond a 1 MiB floor.
    const std::string zeros(8 << 20, '\0');
    const std::string tar = tarBytes({{"zeros.raw", zeros}});
    dir.write("bomb.tar.gz", gzipBytes(tar));
  }
  expectLoadError(
      [&] {
        extractArchive(path, {0, 100, 1 << 20, 100});
      },
      path, "times the archive's");
  ExtractedArchive whole = extractArchive(path, {0, 100, 16 << 20, 100});
  EXPECT_EQ(whole.bytes, uint64_t(8) << 20);
}

// A bomb inside an archive whose whole ratio looks honest (an incompressible member after it)
// is stopped by the running ratio near the floor, not after writing it all.
TEST(HostileArchives, ABombAheadOfIncompressibleDataStopsAtTheRunningRatio) {
  TempDir dir;
  std::string noise(4 << 20, '\0');
  uint32_t x = 12345;
  for (char& c : noise) c = char((x = x * 1664525u + 1013904223u) >> 24);
  const std::string zeros(64 << 20, '\0');
  const std::string bombFirst = dir.write(
      "bomb_first.tar.gz", gzipBytes(tarBytes({{"zeros.raw", zeros}, {"noise.raw", noise}})));
  const std::string noiseFirst = dir.write(
      "noise_first.tar.gz", gzipBytes(tarBytes({{"noise.raw", noise}, {"zeros.raw", zeros}})));
  const ArchiveLimits limits{0, 100, 16 << 20, 100};
  expectLoadError([&] { extractArchive(bombFirst, limits); }, bombFirst, "read of it");
  // Read in order, the same members never pass 100:1.
  EXPECT_EQ(extractArchive(noiseFirst, limits).bytes, uint64_t(68) << 20);
}

TEST(HostileArchives, ASignalRemovesTheScratchFolderBeforeTheProcessEnds) {
  TempDir dir;
  const std::string scratch = dir.path("ewaview-archive-test");
  fs::create_directories(scratch + "/a/b/c");
  for (int n = 0; n < 300; ++n) dir.write("ewaview-archive-test/a/f" + std::to_string(n), "x");
  dir.write("ewaview-archive-test/a/b/c/deep.raw", std::string(1000, 'd'));
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    registerScratchFolder(scratch);
    raise(SIGTERM);
    _exit(0);  // not reached: the signal ends the process after the clean-up
  }
  int status = 0;
  waitpid(child, &status, 0);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM);
  EXPECT_FALSE(fs::exists(scratch));
}

}  // namespace
}  // namespace ewa
