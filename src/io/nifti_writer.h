// Writing a volume as a single-file NIfTI-1, or NIfTI-2 where it must (.nii, .nii.gz):
// --save-volume.
#pragma once

#include <string>

#include "core/volume.h"

namespace ewa {

// The NIfTI file holding `volume` (header, empty extension flag, voxels little-endian):
// uint8, int16, uint16 or float32 as they are, no scaling. NIfTI-1, or NIfTI-2 (its 540-byte
// header of 64-bit dims and doubles) for a volume NIfTI-1 cannot hold: an axis over 32767
// voxels, a spacing or origin outside float32's range (needsNifti2). A patient-frame volume,
// or any volume placed off the identity (an origin or a direction), gets its voxel-to-world
// matrix as both the sform and the qform (code 1, scanner; NIfTI's RAS is the viewer's LPS
// with x and y negated; qform 0 when the axes are not orthogonal); a volume at the origin with
// the identity direction and no patient frame has neither, only pixdim. The unit goes in
// xyzt_units when NIfTI names it (m, mm, µm).
std::string encodeNifti(const Volume& volume);

// Whether `volume` needs NIfTI-2: an axis over 32767 voxels, or a spacing or origin that
// NIfTI-1's float32 fields cannot hold.
bool needsNifti2(const Volume& volume);

}  // namespace ewa
