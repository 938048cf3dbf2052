// Writing a volume in the format its file name asks for: NRRD, NIfTI or MetaImage (--save-volume).
#include "io/volume_writer.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>

#include "io/atomic_file.h"
#include "io/deflate_encode.h"
#include "io/metaimage_writer.h"
#include "io/nifti_writer.h"
#include "io/nrrd_writer.h"

namespace ewa {

namespace {

bool endsWith(const std::string& name, const std::string& suffix) {
  return name.size() > suffix.size() &&
         name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

std::optional<SavedVolumeFormat> savedVolumeFormat(const std::string& path) {
  std::string name = std::filesystem::path(path).filename().string();
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (endsWith(name, ".nrrd")) return SavedVolumeFormat::Nrrd;
  if (endsWith(name, ".nii")) return SavedVolumeFormat::Nifti;
  if (endsWith(name, ".nii.gz")) return SavedVolumeFormat::NiftiGzip;
  if (endsWith(name, ".mha")) return SavedVolumeFormat::MetaImage;
  return std::nullopt;
}

void writeVolume(const std::string& path, const Volume& volume) {
  const auto format = savedVolumeFormat(path);
  if (!format) throw std::runtime_error(path + ": volumes are saved as " + kSavedVolumeExtensions);
  if (*format == SavedVolumeFormat::Nrrd) return writeFileAtomically(path, encodeNrrd(volume));
  if (*format == SavedVolumeFormat::MetaImage)
    return writeFileAtomically(path, encodeMetaImage(volume));
  const std::string nifti = encodeNifti(volume, path);
  if (*format == SavedVolumeFormat::Nifti) return writeFileAtomically(path, nifti);
  writeFileAtomically(path,
                      gzipBytes(reinterpret_cast<const uint8_t*>(nifti.data()), nifti.size()));
}

}  // namespace ewa
