// Zarr v2 metadata: an array's .zarray and an OME-NGFF image's multiscales in .zattrs, checked.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "io/file_scalar.h"

namespace ewa {

// How a Zarr array's chunks are compressed (numcodecs' ids).
enum class ZarrCodec { None, Blosc, Zstd, Zlib, Gzip, Bz2 };

// What a .zarray says, checked: shape and chunks positive and of one rank (1 to 32), the chunk's
// bytes within this machine's memory, a dtype ewaview reads, C order, no filters.
struct ZarrArrayMeta {
  std::vector<int64_t> shape;
  std::vector<int64_t> chunks;
  FileScalar type = FileScalar::UInt8;
  bool bigEndian = false;
  ZarrCodec codec = ZarrCodec::None;
  // The value of voxels whose chunk file is missing (fill_value; null reads as 0).
  double fillValue = 0.0;
  char separator = '.';     // dimension_separator: chunk keys "0.1.2" or "0/1/2"
  uint64_t chunkBytes = 0;  // one chunk's bytes, decompressed: product of chunks x item size
};

// Parses `text`, the .zarray at `path`. Throws LoadError("<path>: <problem>").
ZarrArrayMeta parseZarrArray(const std::string& path, const std::string& text);

// One axis of an OME-NGFF image: name ("z"), type ("space", "time", "channel" or ""), unit.
struct ZarrAxis {
  std::string name;
  std::string type;
  std::string unit;
};

// One resolution level: its array's folder (relative, checked to stay inside the image's
// folder) and the scale and translation (one value an axis; empty when not given) that place
// its voxels, the multiscale's own transformations already applied.
struct ZarrLevel {
  std::string path;
  std::vector<double> scale;
  std::vector<double> translation;
};

// The first image of an OME-NGFF "multiscales" list (versions 0.1 to 0.4): axes (0.3 names
// only; 0.1 and 0.2: none, read as t, c, z, y, x) and levels, finest first.
struct ZarrMultiscale {
  std::string name;
  std::vector<ZarrAxis> axes;
  std::vector<ZarrLevel> levels;
};

// Parses `text`, the .zattrs at `path`; nullopt when it has no "multiscales" (a plain Zarr
// group or array's attributes). Throws LoadError for a multiscales entry that is malformed.
std::optional<ZarrMultiscale> parseZarrMultiscales(const std::string& path,
                                                   const std::string& text);

}  // namespace ewa
