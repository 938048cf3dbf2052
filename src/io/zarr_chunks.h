// Decoding one Zarr chunk file's bytes (blosc, zstd, zlib, gzip, bz2 or none) to its exact size.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "io/zarr_metadata.h"

namespace ewa {

// The chunk's bytes as stored: `data`/`size` decompressed with `codec` to exactly
// `expectedSize` bytes (a chunk's full shape: Zarr v2 pads the chunks at the array's edge).
// Throws LoadError("<path>: <problem>") for corrupt data, or data that decodes to more or fewer
// bytes; what a codec's header claims is checked before anything is allocated from it.
std::vector<uint8_t> decodeZarrChunk(const std::string& path, ZarrCodec codec, const uint8_t* data,
                                     size_t size, uint64_t expectedSize);

// The largest chunk file read for a chunk of `expectedSize` bytes: no codec makes incompressible
// data grow by more than a little, so a bigger file is not a chunk of this array.
uint64_t maxZarrChunkFileBytes(uint64_t expectedSize);

}  // namespace ewa
