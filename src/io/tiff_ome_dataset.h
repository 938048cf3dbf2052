// OME-TIFF datasets over several files: the slices their TiffData elements place.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/tiff_pages.h"
#include "io/tiff_planes.h"
#include "io/volume_layout.h"

namespace ewa {

// Pages in a file, or 0 when it is missing or not a TIFF file.
int64_t tiffPageCount(const std::string& file);

// An OME-TIFF dataset over several files (its XML in `xmlFile`): each slice of `planeChannel`
// and `frame` from the file and page its TiffData names, every page like `format` (`sample`:
// the sample of a pixel to read). Adds a note to `layout`; errors start with `path`.
std::vector<uint8_t> readOmeDataset(const std::string& path, const std::string& xmlFile,
                                    const TiffPlaneOrder& order, const PageFormat& format,
                                    int64_t planeChannel, int sample, int64_t frame,
                                    VolumeLayout& layout);

}  // namespace ewa
