// NIfTI-1 and NIfTI-2 headers: the fixed fields the loader needs, and the volume's placement.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "io/volume_layout.h"

namespace ewa {

constexpr size_t kNifti1Size = 348;
constexpr size_t kNifti2Size = 540;

// The fields of either header version, widened to the NIfTI-2 types.
struct NiftiHeader {
  bool nifti2 = false;
  bool analyze = false;  // an Analyze 7.5 .hdr (no NIfTI magic): no transforms, no scaling
  bool bigEndian = false;
  int64_t dim[8] = {};
  double pixdim[8] = {};
  int datatype = 0;
  double voxOffset = 0.0;
  double sclSlope = 0.0, sclInter = 0.0;
  int qformCode = 0, sformCode = 0;
  int xyztUnits = 0;  // the spatial unit in its low 3 bits: 1 metre, 2 mm, 3 micron
  double quatern[3] = {}, qoffset[3] = {};
  double srow[3][4] = {};
  std::string analyzeUnit;  // Analyze's vox_units ("mm")
};

// Parses the first bytes of a file (at least kNifti2Size when the file has them): size field
// (348 or 540, either byte order), magic, dims, type, scaling and both transforms. A .hdr of
// 348 bytes without the magic is Analyze 7.5, NIfTI-1's ancestor: dims, type and pixdim, its
// vox_units as the unit, and no transform or scaling (its orientation field is ambiguous and
// SPM's scale field is not the format's). Throws LoadError naming `path` for a file that is no
// NIfTI or is cut inside the header.
NiftiHeader parseNiftiHeader(const std::string& path, const std::vector<uint8_t>& bytes);

// Spacing, origin, direction and frame from the sform (sform_code > 0), else the qform, else
// pixdim alone; NIfTI's RAS turned into LPS; the unit from xyzt_units (none when unknown).
void placeNiftiInWorld(const NiftiHeader& header, VolumeLayout& layout);

}  // namespace ewa
