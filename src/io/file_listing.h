// File listing for the open dialog: folders and volume files of one folder (no UI).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ewa {

struct DirEntry {
  std::string name;  // file name only
  bool directory = false;
  uintmax_t size = 0;  // bytes (files)
};

// Extensions loadVolume reads, archives included (lower case, with the dot).
const std::vector<std::string>& volumeFileExtensions();
// True when the file name of `path` ends in one of `extensions` (case-insensitive).
bool hasExtension(const std::string& path, const std::vector<std::string>& extensions);

// Folders (sorted by name) then files whose extension is in `extensions` (sorted; all files
// when `extensions` is empty). With `dicomByContent`, files named as DICOM files are
// (mayBeDicomByName: scanners name them IM0001 or by their UID, 1.2.840.113619.2.1.5) are
// listed too when they start like DICOM (the first kDicomSniffLimit such files looked into).
// Names starting with '.' are left out unless `showHidden`; unreadable entries are skipped.
// Throws std::runtime_error("dir: problem") when the folder cannot be read.
std::vector<DirEntry> listDirectory(const std::string& dir,
                                    const std::vector<std::string>& extensions,
                                    bool showHidden = false, bool dicomByContent = false);
constexpr int kDicomSniffLimit = 1000;

// Whether a file is named as DICOM files are: no extension or a number for one (IM0001, a UID),
// or .dcm, .dicom, .dic, .ima, .acr (ACR-NEMA), .nema.
bool mayBeDicomByName(const std::string& name);

// The paths of the files in `dir` whose extension is in `extensions`, in natural name order
// ("z2" before "z10"): a stack's slices. Hidden files are left out (macOS leaves "._NAME"
// beside each file it copies). Throws as listDirectory does.
std::vector<std::string> sliceFilesIn(const std::string& dir,
                                      const std::vector<std::string>& extensions);

}  // namespace ewa
