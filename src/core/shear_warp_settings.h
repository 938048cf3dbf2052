// Settings of the shear-warp renderer (CLI: --preintegrated, --table-lookup, ...).
#pragma once

#include <string>
#include <vector>

namespace ewa {

// ShearWarpSettings::intermediateScale's default: intermediate pixels a voxel at most (on the
// focal point's slice of perspective views). A picture finer than that is magnified by the warp.
// Perspective views: the default volume in the default window (7.7 pixels a voxel there)
// composited in a quarter of the picture's time against an intermediate image as fine as the
// picture, at the same RMSE against EWA (0.0010); the engine close up (under 2 there) is
// unchanged, at 1 its RMSE rises from 0.0077 to 0.0132.
constexpr double kMaxIntermediatePerVoxel = 2.0;

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
  // Most intermediate-image pixels a voxel (perspective: on the focal point's slice), >= 1,
  // where the picture is finer; 1 is Lacroute's one a voxel, whose close-ups the warp magnifies.
  double intermediateScale = kMaxIntermediatePerVoxel;
};

const char* tableLookupName(TableLookup lookup);
bool parseTableLookup(const std::string& text, TableLookup* lookup);
std::vector<std::string> tableLookupNames();  // every name parseTableLookup accepts
const char* bufferSlicesName(BufferSlices buffers);
bool parseBufferSlices(const std::string& text, BufferSlices* buffers);
std::vector<std::string> bufferSlicesNames();  // every name parseBufferSlices accepts

}  // namespace ewa
