// zlib/gzip inflation bounded by the size a header promises: no more, no less, no huge buffers.
#include "io/decompress.h"

#include <zlib.h>

#include <algorithm>

#include "io/load_failure.h"
#include "io/memory_limit.h"
#include "io/zlib_inflater.h"

namespace ewa {

namespace {

// Deflate cannot expand data by more than about 1032:1; beyond that a header is lying.
constexpr uint64_t kMaxRatio = 1032;
// zlib counts in uInt; feed and drain it in pieces it can count.
constexpr size_t kMaxChunk = size_t{1} << 30;

}  // namespace

std::vector<uint8_t> inflateExact(const std::string& path, const uint8_t* data, size_t size,
                                  uint64_t expectedSize, const std::string& what) {
  const std::string prefix = what + ": ";
  checkAllocation(path, expectedSize, what + " after decompression");
  if (expectedSize / kMaxRatio > size + 64) {
    failLoad(path, prefix + std::to_string(size) + " compressed bytes cannot inflate to the " +
                       std::to_string(expectedSize) + " bytes the header promises");
  }
  ZlibInflater inflater(15 + 32);  // maximum window, zlib or gzip header detected
  if (!inflater.ok()) failLoad(path, prefix + "cannot start zlib");
  z_stream& zs = inflater.stream();

  const auto expected = static_cast<size_t>(expectedSize);
  std::vector<uint8_t> out(std::min<size_t>(expected, std::max<size_t>(size_t{1} << 20, size * 4)));
  size_t produced = 0;
  const uint8_t* in = data;
  size_t inLeft = size;
  uint8_t probe = 0;
  bool newMember = false;  // true right after a gzip member ended: what follows may be junk
  const auto shortBy = [&] {
    return prefix + "inflates to only " + std::to_string(produced) + " bytes, expected " +
           std::to_string(expected) + " (truncated or wrong sizes?)";
  };

  while (true) {
    // Once the expected bytes are out, inflate into a 1-byte probe to catch surplus data.
    const bool probing = produced == expected;
    if (!probing && produced == out.size()) {
      out.resize(std::min(expected, out.size() > expected / 2 ? expected : out.size() * 2));
    }
    if (zs.avail_in == 0 && inLeft > 0) {
      const size_t chunk = std::min(inLeft, kMaxChunk);
      zs.next_in = const_cast<Bytef*>(in);
      zs.avail_in = static_cast<uInt>(chunk);
      in += chunk;
      inLeft -= chunk;
    }
    const size_t room = probing ? 1 : std::min(out.size() - produced, kMaxChunk);
    zs.next_out = probing ? &probe : out.data() + produced;
    zs.avail_out = static_cast<uInt>(room);
    const int ret = inflate(&zs, Z_NO_FLUSH);
    const size_t got = room - zs.avail_out;
    if (probing && got > 0) {
      failLoad(path, prefix + "inflates to more than the expected " + std::to_string(expected) +
                         " bytes");
    }
    produced += got;
    if (got > 0) newMember = false;

    switch (ret) {
      case Z_OK:
        continue;
      case Z_STREAM_END:
        if (produced == expected) return out;
        if (zs.avail_in == 0 && inLeft == 0) failLoad(path, shortBy());
        // Another gzip member may follow (as `cat a.gz b.gz` makes).
        if (inflateReset(&zs) != Z_OK) failLoad(path, prefix + "cannot restart zlib");
        newMember = true;
        continue;
      case Z_BUF_ERROR:
        // No progress possible: input used up before the stream's end.
        if (zs.avail_in == 0 && inLeft == 0) {
          if (produced < expected) failLoad(path, shortBy());
          failLoad(path, prefix + "truncated (the end of the compressed stream is missing)");
        }
        failLoad(path, prefix + "zlib made no progress");
      case Z_DATA_ERROR:
        if (newMember) failLoad(path, shortBy());
        failLoad(path,
                 prefix + "corrupt (" + std::string(zs.msg ? zs.msg : "invalid stream") + ")");
      case Z_NEED_DICT:
        failLoad(path, prefix + "needs a preset dictionary");
      case Z_MEM_ERROR:
        failLoad(path, prefix + "out of memory while inflating");
      default:
        failLoad(path, prefix + "zlib error " + std::to_string(ret));
    }
  }
}

std::vector<uint8_t> inflatePrefix(const std::string& path, const uint8_t* data, size_t size,
                                   uint64_t maxBytes, const std::string& what) {
  return inflateWindow(path, data, size, 0, maxBytes, what);
}

std::vector<uint8_t> inflateWindow(const std::string& path, const uint8_t* data, size_t size,
                                   uint64_t skip, uint64_t maxBytes, const std::string& what) {
  const std::string prefix = what + ": ";
  if (skip > maxBytes) skip = maxBytes;
  checkAllocation(path, maxBytes - skip, what + " after decompression");
  ZlibInflater inflater(15 + 32);  // maximum window, zlib or gzip header detected
  if (!inflater.ok()) failLoad(path, prefix + "cannot start zlib");
  z_stream& zs = inflater.stream();
  const auto limit = static_cast<size_t>(maxBytes - skip);
  // Grow as data comes, so a lying size costs nothing until the stream really holds the bytes.
  std::vector<uint8_t> out(std::min<size_t>(limit, size_t{1} << 16));
  // The skipped bytes pass through this and are dropped: memory for the window alone.
  std::vector<uint8_t> scratch(skip > 0 ? std::min<uint64_t>(skip, 1u << 20) : 0);
  uint64_t skipLeft = skip;
  size_t produced = 0;
  const uint8_t* in = data;
  size_t inLeft = size;
  bool afterEnd = false;  // a gzip member ended: what follows may be another member or junk
  while (produced < limit) {
    if (skipLeft == 0 && produced == out.size()) out.resize(std::min(limit, out.size() * 2));
    if (zs.avail_in == 0 && inLeft > 0) {
      const size_t chunk = std::min(inLeft, kMaxChunk);
      zs.next_in = const_cast<Bytef*>(in);
      zs.avail_in = static_cast<uInt>(chunk);
      in += chunk;
      inLeft -= chunk;
    }
    const size_t room = skipLeft > 0 ? size_t(std::min<uint64_t>(skipLeft, scratch.size()))
                                     : std::min(out.size() - produced, kMaxChunk);
    zs.next_out = skipLeft > 0 ? scratch.data() : out.data() + produced;
    zs.avail_out = static_cast<uInt>(room);
    const int ret = inflate(&zs, Z_NO_FLUSH);
    if (skipLeft > 0)
      skipLeft -= room - zs.avail_out;
    else
      produced += room - zs.avail_out;
    if (room != zs.avail_out) afterEnd = false;
    if (ret == Z_OK) continue;
    if (ret == Z_STREAM_END) {
      if (zs.avail_in == 0 && inLeft == 0) break;
      if (inflateReset(&zs) != Z_OK) failLoad(path, prefix + "cannot restart zlib");
      afterEnd = true;
      continue;
    }
    if (ret == Z_DATA_ERROR && afterEnd) break;
    if (ret == Z_BUF_ERROR && zs.avail_in == 0 && inLeft == 0) break;  // truncated: caller checks
    failLoad(path, prefix + "corrupt (" + std::string(zs.msg ? zs.msg : "invalid stream") + ")");
  }
  out.resize(produced);
  return out;
}

}  // namespace ewa
