// The per-format loaders behind loadVolume; each throws LoadError naming the file and problem.
#pragma once

#include <string>

#include "core/volume.h"

namespace ewa {

Volume loadNrrd(const std::string& path);       // .nrrd, .nhdr
Volume loadMetaImage(const std::string& path);  // .mhd, .mha
Volume loadDat(const std::string& path);        // .dat (Voreen / Inviwo)
Volume loadVti(const std::string& path);        // .vti (VTK XML ImageData)

}  // namespace ewa
