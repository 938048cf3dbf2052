// Which pages of a multi-page TIFF make a volume: ImageJ hyperstacks and OME-TIFF's planes.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace ewa {

// One OME TiffData element: `planeCount` planes from (firstZ, firstC, firstT) on, in the
// dimension order, held by pages ifd, ifd + 1, ... of `file` (a name in the folder of the file
// holding the XML; empty: that file).
struct TiffDataBlock {
  std::string file;
  int64_t ifd = 0;
  int64_t firstZ = 0, firstC = 0, firstT = 0;
  int64_t planeCount = -1;  // -1: not given (the schema's default: 1 with an IFD, else every page)
  bool ifdGiven = false;
};

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
  // Where the first slice lies (OME's Plane TheZ 0, TheC 0, TheT 0: PositionX/Y/Z), in `unit`;
  // absent from ImageJ's descriptions, and when a position's unit cannot be given in `unit`.
  bool hasOrigin = false;
  std::array<double, 3> origin{};
  // OME's TiffData elements, kept only when one names another file (a dataset split over
  // several files: by channel, time point or size); else the pages follow the order above.
  std::vector<TiffDataBlock> blocks;
};

// Where a slice lies in an OME dataset of several files.
struct TiffPlaneSource {
  std::string file;  // the path to open
  int64_t ifd = 0;   // its page
};

// Reads an ImageJ description ("ImageJ=...": channels=, slices=, frames=, spacing=, unit=; its
// hyperstacks are XYCZT) or an OME-XML one (the first Pixels element: DimensionOrder, SizeZ,
// SizeC, SizeT, PhysicalSizeX/Y/Z and their units, micrometres when not named; the first
// plane's PositionX/Y/Z in theirs, OME's "reference frame" when not named). `samples`
// (per pixel) of an RGB OME plane count among SizeC but not among the pages. Anything else,
// or a description that cannot be read, is a plain stack. Throws nothing.
TiffPlaneOrder tiffPlaneOrder(const std::string& path, const std::string& description,
                              int64_t samples);

// `name` (a TiffData's FileName, a BinaryOnly's MetadataFile) as the path of a file beside
// `xmlFile` (siblingPath). Names with folders in them, "." and ".." are refused:
// LoadError("<path>: <namer> names 'NAME', not a file beside it").
std::string omeFileBeside(const std::string& path, const std::string& xmlFile,
                          const std::string& name, const std::string& namer);

// The file and page of every slice of `channel` and `frame` by `order.blocks`, for the dataset
// whose XML is in `path`. `pagesIn(file)` counts a file's pages (0 when it cannot be opened).
// Throws LoadError("<path>: ...") for a file name leaving the folder, or a file missing that
// holds a wanted plane. Slices no block holds are absent from the map (slice z: its source).
std::map<int64_t, TiffPlaneSource> omePlaneSources(
    const std::string& path, const TiffPlaneOrder& order, int64_t channel, int64_t frame,
    const std::function<int64_t(const std::string&)>& pagesIn);

// The companion file an OME-TIFF's description names when it carries no metadata of its own
// (`<BinaryOnly MetadataFile="x.companion.ome"/>`), else "". Throws nothing.
std::string omeMetadataFile(const std::string& description);

// The slice (z) page `page` holds when it belongs to `channel` and `frame`, else -1.
int64_t tiffSliceOfPage(const TiffPlaneOrder& order, int64_t page, int64_t channel, int64_t frame);

}  // namespace ewa
