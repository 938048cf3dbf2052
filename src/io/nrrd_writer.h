// Encoding a volume as an attached, gzip-compressed NRRD file (--save-volume: writeVolume).
#pragma once

#include <string>

#include "core/volume.h"

namespace ewa {

// The NRRD file holding `volume`: its voxels (little-endian, gzip), sizes, spacing and direction
// as "space directions", origin, the patient frame as "space: left-posterior-superior" (else
// "3D-right-handed"), its unit as "space units", and its notes as comments. What loadVolume
// reads back is the same volume.
std::string encodeNrrd(const Volume& volume);

}  // namespace ewa
