// Writing a volume in the format its file name asks for: NRRD, NIfTI, MetaImage or TIFF
// (--save-volume).
#include "io/volume_writer.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <utility>

#include "io/atomic_file.h"
#include "io/deflate_encode.h"
#include "io/input_guard.h"
#include "io/metaimage_writer.h"
#include "io/nifti_writer.h"
#include "io/nrrd_writer.h"
#include "io/text_fields.h"
#include "io/tiff_writer.h"

namespace ewa {

namespace {

// Each format by the ending of its names.
const std::pair<const char*, SavedVolumeFormat> kFormats[] = {
    {".nrrd", SavedVolumeFormat::Nrrd},
    {".nii", SavedVolumeFormat::Nifti},
    {".nii.gz", SavedVolumeFormat::NiftiGzip},
    {".mha", SavedVolumeFormat::MetaImage},
    {".mhd", SavedVolumeFormat::MetaImageHeader},
    {".tif", SavedVolumeFormat::Tiff},
    {".tiff", SavedVolumeFormat::Tiff}};

// The second name of a header's data file: NAME.1.raw, used when NAME.raw is the old pair's.
std::string pairedName(const std::string& path) {
  return std::filesystem::path(path).replace_extension(".1.raw").string();
}

}  // namespace

std::vector<std::string> savedVolumeExtensions() {
  std::vector<std::string> out;
  for (const auto& [suffix, format] : kFormats) out.emplace_back(suffix);
  return out;
}

std::string savedVolumeExtensionsText() {
  const std::vector<std::string> endings = savedVolumeExtensions();
  std::string out;
  for (size_t n = 0; n < endings.size(); ++n)
    out += (n == 0 ? "" : n + 1 == endings.size() ? " or " : ", ") + endings[n];
  return out;
}

std::optional<SavedVolumeFormat> savedVolumeFormat(const std::string& path) {
  const std::string name = toLower(std::filesystem::path(path).filename().string());
  for (const auto& [suffix, format] : kFormats) {
    const size_t n = std::char_traits<char>::length(suffix);
    if (name.size() > n && name.compare(name.size() - n, n, suffix) == 0) return format;
  }
  return std::nullopt;
}

std::string savedVolumeExtension(SavedVolumeFormat format) {
  switch (format) {
    case SavedVolumeFormat::Nrrd:
      return ".nrrd";
    case SavedVolumeFormat::Nifti:
    case SavedVolumeFormat::NiftiGzip:
      return ".nii.gz";
    case SavedVolumeFormat::MetaImage:
      return ".mha";
    case SavedVolumeFormat::MetaImageHeader:
      return ".mhd";
    case SavedVolumeFormat::Tiff:
      return ".tif";
  }
  return ".nrrd";
}

std::vector<std::string> savedVolumeLosses(const std::string& path, const Volume& volume) {
  const auto format = savedVolumeFormat(path);
  if (format == SavedVolumeFormat::Tiff) return tiffLosses(volume);
  if ((format == SavedVolumeFormat::Nifti || format == SavedVolumeFormat::NiftiGzip) &&
      needsNifti2(volume))
    return {
        "NIfTI-2, not NIfTI-1: an axis over 32767 voxels, or a spacing or origin beyond "
        "float32, which NIfTI-1 cannot hold (tools that read NIfTI-1 only will not open it)"};
  return {};
}

void writeVolume(const std::string& path, const Volume& volume) {
  writeVolume(path, volume, volume.sourceFiles());
}

void writeVolume(const std::string& path, const Volume& volume,
                 const std::vector<std::string>& inputs) {
  const auto format = savedVolumeFormat(path);
  if (!format)
    throw std::runtime_error(path + ": volumes are saved as " + savedVolumeExtensionsText());
  refuseToReplaceInputs(path, inputs);
  if (*format == SavedVolumeFormat::Nrrd) return writeFileAtomically(path, encodeNrrd(volume));
  if (*format == SavedVolumeFormat::MetaImage)
    return writeFileAtomically(path, encodeMetaImage(volume));
  if (*format == SavedVolumeFormat::MetaImageHeader) {
    // The data first, under a name the old header does not use: the header's rename is the one
    // step that swaps the old pair for the new.
    const std::string old = metaImageDataFileOf(path);
    const std::string data = metaImageDataPath(path, inputs);
    refuseToReplaceInputs(data, inputs);
    const std::vector<uint8_t> bytes = metaImageData(volume);
    writeFileAtomically(
        data, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
    writeFileAtomically(
        path, encodeMetaImageHeader(volume, std::filesystem::path(data).filename().string()));
    // The old data, only where it is one of the names this writer gives and no input.
    const std::vector<std::string> ours = {
        std::filesystem::path(path).replace_extension(".raw").string(), pairedName(path)};
    if (!old.empty() && !sameExistingFile(old, data) &&
        std::any_of(ours.begin(), ours.end(), [&](const std::string& n) { return n == old; }) &&
        std::none_of(inputs.begin(), inputs.end(),
                     [&](const std::string& in) { return sameExistingFile(in, old); })) {
      std::error_code ec;
      std::filesystem::remove(old, ec);
    }
    return;
  }
  if (*format == SavedVolumeFormat::Tiff)
    return writeFileAtomically(path, encodeTiff(volume, path));
  const std::string nifti = encodeNifti(volume);
  if (*format == SavedVolumeFormat::Nifti) return writeFileAtomically(path, nifti);
  writeFileAtomically(path,
                      gzipBytes(reinterpret_cast<const uint8_t*>(nifti.data()), nifti.size()));
}

std::vector<std::string> writeVolumeAndLosses(const std::string& path, const Volume& volume,
                                              const std::vector<std::string>& inputs) {
  writeVolume(path, volume, inputs);
  return savedVolumeLosses(path, volume);
}

std::vector<std::string> writeVolumeAndLosses(const std::string& path, const Volume& volume) {
  return writeVolumeAndLosses(path, volume, volume.sourceFiles());
}

std::string metaImageDataPath(const std::string& path, const std::vector<std::string>& inputs) {
  const std::string first = std::filesystem::path(path).replace_extension(".raw").string();
  const std::string old = metaImageDataFileOf(path);
  const bool taken = (!old.empty() && (old == first || sameExistingFile(old, first))) ||
                     std::any_of(inputs.begin(), inputs.end(), [&](const std::string& in) {
                       return in == first || sameExistingFile(in, first);
                     });
  return taken ? pairedName(path) : first;
}

std::string metaImageDataFileOf(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return "";
  std::ifstream in(path, std::ios::binary);
  std::string line;
  // A header is a few hundred bytes; a line this far in is no header line of ours.
  for (int n = 0; n < 64 && std::getline(in, line); ++n) {
    const size_t eq = line.find('=');
    if (eq == std::string::npos) continue;
    if (toLower(trim(line.substr(0, eq))) != "elementdatafile") continue;
    const std::string name = trim(line.substr(eq + 1));
    if (name.empty() || toLower(name) == "local") return "";
    return (std::filesystem::path(path).parent_path() / name).string();
  }
  return "";
}

}  // namespace ewa
