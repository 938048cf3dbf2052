// Which pages of a multi-page TIFF make a volume: ImageJ hyperstacks and OME-TIFF's planes.
#pragma once

#include <cstdint>
#include <string>

namespace ewa {

// The planes of a TIFF as its description lays them out: the order of the Z, C (channel) and T
// (time) dimensions over the pages, fastest first, their sizes and the pixel size when given.
struct TiffPlaneOrder {
  std::string kind;           // "ImageJ", "OME" or "" (a plain stack: every page a slice)
  std::string order = "CZT";  // fastest first
  int64_t slices = 0;         // Z; 0: as many as there are pages (a plain stack)
  int64_t channels = 1;       // C, pages per channel set
  int64_t frames = 1;         // T
  double sizeX = 0.0, sizeY = 0.0, sizeZ = 0.0;  // pixel size and slice spacing; 0: not given
  std::string unit;  // of the sizes, as written ("micron", "µm"); "" when not given
};

// Reads an ImageJ description ("ImageJ=...": channels=, slices=, frames=, spacing=, unit=; its
// hyperstacks are XYCZT) or an OME-XML one (the first Pixels element: DimensionOrder, SizeZ,
// SizeC, SizeT, PhysicalSizeX/Y/Z and their units, micrometres when not named). `samples`
// (per pixel) of an RGB OME plane count among SizeC but not among the pages. Anything else,
// or a description that cannot be read, is a plain stack. Throws nothing.
TiffPlaneOrder tiffPlaneOrder(const std::string& path, const std::string& description,
                              int64_t samples);

// The slice (z) page `page` holds when it belongs to `channel` and `frame`, else -1.
int64_t tiffSliceOfPage(const TiffPlaneOrder& order, int64_t page, int64_t channel, int64_t frame);

}  // namespace ewa
