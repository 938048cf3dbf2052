// bzip2 decompression bounded by the size a header promises: no more, no less, no huge buffers.
#include <bzlib.h>

#include <algorithm>

#include "io/decompress.h"
#include "io/load_failure.h"
#include "io/memory_limit.h"

namespace ewa {

namespace {

// libbz2 counts in unsigned int; feed and drain it in pieces it can count.
constexpr size_t kMaxChunk = size_t{1} << 30;

// bzip2, unlike deflate (at most 1032:1), has no useful bound on its ratio: a few kilobytes can
// unpack to gigabytes of zeros. Real volumes compress a few times to a few hundred times, so a
// header promising more than this ratio beyond this size is refused before decompressing.
constexpr uint64_t kMaxPlausibleRatio = 2000;
constexpr uint64_t kRatioFloorBytes = uint64_t{1} << 30;

class Bunzipper {
 public:
  Bunzipper() { ok_ = BZ2_bzDecompressInit(&bs_, 0, 0) == BZ_OK; }
  ~Bunzipper() {
    if (ok_) BZ2_bzDecompressEnd(&bs_);
  }
  Bunzipper(const Bunzipper&) = delete;
  Bunzipper& operator=(const Bunzipper&) = delete;
  bool ok() const { return ok_; }
  bz_stream& stream() { return bs_; }
  // Starts a new stream where the last one ended, keeping the input position.
  bool restart() {
    char* in = bs_.next_in;
    const unsigned int left = bs_.avail_in;
    BZ2_bzDecompressEnd(&bs_);
    bs_ = bz_stream{};
    ok_ = BZ2_bzDecompressInit(&bs_, 0, 0) == BZ_OK;
    bs_.next_in = in;
    bs_.avail_in = left;
    return ok_;
  }

 private:
  bz_stream bs_{};
  bool ok_ = false;
};

}  // namespace

std::vector<uint8_t> bunzip2Exact(const std::string& path, const uint8_t* data, size_t size,
                                  uint64_t expectedSize, const std::string& what) {
  const std::string prefix = what + ": ";
  checkAllocation(path, expectedSize, what + " after decompression");
  if (expectedSize > kRatioFloorBytes && expectedSize / kMaxPlausibleRatio > size)
    failLoad(path, prefix + std::to_string(size) + " compressed bytes said to decompress to " +
                       std::to_string(expectedSize) + " bytes, more than " +
                       std::to_string(kMaxPlausibleRatio) +
                       " times as many (a decompression bomb?)");
  Bunzipper bunzipper;
  if (!bunzipper.ok()) failLoad(path, prefix + "cannot start bzip2");
  bz_stream& bs = bunzipper.stream();
  const auto expected = static_cast<size_t>(expectedSize);
  // Grow as data comes, so a lying size costs nothing until the stream really holds the bytes.
  std::vector<uint8_t> out(std::min<size_t>(expected, std::max<size_t>(size_t{1} << 20, size * 4)));
  size_t produced = 0;
  const uint8_t* in = data;
  size_t inLeft = size;
  char probe = 0;
  bool newStream = false;  // true right after a stream ended: what follows may be junk
  const auto shortBy = [&] {
    return prefix + "decompresses to only " + std::to_string(produced) + " bytes, expected " +
           std::to_string(expected) + " (truncated or wrong sizes?)";
  };
  while (true) {
    // Once the expected bytes are out, decompress into a 1-byte probe to catch surplus data.
    const bool probing = produced == expected;
    if (!probing && produced == out.size())
      out.resize(std::min(expected, out.size() > expected / 2 ? expected : out.size() * 2));
    if (bs.avail_in == 0 && inLeft > 0) {
      const size_t chunk = std::min(inLeft, kMaxChunk);
      bs.next_in = reinterpret_cast<char*>(const_cast<uint8_t*>(in));
      bs.avail_in = static_cast<unsigned int>(chunk);
      in += chunk;
      inLeft -= chunk;
    }
    const size_t room = probing ? 1 : std::min(out.size() - produced, kMaxChunk);
    bs.next_out = probing ? &probe : reinterpret_cast<char*>(out.data() + produced);
    bs.avail_out = static_cast<unsigned int>(room);
    const int ret = BZ2_bzDecompress(&bs);
    const size_t got = room - bs.avail_out;
    if (probing && got > 0)
      failLoad(path, prefix + "decompresses to more than the expected " + std::to_string(expected) +
                         " bytes");
    produced += got;
    if (got > 0) newStream = false;
    if (ret == BZ_OK) {
      // No progress with all input used: the stream's end is missing.
      if (got == 0 && bs.avail_in == 0 && inLeft == 0) {
        if (produced < expected) failLoad(path, shortBy());
        failLoad(path, prefix + "truncated (the end of the compressed stream is missing)");
      }
      continue;
    }
    if (ret == BZ_STREAM_END) {
      if (produced == expected) return out;
      if (bs.avail_in == 0 && inLeft == 0) failLoad(path, shortBy());
      if (!bunzipper.restart()) failLoad(path, prefix + "cannot restart bzip2");
      newStream = true;
      continue;
    }
    if (ret == BZ_DATA_ERROR_MAGIC && newStream) failLoad(path, shortBy());
    if (ret == BZ_MEM_ERROR) failLoad(path, prefix + "out of memory while decompressing");
    failLoad(path, prefix + (ret == BZ_DATA_ERROR_MAGIC ? "corrupt (not a bzip2 stream)"
                             : ret == BZ_DATA_ERROR     ? "corrupt (bad data or checksum)"
                                                        : "bzip2 error " + std::to_string(ret)));
  }
}

}  // namespace ewa
