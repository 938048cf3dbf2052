// Encoding a volume as a MetaImage file with its data inside (.mha, zlib): --save-volume.
#pragma once

#include <string>

#include "core/volume.h"

namespace ewa {

// The .mha file holding `volume` as ITK writes one: ObjectType Image, 3 dims, its voxels
// little-endian in the volume's type (MET_UCHAR, MET_SHORT, MET_USHORT, MET_FLOAT),
// zlib-compressed after the header (ElementDataFile = LOCAL); ElementSpacing, Offset (the
// origin) and TransformMatrix (each axis's direction in turn, ITK's LPS world) written to the
// last digit; a patient-frame volume gets AnatomicalOrientation (the side each axis comes
// from, RAI for the identity), which loadVolume reads as patient axes. MetaImage has no unit
// or notes: they are not written.
std::string encodeMetaImage(const Volume& volume);

}  // namespace ewa
