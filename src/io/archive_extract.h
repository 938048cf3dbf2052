// Archives of volumes (.zip, .tar and compressed tars, .7z): unpacked into a scratch folder.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ewa {

// Archive file names loadVolume opens (lower case, with the dot; matched as suffixes).
const std::vector<std::string>& archiveFileExtensions();
// True when the file name of `path` ends in one of archiveFileExtensions().
bool isArchiveName(const std::string& path);

// Bounds on what one archive may unpack to, counted as it is written; a size an entry declares
// is checked before it is written, never trusted. maxBytes 0: the machine's memory or the
// scratch disk's free space, whichever is smaller (a volume unpacked must also fit in memory).
// Beyond ratioFloorBytes, the archive may unpack to at most maxRatio times its own size, and
// what it has unpacked so far to at most maxRatio times the compressed bytes read so far (so a
// bomb stops near the floor, not at its whole file's ratio): real volumes compress a few times
// to a few tens of times, archive bombs a thousand times and more, and writing such a bomb out
// to the disk's limit would take minutes (libarchive and zlib advise bounding the ratio).
struct ArchiveLimits {
  uint64_t maxBytes = 0;
  uint64_t maxFiles = 100000;
  uint64_t ratioFloorBytes = 256ull << 20;
  uint64_t maxRatio = 100;
};

// A private folder (under the temporary directory, ewaview-archive-PID-XXXXXX) holding an
// archive's regular files; it and everything in it are removed when this goes away, or, when
// the process was killed first, by the next ewaview that unpacks an archive. Move-only.
class ExtractedArchive {
 public:
  // Registers `folder` for removal should a signal end the process (scratch_cleanup.h).
  explicit ExtractedArchive(std::string folder);
  ExtractedArchive(ExtractedArchive&& other) noexcept;
  ExtractedArchive& operator=(ExtractedArchive&& other) noexcept;
  ExtractedArchive(const ExtractedArchive&) = delete;
  ExtractedArchive& operator=(const ExtractedArchive&) = delete;
  ~ExtractedArchive();

  const std::string& folder() const { return folder_; }
  uint64_t files = 0;    // regular files written
  uint64_t bytes = 0;    // their bytes
  uint64_t skipped = 0;  // entries left out: links, devices, names leaving the folder

  // `message` with the scratch folder's paths made relative to the archive, so errors name
  // the entry ("data/1-1.dcm: ...") rather than a temporary path.
  std::string relative(const std::string& message) const;

 private:
  void remove();
  std::string folder_;
};

// Unpacks the regular files of the archive at `path` (zip, tar, cpio or 7z, compressed with
// gzip, bzip2, xz or zstd). Entries are written only below the scratch folder: absolute names
// and ".." are refused, links and devices skipped, as are macOS resource forks (__MACOSX/,
// "._*"). Throws LoadError("<path>: problem") for an archive that cannot be read, an encrypted
// entry, or one that unpacks beyond `limits`.
ExtractedArchive extractArchive(const std::string& path, const ArchiveLimits& limits = {});

// What in an unpacked archive to open: its one volume file with a header (.nrrd, .nhdr, .mhd,
// .mha, .dat, .vti, .nii, .nii.gz, .hdr, .slc, an OME companion .ome or .ome.xml, MRC), else the
// folder (through folders that hold nothing else) for its DICOM series or TIFF stack. Throws
// LoadError("<path>: problem") when it holds no files or several volume files.
std::string archiveVolumePath(const ExtractedArchive& archive, const std::string& path);

}  // namespace ewa
