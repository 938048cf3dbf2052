// Encoding a volume as an OME-TIFF stack through libtiff (.tif, .tiff): --save-volume.
#pragma once

#include <string>
#include <vector>

#include "core/volume.h"

namespace ewa {

// The OME-TIFF file holding `volume`: one page a slice (z), rows from y = 0, in the volume's
// type (8 or 16 bits unsigned, 16 bits signed, 32-bit float), deflate-compressed (integers
// with the horizontal predictor), and the first page's description the OME-XML that names the
// pixel size and slice spacing with their unit (`reference frame` when the volume has none or
// one OME does not name) as Fiji (Bio-Formats), tifffile, napari and QuPath read it, and, for
// an origin not at zero, each slice's Plane position in that unit. The
// resolution tags hold the pixel size too (per centimetre for a length unit), for readers
// that know no OME. The file name of `path` is the Image's name in the XML. BigTIFF past 4 GB.
// Throws std::runtime_error("<path>: ...") when libtiff refuses.
std::string encodeTiff(const Volume& volume, const std::string& path);

// What a TIFF cannot keep of `volume`, for a note: its axes when turned against the world's or in a
// patient frame, and a unit OME does not name. Empty when it keeps everything loadVolume gives
// back.
std::vector<std::string> tiffLosses(const Volume& volume);

}  // namespace ewa
