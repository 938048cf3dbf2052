// Writing a volume in the format its file name asks for: NRRD, NIfTI or MetaImage (--save-volume).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/volume.h"

namespace ewa {

enum class SavedVolumeFormat { Nrrd, Nifti, NiftiGzip, MetaImage };

// The names a volume can be saved under, for messages: ".nrrd, .nii, .nii.gz or .mha".
constexpr const char* kSavedVolumeExtensions = ".nrrd, .nii, .nii.gz or .mha";

// The endings savedVolumeFormat knows: ".nrrd", ".nii", ".nii.gz", ".mha" (the save dialog's
// list).
std::vector<std::string> savedVolumeExtensions();

// The format the file name of `path` ends in (".nrrd", ".nii", ".nii.gz", ".mha", any case,
// with a name before it), or none.
std::optional<SavedVolumeFormat> savedVolumeFormat(const std::string& path);

// `volume` written to `path` atomically in the format its name asks for: a gzip NRRD
// (encodeNrrd), a NIfTI-1 file (encodeNifti) or one gzip-compressed, or a MetaImage file with
// its data inside (encodeMetaImage). Throws
// std::runtime_error("<path>: ...") for another name, a volume the format cannot hold and a
// file that cannot be written.
void writeVolume(const std::string& path, const Volume& volume);

}  // namespace ewa
