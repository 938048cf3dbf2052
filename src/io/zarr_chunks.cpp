// Zarr chunk decoding through Debian's libblosc (blosc1), libzstd, zlib and libbz2.
#include "io/zarr_chunks.h"

#include <blosc.h>
#include <zstd.h>

#include <cstring>
#include <memory>

#include "io/decompress.h"
#include "io/load_failure.h"

namespace ewa {

namespace {

std::string bytesText(uint64_t n) {
  return std::to_string(n) + (n == 1 ? " byte" : " bytes");
}

std::vector<uint8_t> unblosc(const std::string& path, const uint8_t* data, size_t size,
                             uint64_t expected) {
  // The header's sizes first: its compressed size must be the file's, its decompressed size
  // the chunk's, before blosc reads further (blosc1's decompression trusts the header).
  size_t nbytes = 0;
  if (size < BLOSC_MIN_HEADER_LENGTH || blosc_cbuffer_validate(data, size, &nbytes) != 0)
    failLoad(path, "not a blosc chunk of " + bytesText(size) +
                       " (its header's sizes do not match the file)");
  if (nbytes != expected)
    failLoad(path, "blosc chunk holds " + bytesText(nbytes) + ", the array's chunks " +
                       bytesText(expected));
  std::vector<uint8_t> out(expected);
  // One thread and a private context: safe on the loader's worker threads, no global state.
  const int got = blosc_decompress_ctx(data, out.data(), out.size(), 1);
  if (got < 0 || uint64_t(got) != expected) failLoad(path, "corrupt blosc chunk");
  return out;
}

std::vector<uint8_t> unzstd(const std::string& path, const uint8_t* data, size_t size,
                            uint64_t expected) {
  const unsigned long long declared = ZSTD_getFrameContentSize(data, size);
  if (declared == ZSTD_CONTENTSIZE_ERROR) failLoad(path, "not a zstd chunk");
  if (declared != ZSTD_CONTENTSIZE_UNKNOWN && declared != expected)
    failLoad(path, "zstd chunk holds " + bytesText(declared) + ", the array's chunks " +
                       bytesText(expected));
  const std::unique_ptr<ZSTD_DCtx, size_t (*)(ZSTD_DCtx*)> context(ZSTD_createDCtx(),
                                                                   ZSTD_freeDCtx);
  if (!context) failLoad(path, "out of memory for zstd");
  // One byte of room beyond the chunk: data that decodes to more than it does not fit.
  std::vector<uint8_t> out(expected + 1);
  const size_t got = ZSTD_decompressDCtx(context.get(), out.data(), out.size(), data, size);
  if (ZSTD_isError(got))
    failLoad(path, std::string("corrupt zstd chunk (") + ZSTD_getErrorName(got) + ")");
  if (got != expected)
    failLoad(path, "zstd chunk holds " + std::string(got > expected ? "more than " : "") +
                       bytesText(got > expected ? expected : got) + ", the array's chunks " +
                       bytesText(expected));
  out.resize(expected);
  return out;
}

}  // namespace

uint64_t maxZarrChunkFileBytes(uint64_t expectedSize) {
  return expectedSize + expectedSize / 8 + 65536;
}

std::vector<uint8_t> decodeZarrChunk(const std::string& path, ZarrCodec codec, const uint8_t* data,
                                     size_t size, uint64_t expectedSize) {
  switch (codec) {
    case ZarrCodec::None:
      if (size != expectedSize)
        failLoad(path, "uncompressed chunk of " + bytesText(size) + ", the array's chunks " +
                           bytesText(expectedSize));
      return std::vector<uint8_t>(data, data + size);
    case ZarrCodec::Blosc:
      return unblosc(path, data, size, expectedSize);
    case ZarrCodec::Zstd:
      return unzstd(path, data, size, expectedSize);
    case ZarrCodec::Zlib:
    case ZarrCodec::Gzip:  // inflateExact tells zlib and gzip apart by their headers
      return inflateExact(path, data, size, expectedSize, "compressed data");
    case ZarrCodec::Bz2:
      return bunzip2Exact(path, data, size, expectedSize, "compressed data");
  }
  failLoad(path, "unknown compressor");
}

}  // namespace ewa
