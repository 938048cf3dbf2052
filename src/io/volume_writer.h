// Writing a volume in the format its file name asks for: NRRD or NIfTI (--save-volume, Save).
#pragma once

#include <optional>
#include <string>

#include "core/volume.h"

namespace ewa {

enum class SavedVolumeFormat { Nrrd, Nifti, NiftiGzip };

// The names a volume can be saved under, for messages: ".nrrd, .nii or .nii.gz".
constexpr const char* kSavedVolumeExtensions = ".nrrd, .nii or .nii.gz";

// The format the file name of `path` ends in (".nrrd", ".nii", ".nii.gz", any case, with a
// name before it), or none.
std::optional<SavedVolumeFormat> savedVolumeFormat(const std::string& path);

// `volume` written to `path` atomically in the format its name asks for: a gzip NRRD
// (encodeNrrd), a NIfTI-1 file (encodeNifti) or one gzip-compressed. Throws
// std::runtime_error("<path>: ...") for another name, a volume the format cannot hold and a
// file that cannot be written.
void writeVolume(const std::string& path, const Volume& volume);

}  // namespace ewa
