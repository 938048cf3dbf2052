// The per-format loaders behind loadVolume; each throws LoadError naming the file and problem.
#pragma once

#include <string>
#include <vector>

#include "core/volume.h"
#include "io/file_bytes.h"

namespace ewa {

// The detached headers below have their data files confined by `scope` (file_bytes.h).
// .nrrd, .nhdr; of a 4D file, `frame` (time, lists) or `channel` (colour, vector kinds).
Volume loadNrrd(const std::string& path, int frame, int channel,
                DataFileScope scope = DataFileScope::HeaderFolder);
// .mhd, .mha; `channel` of ElementNumberOfChannels interleaved.
Volume loadMetaImage(const std::string& path, int channel,
                     DataFileScope scope = DataFileScope::HeaderFolder);
// .dat (Voreen / Inviwo)
Volume loadDat(const std::string& path, DataFileScope scope = DataFileScope::HeaderFolder);
// .vti (VTK XML ImageData); `channel` of an array's NumberOfComponents.
Volume loadVti(const std::string& path, int channel);
// .nii, .nii.gz, .hdr/.img (NIfTI-1 and -2); `frame` of a 4D file, `channel` of RGB and RGBA.
Volume loadNifti(const std::string& path, int frame, int channel);
Volume loadSlc(const std::string& path);  // .slc (VTK SLC)
Volume loadMrc(const std::string& path);  // .mrc .mrcs .map .ccp4 .rec (MRC2014, CCP4)
// .vtk (legacy VTK, STRUCTURED_POINTS); `channel` of SCALARS' components.
Volume loadVtkLegacy(const std::string& path, int channel);
// A DICOM series: `path` is a folder or one file of the series; `series` a SeriesInstanceUID
// or empty (the named file's series, else the folder's series with the most slices);
// `channel` of RGB images; `frame`, of a series holding several volumes at the same positions
// (diffusion directions, echoes, time points: dicom_volumes.h), the volume to open.
Volume loadDicom(const std::string& path, const std::string& series, int channel, int frame);
// A multi-page TIFF, or a folder of single-page TIFFs; `channel` of multi-channel data.
// `frame`: an ImageJ hyperstack's or OME-TIFF's time point.
Volume loadTiff(const std::string& path, int channel, int frame);
// An OME-XML companion file (.companion.ome, .ome.xml) of an OME-TIFF dataset over several files.
Volume loadOmeCompanion(const std::string& path, int channel, int frame);

// An OME-Zarr image (Zarr v2: a folder with .zattrs multiscales, or a bare array's folder with
// .zarray) at pyramid `level`; `frame` and `channel` of its time and channel axes. Chunk files
// are confined to the image's folder by `scope`. region_read.h reads a box of it.
Volume loadZarr(const std::string& path, int level, int frame, int channel,
                DataFileScope scope = DataFileScope::HeaderFolder);
// True for a Zarr image or array: a folder holding .zattrs, .zgroup or .zarray, or such a file.
bool isZarrPath(const std::string& path);
// .h5, .hdf5: the 3D dataset `dataset` (a path inside the file; "": the file's only 3D one).
Volume loadHdf5(const std::string& path, const std::string& dataset);

// Ordinary images as slices (PNG, 8 or 16 bits; JPEG; BMP; PGM/PPM): the images of a folder, or
// of the named image's folder, in natural name order; `channel` of colour images.
Volume loadImageStack(const std::string& path, int channel);
// The file names loadImageStack reads.
const std::vector<std::string>& sliceImageExtensions();

// True when the file starts like DICOM: Part 10 ("DICM" at byte 128), or a bare data set from
// byte 0 as ACR-NEMA files hold one (its first two elements, group 0008, in tag order), looked
// for only in files named as DICOM files are (mayBeDicomByName, .dcm, .ima, .acr, ...).
bool looksLikeDicom(const std::string& path);

}  // namespace ewa
