// zlib/gzip and bzip2 decompression to an exactly known size, for compressed volume data.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace ewa {

// Inflates a zlib or gzip stream (told apart by its header; gzip members that follow one
// another are joined) that must yield exactly `expectedSize` bytes. Throws LoadError
// "<path>: <what>: ..." when the data is corrupt, truncated, or inflates to more or fewer bytes.
// The output buffer grows only as inflation proceeds (up to `expectedSize`), so a header that
// lies about the size cannot make us allocate memory the data does not fill.
std::vector<uint8_t> inflateExact(const std::string& path, const uint8_t* data, size_t size,
                                  uint64_t expectedSize, const std::string& what);

// Inflates the first `maxBytes` bytes of a zlib or gzip stream (fewer when the stream ends
// sooner; trailing data is never looked at), for formats whose header is inside the stream.
// Throws LoadError for corrupt data; the caller checks that it got as many bytes as it needs.
std::vector<uint8_t> inflatePrefix(const std::string& path, const uint8_t* data, size_t size,
                                   uint64_t maxBytes, const std::string& what);

// As inflatePrefix, but only bytes [skip, maxBytes) are kept (fewer when the stream ends
// sooner): the bytes before `skip` are inflated and dropped, so reading one frame late in a
// compressed file costs memory for that frame alone.
std::vector<uint8_t> inflateWindow(const std::string& path, const uint8_t* data, size_t size,
                                   uint64_t skip, uint64_t maxBytes, const std::string& what);

// Decompresses a bzip2 stream (streams that follow one another are joined, as pbzip2 writes
// them) that must yield exactly `expectedSize` bytes; otherwise as inflateExact.
std::vector<uint8_t> bunzip2Exact(const std::string& path, const uint8_t* data, size_t size,
                                  uint64_t expectedSize, const std::string& what);

}  // namespace ewa
