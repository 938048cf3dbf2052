// Public entry points for reading volumes from NRRD, MetaImage, .dat, VTK XML image and raw files.
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>
#include <stdexcept>
#include <string>

#include "core/volume.h"
#include "io/file_bytes.h"
#include "io/volume_layout.h"

namespace ewa {

// Thrown by every loader; what() is one line: "<path>: <problem>".
class LoadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// How to read a headerless raw file (x fastest, no padding, data from the first byte).
struct RawOptions {
  std::array<int64_t, 3> dims{0, 0, 0};
  FileScalar type = FileScalar::UInt8;  // the wide types become float32 (makeVolume)
  glm::dvec3 spacing{1.0};
  bool bigEndian = false;
};

// Parses the command-line strings "X,Y,Z", a type ("int8", "uint8", "int16", "uint16", "int32",
// "uint32", "int64", "uint64", "float32", "float64", or C's names "char", "uchar", "short",
// "ushort", "int", "uint", "float", "double"), "X,Y,Z" (or one value for all axes) and
// "little|big". An empty type,
// spacing or endian string means the default. Throws LoadError("--raw-...: problem") on bad text.
RawOptions parseRawOptions(const std::string& dims, const std::string& type,
                           const std::string& spacing, const std::string& endian);

class ArchiveCache;

// Choices inside files that hold more than one volume.
struct LoadOptions {
  std::string series;  // DICOM SeriesInstanceUID; empty: the named file's, else the largest
  int frame = 0;       // 4D NIfTI, a DICOM series of several volumes: the volume to open
  int channel = 0;     // multi-channel TIFF, RGB DICOM: the channel to open
  // Replaces the file's spacing (--spacing: image slices have none, some files a wrong one).
  std::optional<glm::dvec3> spacing;
  // Where a detached header may name its data files (--allow-outside-data: anywhere).
  DataFileScope dataFiles = DataFileScope::HeaderFolder;
  int level = 0;          // OME-Zarr: the pyramid level (0: full resolution)
  std::string dataset{};  // HDF5: the dataset's path in the file; empty: its only 3D dataset
};

// Sets `spacing` (positive and finite; throws LoadError naming `path` otherwise) with a note
// saying what the file had: what LoadOptions::spacing does, for raw files too.
void overrideSpacing(const std::string& path, Volume& volume, const glm::dvec3& spacing);

// Loads by file extension (case-insensitive): .nrrd/.nhdr (NRRD), .mhd/.mha (MetaImage),
// .dat (Voreen/Inviwo text header), .vti (VTK XML image data), .nii/.nii.gz/.hdr/.img
// (NIfTI), .dcm or any DICOM file (its series), .tif/.tiff (TIFF stack), .ome/.ome.xml (an
// OME-TIFF dataset's companion metadata), .slc (VTK SLC), .mrc/.mrcs/.map/.ccp4/.rec (MRC2014
// and CCP4 maps, cryo-EM and tomography), .zarr folders (OME-Zarr; also a Zarr array's folder
// or its .zattrs/.zarray file), .h5/.hdf5 (HDF5); a
// folder opens its DICOM series or its TIFF files; an archive (.zip, .tar, .tar.gz, .7z, ...)
// opens the one volume file or the DICOM series or TIFF stack it holds (archive_extract.h). Throws
// LoadError. Signed 8-bit data (which Volume has no type for) is widened to Int16; negative
// spacings keep their magnitude; the direction is left a rotation (a reflected one reverses the
// slices, see volume_orientation.h).
// `archives`: where the last archive unpacked is kept (the window's, so that paging its frames
// does not unpack it again); null: an archive is unpacked for this load and removed after it.
Volume loadVolume(const std::string& path, const LoadOptions& options = {},
                  ArchiveCache* archives = nullptr);

// Whether LoadOptions::level (--level) can apply to what `path` names: an OME-Zarr image (a
// folder, or its metadata file, as loadVolume opens one), an archive (it may hold one), or a
// path that does not exist (loading says so). False for any other file or folder.
bool mayHoldZarrLevels(const std::string& path);

// Loads a headerless file laid out as `options` says. The file must hold at least the
// voxels; extra trailing bytes are ignored. Throws LoadError.
Volume loadRawVolume(const std::string& path, const RawOptions& options);

}  // namespace ewa
