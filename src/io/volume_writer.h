// Writing a volume in the format its file name asks for: NRRD, NIfTI, MetaImage or TIFF
// (--save-volume).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/volume.h"

namespace ewa {

enum class SavedVolumeFormat { Nrrd, Nifti, NiftiGzip, MetaImage, MetaImageHeader, Tiff };

// The endings savedVolumeFormat knows: ".nrrd", ".nii", ".nii.gz", ".mha", ".mhd", ".tif", ".tiff"
// (the save dialog's list).
std::vector<std::string> savedVolumeExtensions();
// The same for messages: ".nrrd, .nii, .nii.gz, .mha, .mhd, .tif or .tiff".
std::string savedVolumeExtensionsText();

// The format the file name of `path` ends in (one of those endings, any case, with a name before
// it), or none.
std::optional<SavedVolumeFormat> savedVolumeFormat(const std::string& path);

// The ending a new file of `format` gets: ".nrrd", ".nii.gz" (NIfTI, either), ".mha", ".mhd",
// ".tif".
std::string savedVolumeExtension(SavedVolumeFormat format);

// What the format `path` asks for cannot keep of `volume`, one note each (TIFF: tiffLosses);
// empty when it keeps what loadVolume gives back, and for a name of no format.
std::vector<std::string> savedVolumeLosses(const std::string& path, const Volume& volume);

// `volume` written to `path` atomically in the format its name asks for: a gzip NRRD
// (encodeNrrd), a NIfTI-1 or NIfTI-2 file (encodeNifti) or one gzip-compressed, or a MetaImage
// file with its data inside (encodeMetaImage), a MetaImage header and its data beside it, or an
// OME-TIFF stack (encodeTiff). A header and its data (NAME.mhd) are written as a pair: the data
// under a name the header already there does not use (NAME.raw, or NAME.1.raw when that one is
// the old header's: metaImageDataPath), then the header renamed over the old one, which is the
// moment the new pair replaces the old; then the old data file is removed. A process killed at
// any point leaves the old pair or the new one, never a header with another write's data.
// Refuses, before writing anything, to replace any of `inputs` (the files the volume was read
// from: Volume::sourceFiles). Throws std::runtime_error("<path>: ...") for another name, a
// volume the format cannot hold and a file that cannot be written.
void writeVolume(const std::string& path, const Volume& volume,
                 const std::vector<std::string>& inputs);
// The same, refusing to replace the files `volume` itself was read from.
void writeVolume(const std::string& path, const Volume& volume);

// writeVolume, then what the format left out of `volume` (savedVolumeLosses), for the caller to
// say: the command line's notes, the window's message, Python's warnings.
std::vector<std::string> writeVolumeAndLosses(const std::string& path, const Volume& volume,
                                              const std::vector<std::string>& inputs);
std::vector<std::string> writeVolumeAndLosses(const std::string& path, const Volume& volume);

// The raw data file a new MetaImage header `path` (NAME.mhd) would be written with: NAME.raw
// beside it, or NAME.1.raw where the header already at `path` names NAME.raw or NAME.raw is
// one of `inputs`.
std::string metaImageDataPath(const std::string& path, const std::vector<std::string>& inputs = {});

// The data file the MetaImage header at `path` names (resolved beside it); empty when there is
// no such header or it names none (LOCAL data, no ElementDataFile line).
std::string metaImageDataFileOf(const std::string& path);

}  // namespace ewa
