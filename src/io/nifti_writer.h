// Writing a volume as a single-file NIfTI-1 (.nii, or .nii.gz gzip-compressed): --save-volume.
#pragma once

#include <string>

#include "core/volume.h"

namespace ewa {

// The NIfTI-1 file holding `volume` (header, empty extension flag, voxels little-endian):
// uint8, int16, uint16 or float32 as they are, no scaling. A patient-frame volume, or any
// volume placed off the identity (an origin or a direction), gets its voxel-to-world matrix as
// both the sform and the qform (code 1, scanner; NIfTI's RAS is the viewer's LPS with x and y
// negated; qform 0 when the axes are not orthogonal); a volume at the origin with the identity
// direction and no patient frame has neither, only pixdim. The unit goes in xyzt_units when
// NIfTI names it (m, mm, µm). Throws std::runtime_error("<name>: ...") for a volume NIfTI-1
// cannot hold (an axis over 32767 voxels, a spacing or origin outside float32's range).
std::string encodeNifti(const Volume& volume, const std::string& name);

}  // namespace ewa
