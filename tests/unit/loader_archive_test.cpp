// Volumes inside archives: a zip or tar.gz opens its volume file or DICOM series, names stay
// inside the scratch folder, the folder goes away, and bad archives fail in one line.
#include <archive.h>
#include <archive_entry.h>
#include <gtest/gtest.h>
#include <stdlib.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "io/archive_cache.h"
#include "io/archive_extract.h"
#include "io/volume_loader.h"
#include "loader_test_files.h"
#include "medical_test_files.h"

namespace ewa {
namespace {

namespace fs = std::filesystem;
using testing::expectLoadError;
using testing::expectVolumeLoadError;
using testing::TempDir;

struct Entry {
  Entry(std::string n, std::string b, std::string l = "")
      : name(std::move(n)), bytes(std::move(b)), linkTo(std::move(l)) {}
  std::string name;
  std::string bytes;
  std::string linkTo;  // a symbolic link when not empty
};

// Writes `entries` as a zip (".zip"), 7z (".7z") or tar compressed with xz (".tar.xz"),
// bzip2 (".tar.bz2"), zstd (".tar.zst") or gzip (any other name) with libarchive.
void writeArchive(const std::string& path, const std::vector<Entry>& entries) {
  archive* a = archive_write_new();
  auto endsWith = [&](const std::string& end) {
    return path.size() > end.size() && path.compare(path.size() - end.size(), end.size(), end) == 0;
  };
  if (endsWith(".zip")) {
    archive_write_set_format_zip(a);
  } else if (endsWith(".7z")) {
    archive_write_set_format_7zip(a);
  } else {
    archive_write_set_format_pax_restricted(a);
    if (endsWith(".tar.xz"))
      archive_write_add_filter_xz(a);
    else if (endsWith(".tar.bz2"))
      archive_write_add_filter_bzip2(a);
    else if (endsWith(".tar.zst"))
      archive_write_add_filter_zstd(a);
    else
      archive_write_add_filter_gzip(a);
  }
  ASSERT_EQ(archive_write_open_filename(a, path.c_str()), ARCHIVE_OK);
  for (const Entry& e : entries) {
    archive_entry* entry = archive_entry_new();
    archive_entry_set_pathname(entry, e.name.c_str());
    archive_entry_set_perm(entry, 0644);
    if (e.linkTo.empty()) {
      archive_entry_set_filetype(entry, AE_IFREG);
      archive_entry_set_size(entry, la_int64_t(e.bytes.size()));
    } else {
      archive_entry_set_filetype(entry, AE_IFLNK);
      archive_entry_set_symlink(entry, e.linkTo.c_str());
    }
    ASSERT_EQ(archive_write_header(a, entry), ARCHIVE_OK) << e.name;
    if (!e.bytes.empty()) {
      ASSERT_EQ(archive_write_data(a, e.bytes.data(), e.bytes.size()), la_ssize_t(e.bytes.size()));
    }
    archive_entry_free(entry);
  }
  archive_write_close(a);
  archive_write_free(a);
}

// 2 x 3 x 4 uint8, voxel n holding first + n.
std::string voxels(int first) {
  std::string bytes;
  for (int n = 0; n < 24; ++n) bytes.push_back(char(first + n));
  return bytes;
}
const std::string kHeader = "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 2 3 4\nencoding: raw\n";
std::string nrrd(int first) {
  return kHeader + "\n" + voxels(first);
}

void expectVoxels(const Volume& v, int first) {
  ASSERT_EQ(v.dims(), (std::array<int64_t, 3>{2, 3, 4}));
  for (int n = 0; n < 24; ++n) ASSERT_EQ(v.valueAt(n), first + n) << "voxel " << n;
}

// Points the temporary folder (where archives unpack) at a scratch folder for one test.
class ArchiveTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const char* old = std::getenv("TMPDIR");
    oldTmp_ = old ? old : "";
    hadTmp_ = old != nullptr;
    setenv("TMPDIR", scratch_.path("").c_str(), 1);
  }
  void TearDown() override {
    if (hadTmp_)
      setenv("TMPDIR", oldTmp_.c_str(), 1);
    else
      unsetenv("TMPDIR");
  }
  // Whatever is left in the temporary folder: nothing once a load is over.
  std::vector<std::string> leftInTemp() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(scratch_.path("")))
      names.push_back(e.path().filename().string());
    return names;
  }

  TempDir files_;  // the archives
 private:
  TempDir scratch_;  // the temporary folder while a test runs
  std::string oldTmp_;
  bool hadTmp_ = false;
};

