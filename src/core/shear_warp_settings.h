// Settings of the shear-warp renderer (CLI: --preintegrated, --table-lookup, ...).
#pragma once

#include <string>

namespace ewa {

enum class TableLookup { Nearest = 0, Bilinear = 1 };
// Where a slab's back samples wait to be its successor's front samples: two slice-sized
// buffers, or one intermediate-image-sized buffer (Schulze et al. 2003, Sec. 3.2).
enum class BufferSlices { Slice = 0, Image = 1 };

struct ShearWarpSettings {
  bool preintegrated = false;
  TableLookup lookup = TableLookup::Nearest;
  bool opacityCorrection = true;
  BufferSlices buffers = BufferSlices::Slice;
  bool runLengthEncoding = true;   // skip transparent cells (off: for tests)
  double terminationAlpha = 0.99;  // early ray termination once a pixel is this opaque
  int threads = 0;                 // 0: every hardware thread
  int tableSize = 256;             // entries per table axis, [2, 256]
};

const char* tableLookupName(TableLookup lookup);
bool parseTableLookup(const std::string& text, TableLookup* lookup);
const char* bufferSlicesName(BufferSlices buffers);
bool parseBufferSlices(const std::string& text, BufferSlices* buffers);

}  // namespace ewa
