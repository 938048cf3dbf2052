// File listing for the open dialog, through std::filesystem.
#include "io/file_listing.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>

#include "io/archive_extract.h"
#include "io/format_loaders.h"
#include "io/text_fields.h"

namespace ewa {

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

const std::vector<std::string>& volumeFileExtensions() {
  static const std::vector<std::string> kExtensions = [] {
    std::vector<std::string> all = {".nrrd", ".nhdr",   ".mhd",     ".mha", ".dat", ".vti",  ".vtk",
                                    ".nii",  ".nii.gz", ".hdr",     ".img", ".dcm", ".ima",  ".tif",
                                    ".tiff", ".ome",    ".ome.xml", ".slc", ".mrc", ".mrcs", ".map",
                                    ".ccp4", ".rec",    ".h5",      ".hdf5"};
    const std::vector<std::string>& archives = archiveFileExtensions();
    all.insert(all.end(), archives.begin(), archives.end());
    const std::vector<std::string>& images = sliceImageExtensions();
    all.insert(all.end(), images.begin(), images.end());
    return all;
  }();
  return kExtensions;
}

bool hasExtension(const std::string& path, const std::vector<std::string>& extensions) {
  // By suffix, so that two-part extensions (".nii.gz") match too.
  const std::string name = lower(std::filesystem::path(path).filename().string());
  return std::any_of(extensions.begin(), extensions.end(), [&](const std::string& ext) {
    return name.size() > ext.size() && name.compare(name.size() - ext.size(), ext.size(), ext) == 0;
  });
}

bool mayBeDicomByName(const std::string& name) {
  if (hasExtension(name, {".dcm", ".dicom", ".dic", ".ima", ".acr", ".nema"})) return true;
  const size_t dot = name.rfind('.');
  if (dot == std::string::npos || dot == 0) return true;
  const std::string ext = name.substr(dot + 1);
  return !ext.empty() && std::all_of(ext.begin(), ext.end(), [](char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
  });
}

std::vector<DirEntry> listDirectory(const std::string& dir,
                                    const std::vector<std::string>& extensions, bool showHidden,
                                    bool dicomByContent) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec);
  if (ec) throw std::runtime_error(dir + ": cannot list: " + ec.message());
  std::vector<DirEntry> dirs, files;
  int sniffed = 0;
  for (; it != fs::directory_iterator(); it.increment(ec)) {
    if (ec) break;
    const std::string name = it->path().filename().string();
    if (!showHidden && !name.empty() && name[0] == '.') continue;
    std::error_code statError;
    if (it->is_directory(statError)) {
      dirs.push_back({name, true, 0});
    } else if (it->is_regular_file(statError)) {
      bool listed = extensions.empty() || hasExtension(name, extensions);
      // Read at most 4 KiB of a bounded number of files: the dialog lists on the UI thread.
      if (!listed && dicomByContent && mayBeDicomByName(name) && sniffed++ < kDicomSniffLimit) {
        try {
          listed = looksLikeDicom(it->path().string());
        } catch (const std::exception&) {  // unreadable: not listed
        }
      }
      if (listed) files.push_back({name, false, it->file_size(statError)});
    }
  }
  auto byName = [](const DirEntry& a, const DirEntry& b) { return a.name < b.name; };
  std::sort(dirs.begin(), dirs.end(), byName);
  std::sort(files.begin(), files.end(), byName);
  dirs.insert(dirs.end(), files.begin(), files.end());
  return dirs;
}

std::vector<std::string> sliceFilesIn(const std::string& dir,
                                      const std::vector<std::string>& extensions) {
  std::vector<std::string> paths;
  for (const DirEntry& e : listDirectory(dir, extensions))
    if (!e.directory) paths.push_back((std::filesystem::path(dir) / e.name).string());
  std::sort(paths.begin(), paths.end(), naturalLess);
  return paths;
}

}  // namespace ewa