TEST_F(ArchiveTest, EveryKindOpensItsVolumeFile) {
  for (const char* name : {"scan.zip", "scan.tar.gz", "SCAN.TGZ", "scan.tar.xz", "scan.tar.bz2",
                           "scan.tar.zst", "scan.7z"}) {
    const std::string path = files_.path(name);
    writeArchive(path, {{"notes/README.txt", "not a volume"}, {"scan/volume.nrrd", nrrd(7)}});
    const Volume v = loadVolume(path);
    expectVoxels(v, 7);
    EXPECT_NE(testing::allNotes(v).find(
                  "unpacked 2 files from the archive and opened 'scan/volume.nrrd'"),
              std::string::npos)
        << testing::allNotes(v);
    EXPECT_TRUE(leftInTemp().empty()) << name << ": the scratch folder stays";
  }
}

TEST_F(ArchiveTest, DetachedHeaderFindsItsDataBesideIt) {
  const std::string path = files_.path("detached.zip");
  writeArchive(path, {{"v/a.nhdr", kHeader + "data file: a.raw\n"}, {"v/a.raw", voxels(40)}});
  expectVoxels(loadVolume(path), 40);
}

TEST_F(ArchiveTest, DicomSeriesInAFolderOfTheZipEqualsTheFolder) {
  const std::string folder = testing::dicomSeries(files_, "series", 5);
  const Volume fromFolder = loadVolume(folder);
  // As Part 10 files, and as bare data sets named without an extension (ACR-NEMA).
  for (const bool bare : {false, true}) {
    SCOPED_TRACE(bare ? "bare" : "Part 10");
    std::vector<Entry> entries;
    for (const auto& e : fs::directory_iterator(folder))
      entries.push_back(
          {"export/series/" + e.path().stem().string() + (bare ? "" : ".dcm"),
           bare ? testing::bareDataSet(e.path().string()) : testing::fileBytes(e.path().string())});
    const std::string path = files_.path(bare ? "acr.zip" : "pacs.zip");
    writeArchive(path, entries);
    const Volume fromZip = loadVolume(path);
    ASSERT_EQ(fromZip.dims(), fromFolder.dims());
    EXPECT_EQ(fromZip.dims()[2], 5);
    EXPECT_NE(testing::allNotes(fromZip).find("opened 'export/series'"), std::string::npos);
    EXPECT_EQ(fromZip.spacing(), fromFolder.spacing());
    EXPECT_EQ(fromZip.origin(), fromFolder.origin());
    EXPECT_EQ(fromZip.bytes(), fromFolder.bytes());
    EXPECT_TRUE(leftInTemp().empty());
  }
}

TEST_F(ArchiveTest, ImageSlicesInAFolderOfTheZipOpenAsAStack) {
  std::vector<Entry> entries = {{"scan/readme.txt", "slices of a scan"}};
  for (int z : {1, 2, 10})  // natural order: z10 last
    entries.push_back(
        {"scan/z" + std::to_string(z) + ".pgm", "P5 2 2 255\n" + std::string(4, char(z))});
  const std::string path = files_.path("slices.zip");
  writeArchive(path, entries);
  const Volume v = loadVolume(path);
  EXPECT_EQ(v.dims(), (std::array<int64_t, 3>{2, 2, 3}));
  EXPECT_EQ(v.value(1, 1, 2), 10);
  EXPECT_EQ(v.value(0, 0, 1), 2);
  EXPECT_NE(testing::allNotes(v).find("opened 'scan'"), std::string::npos);
  EXPECT_TRUE(leftInTemp().empty());
}

