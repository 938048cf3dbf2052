// Siemens mosaics: one image holding a volume's slices as tiles (syngo MR's EPI, DTI, fMRI).
#pragma once

#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "io/dicom_series.h"

namespace ewa {

// How a mosaic holds its slices: `count` tiles of tileColumns x tileRows, `perRow` to a row of
// the image (ceil(sqrt(count)), as dcm2niix and nibabel lay them out), stored slice k at
// first + k * spacing * (reversed ? -normal : normal), normal = row x column cosines.
struct DicomMosaic {
  int64_t count = 0, perRow = 0, tileColumns = 0, tileRows = 0;
  glm::dvec3 first{0.0};  // the first stored slice's first voxel
  double spacing = 1.0;   // SpacingBetweenSlices, else SliceThickness, else 1 (spacingAssumed)
  bool spacingAssumed = false;
  bool reversed = false;  // the CSA SliceNormalVector points against row x column
};

// `file`'s mosaic, when it is one (ImageType holds MOSAIC, DicomSlice::mosaic, and its CSA
// image header (0029,xx10 of the "SIEMENS CSA HEADER" block) gives NumberOfImagesInMosaic over
// 1); else nullopt. The image's position is its top left corner, as if it were one slice: the
// first tile's is moved to the centre's offset, as dcm2niix does. Throws LoadError naming the
// file when the tiles do not fit the image.
std::optional<DicomMosaic> dicomMosaic(const DicomSlice& file);

// A series of mosaics (one a time point or diffusion direction): the one of `volume`, in
// InstanceNumber order (then by file name), with a note when there are several; `count` gets
// how many. Throws LoadError naming `path` for `volume` out of range.
DicomSlice selectMosaicVolume(const std::string& path, std::vector<DicomSlice> files, int volume,
                              std::vector<std::string>& notes, int* count);

// The mosaic image's `values` (its columns x rows) as its slices' planes, ordered along the
// normal (stored order, or reversed).
std::vector<double> mosaicPlanes(const std::vector<double>& values, int64_t columns,
                                 const DicomMosaic& mosaic);

}  // namespace ewa
