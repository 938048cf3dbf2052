// Inflating a deflated DICOM data set (transfer syntax 1.2.840.10008.1.2.1.99) for the
// pre-check, within bounds a deflate bomb cannot pass.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace ewa {

// The inflated data set may be at most this many times the deflated bytes (but always
// kDicomInflateFloor), and never more than kDicomInflateCap. Deflate can reach about 1000:1;
// real images deflate a few times (an all-zero frame a few hundred times), so a file past these
// is a bomb, refused before GDCM inflates it into gigabytes.
constexpr uint64_t kDicomInflateRatio = 256;
constexpr uint64_t kDicomInflateFloor = uint64_t(64) << 20;  // 64 MiB
constexpr uint64_t kDicomInflateCap = uint64_t(2) << 30;     // 2 GiB

// The largest inflated size allowed for `deflatedBytes` of deflated data.
uint64_t dicomInflateLimit(uint64_t deflatedBytes);

// Inflates the raw deflate stream (no zlib or gzip wrapper, as the standard has it) of `size`
// bytes at `data`, which must end within them (bytes after its end are ignored, as GDCM does).
// Throws LoadError naming `path` when the stream is corrupt or cut short, or inflates to more
// than dicomInflateLimit(size) bytes; the buffer grows only as the data fills it.
std::vector<uint8_t> inflateDicomDataSet(const std::string& path, const uint8_t* data, size_t size);

}  // namespace ewa