TEST_F(ArchiveTest, NamesLeavingTheFolderAndLinksAreLeftOut) {
  const std::string path = files_.path("hostile.tar.gz");
  writeArchive(path, {{"../escape.nrrd", nrrd(1)},
                      {"/tmp/absolute.nrrd", nrrd(2)},
                      {"a/../../up.nrrd", nrrd(3)},
                      {"__MACOSX/scan/._good.nrrd", nrrd(4)},
                      {"scan/._good.nrrd", nrrd(5)},
                      {"link.nrrd", "", "/etc/passwd"},
                      {"scan/good.nrrd", nrrd(60)}});
  const ExtractedArchive unpacked = extractArchive(path);
  EXPECT_EQ(unpacked.files, 1u);
  EXPECT_EQ(unpacked.skipped, 6u);
  EXPECT_EQ(leftInTemp().size(), 1u) << "only the scratch folder: nothing escaped into its parent";
  expectVoxels(loadVolume(path), 60);
}

TEST_F(ArchiveTest, BadArchivesFailInOneLineNamingTheArchive) {
  expectVolumeLoadError(files_.write("garbage.zip", "this is not a zip file at all"),
                        "not an archive ewaview can read");
  std::string cut = [&] {
    const std::string whole = files_.path("whole.zip");
    writeArchive(whole, {{"v.nrrd", nrrd(0) + std::string(4000, 'x')}});
    std::ifstream in(whole, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }();
  cut.resize(cut.size() / 2);
  expectVolumeLoadError(files_.write("cut.zip", cut), "a damaged archive: cannot read 'v.nrrd'");

  const std::string empty = files_.path("empty.zip");
  writeArchive(empty, {});
  expectVolumeLoadError(empty, "holds no files");
  const std::string links = files_.path("links.tar.gz");
  writeArchive(links, {{"a.nrrd", "", "/etc/passwd"}});
  expectVolumeLoadError(links, "holds no files but 1 links or names outside it");

  const std::string two = files_.path("two.zip");
  writeArchive(two, {{"b.nrrd", nrrd(0)}, {"a/c.nii", "x"}});
  expectVolumeLoadError(two, "holds 2 volume files (a/c.nii, b.nrrd): unpack it and open one");

  // An entry's own problem names the entry, never the scratch folder.
  const std::string bad = files_.path("bad.zip");
  writeArchive(bad, {{"scan/v.nrrd", kHeader + "\n" + voxels(0).substr(0, 10)}});
  expectVolumeLoadError(bad, "scan/v.nrrd: ");
  try {
    loadVolume(bad);
  } catch (const LoadError& e) {
    EXPECT_EQ(std::string(e.what()).find("ewaview-archive"), std::string::npos) << e.what();
  }
  const std::string text = files_.path("text.zip");
  writeArchive(text, {{"README.txt", "hello"}});
  expectVolumeLoadError(
      text, "holds no volume file, DICOM image, TIFF file or slice image (1 other files)");
  EXPECT_TRUE(leftInTemp().empty()) << "failed loads remove the scratch folder too";
}

TEST_F(ArchiveTest, UnpackingStopsAtTheLimitsWhateverTheEntriesDeclare) {
  const std::string path = files_.path("big.zip");
  writeArchive(path, {{"a.nrrd", nrrd(0)}, {"b.raw", std::string(5000, 'b')}, {"c.txt", "c"}});
  expectLoadError(
      [&] {
        extractArchive(path, {4096, 100});
      },
      path, "unpacks to more than 4096 bytes");
  expectLoadError([&] { extractArchive(path, {0, 2}); }, path, "holds more than 2 files");
  ExtractedArchive all = extractArchive(path, {0, 3});
  EXPECT_EQ(all.files, 3u);
  EXPECT_EQ(all.bytes, nrrd(0).size() + 5001);
  const std::string folder = all.folder();
  EXPECT_TRUE(fs::is_regular_file(folder + "/b.raw"));
  {
    const ExtractedArchive moved = std::move(all);
    EXPECT_TRUE(all.folder().empty());
    EXPECT_TRUE(fs::is_regular_file(folder + "/b.raw"));
  }
  EXPECT_FALSE(fs::exists(folder)) << "the folder goes with its last owner";
}

TEST_F(ArchiveTest, TheCacheUnpacksAnArchiveOnceWhileItStaysTheSame) {
  // Two time points of a 4D NRRD: paging them unpacks once; a changed archive again.
  const std::string path = files_.path("series.tar.gz");
  const std::string head4d =
      "NRRD0004\ntype: uint8\ndimension: 4\nsizes: 2 3 4 2\nencoding: raw\n"
      "kinds: domain domain domain list\n\n";
  writeArchive(path, {{"t.nrrd", head4d + voxels(0) + voxels(100)}});
  auto cache = std::make_unique<ArchiveCache>();
  LoadOptions options;
  expectVoxels(loadVolume(path, options, cache.get()), 0);
  options.frame = 1;
  expectVoxels(loadVolume(path, options, cache.get()), 100);
  EXPECT_EQ(cache->extractions(), 1u);
  EXPECT_EQ(leftInTemp().size(), 1u) << "the kept folder";
  // Rewritten (another size): unpacked again, the old folder gone.
  writeArchive(path, {{"t.nrrd", head4d + voxels(0) + voxels(50) + "pad"}});
  expectVoxels(loadVolume(path, options, cache.get()), 50);
  EXPECT_EQ(cache->extractions(), 2u);
  EXPECT_EQ(leftInTemp().size(), 1u);
  // Another archive replaces it; a failed one keeps nothing.
  const std::string other = files_.path("other.zip");
  writeArchive(other, {{"v.nrrd", nrrd(9)}});
  options.frame = 0;
  expectVoxels(loadVolume(other, options, cache.get()), 9);
  EXPECT_EQ(leftInTemp().size(), 1u);
  expectLoadError([&] { loadVolume(files_.write("bad.zip", "nope"), options, cache.get()); },
                  files_.path("bad.zip"), "not an archive");
  EXPECT_TRUE(leftInTemp().empty());
  expectVoxels(loadVolume(other, options, cache.get()), 9);
  cache.reset();
  EXPECT_TRUE(leftInTemp().empty()) << "the cache's folder goes with it";
}

TEST_F(ArchiveTest, FoldersOfKilledProcessesAreRemovedByTheNext) {
  // A process id that is not running (the largest Linux allows, plus one), and a live one's.
  const std::string temp = fs::temp_directory_path().string();
  fs::create_directories(temp + "/ewaview-archive-4194305-abcdef/data");
  fs::create_directories(temp + "/ewaview-archive-1-abcdef");  // init: alive, not ours
  fs::create_directories(temp + "/other-folder");
  const std::string path = files_.path("v.zip");
  writeArchive(path, {{"v.nrrd", nrrd(3)}});
  expectVoxels(loadVolume(path), 3);
  std::vector<std::string> left = leftInTemp();
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"ewaview-archive-1-abcdef", "other-folder"}));
}

TEST(ArchiveNames, ByTheirSuffix) {
  for (const char* name : {"a.zip", "b.TAR.GZ", "c.tgz", "d.tar.xz", "e.7z", "f.tar", "g.tar.bz2"})
    EXPECT_TRUE(isArchiveName(name)) << name;
  for (const char* name : {"a.nii.gz", "b.gz", "zip", "c.nrrd", "d.tar.gz.part"})
    EXPECT_FALSE(isArchiveName(name)) << name;
}

}  // namespace
}  // namespace ewa
