// VTK XML binary arrays: byte-count header or zlib block table, each count checked first.
#include "io/vtk_binary_array.h"

#include "io/byte_order.h"
#include "io/decompress.h"
#include "io/load_failure.h"

namespace ewa {

namespace {

std::vector<uint8_t> decodeUncompressed(const std::string& path, const ByteSource& source,
                                        const VtkBinaryFormat& f, uint64_t expected) {
  const std::vector<uint8_t> head = source.read(0, f.headerWidth, "array header");
  const uint64_t count = readUnsigned(head.data(), f.headerWidth, f.bigEndian);
  if (count != expected) {
    failLoad(path, "data array holds " + std::to_string(count) + " bytes, but the extent needs " +
                       std::to_string(expected));
  }
  return source.read(f.headerWidth, count, "array data");
}

std::vector<uint8_t> decodeZlib(const std::string& path, const ByteSource& source,
                                const VtkBinaryFormat& f, uint64_t expected) {
  const size_t w = f.headerWidth;
  const std::vector<uint8_t> head = source.read(0, 3 * w, "compression header");
  const uint64_t blocks = readUnsigned(head.data(), w, f.bigEndian);
  const uint64_t blockSize = readUnsigned(head.data() + w, w, f.bigEndian);
  const uint64_t lastSize = readUnsigned(head.data() + 2 * w, w, f.bigEndian);
  if (blocks == 0 || blockSize == 0) failLoad(path, "compressed data array has no blocks");
  // The block table must fit in what is there before we read it.
  if (blocks > (source.size() - 3 * w) / w) {
    failLoad(path, "compression header claims " + std::to_string(blocks) +
                       " blocks, more than the file holds (truncated or corrupt)");
  }
  if (lastSize > blockSize) failLoad(path, "last compressed block is larger than the block size");
  const uint64_t last = lastSize == 0 ? blockSize : lastSize;  // 0: the last block is full
  uint64_t total = 0;
  if (__builtin_mul_overflow(blocks - 1, blockSize, &total) ||
      __builtin_add_overflow(total, last, &total) || total != expected) {
    failLoad(path, "compressed data array does not hold the " + std::to_string(expected) +
                       " bytes the extent needs");
  }
  const std::vector<uint8_t> table = source.read(3 * w, blocks * w, "block size table");
  std::vector<uint64_t> packedSizes(static_cast<size_t>(blocks));
  uint64_t packedTotal = 0;
  for (size_t b = 0; b < packedSizes.size(); ++b) {
    packedSizes[b] = readUnsigned(table.data() + b * w, w, f.bigEndian);
    if (__builtin_add_overflow(packedTotal, packedSizes[b], &packedTotal))
      failLoad(path, "compressed block sizes overflow");
  }
  const uint64_t dataStart = (3 + blocks) * w;
  const std::vector<uint8_t> packed = source.read(dataStart, packedTotal, "compressed blocks");

  // The output grows block by block, as inflation really produces data.
  std::vector<uint8_t> out;
  uint64_t at = 0;
  for (size_t b = 0; b < packedSizes.size(); ++b) {
    const uint64_t size = b + 1 == packedSizes.size() ? last : blockSize;
    const std::vector<uint8_t> block =
        inflateExact(path, packed.data() + at, static_cast<size_t>(packedSizes[b]), size,
                     "compressed block " + std::to_string(b));
    out.insert(out.end(), block.begin(), block.end());
    at += packedSizes[b];
  }
  return out;
}

}  // namespace

std::vector<uint8_t> decodeVtkBinaryArray(const std::string& path, const ByteSource& source,
                                          const VtkBinaryFormat& format, uint64_t expectedBytes) {
  return format.zlib ? decodeZlib(path, source, format, expectedBytes)
                     : decodeUncompressed(path, source, format, expectedBytes);
}

}  // namespace ewa
