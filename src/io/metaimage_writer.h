// Encoding a volume as MetaImage: one file with its data inside (.mha, zlib), or a header
// (.mhd) and its raw data beside it: --save-volume.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

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

// The .mhd header of a detached pair: the same fields, uncompressed, ElementDataFile naming
// `dataFile` (a file beside the header that holds metaImageData).
std::string encodeMetaImageHeader(const Volume& volume, const std::string& dataFile);

// The voxels as MetaImage stores them: little-endian, in the volume's type.
std::vector<uint8_t> metaImageData(const Volume& volume);

}  // namespace ewa
