// Parsing of NRRD headers (attached .nrrd or detached .nhdr) into what the NRRD loader needs.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/nrrd_axes.h"
#include "io/volume_layout.h"

namespace ewa {

// How the data are written: bytes as they are, compressed, or as text (ascii: numbers between
// white space; hex: two hex digits a byte).
enum class NrrdEncoding { Raw, Gzip, Bzip2, Ascii, Hex };

struct NrrdHeader {
  VolumeLayout layout;         // the spatial sizes padded to 3D, spacing, origin, type, endian
  int dimension = 0;           // as written (1..4)
  std::vector<int64_t> sizes;  // as written, every axis (data file subdimensions count them)
  NrrdExtraAxis extra;         // a 4D file's axis that is not spatial
  NrrdEncoding encoding = NrrdEncoding::Raw;
  int64_t byteSkip = 0;  // -1: data ends at the end of the file (raw only)
  int64_t lineSkip = 0;
  std::vector<std::string> dataFiles;  // paths resolved against the header; empty: attached
  int subdim = 0;                      // axes held by each data file; 0: split evenly
  uint64_t attachedOffset = 0;         // where attached data starts (after the blank line)
};

// Reads and checks the header at `path`. Throws LoadError("<path>: <problem>").
NrrdHeader parseNrrdHeader(const std::string& path);

// Expands a "data file" pattern such as "slice.%03d" for one index; only one %d/%i/%u
// conversion (with flags and width) and "%%" are allowed, so the text is never given to printf.
std::string formatNrrdPattern(const std::string& path, const std::string& pattern, int64_t index);

}  // namespace ewa
