// VTK SLC (.slc): a text header, an RGB icon, then 8-bit slices, raw or run-length encoded.
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "io/file_bytes.h"
#include "io/format_loaders.h"
#include "io/load_failure.h"
#include "io/memory_limit.h"
#include "io/volume_layout.h"

namespace ewa {

namespace {

// Reads the header's numbers and the binary blocks between them, as vtkSLCReader's fscanf
// calls do, but never past the end of the bytes.
class SlcScanner {
 public:
  SlcScanner(const std::string& path, const std::vector<uint8_t>& bytes)
      : path_(path), bytes_(bytes) {}

  int64_t integer(const char* what) {
    skipSpace();
    const size_t start = pos_;
    if (pos_ < bytes_.size() && (bytes_[pos_] == '-' || bytes_[pos_] == '+')) ++pos_;
    while (pos_ < bytes_.size() && std::isdigit(bytes_[pos_]) && pos_ - start < 12) ++pos_;
    const std::string text(bytes_.begin() + ptrdiff_t(start), bytes_.begin() + ptrdiff_t(pos_));
    if (text.empty() || text == "-" || text == "+") failLoad(path_, std::string("bad ") + what);
    return std::strtoll(text.c_str(), nullptr, 10);
  }
  double number(const char* what) {
    skipSpace();
    const size_t start = pos_;
    while (pos_ < bytes_.size() && pos_ - start < 40 &&
           (std::isdigit(bytes_[pos_]) || std::strchr("+-.eE", bytes_[pos_]) != nullptr))
      ++pos_;
    const std::string text(bytes_.begin() + ptrdiff_t(start), bytes_.begin() + ptrdiff_t(pos_));
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size())
      failLoad(path_, std::string("bad ") + what);
    return v;
  }
  // The "X" that ends "W H X" and "SIZE X"; binary data starts right after it.
  void marker(const char* what) {
    skipSpace();
    if (pos_ >= bytes_.size() || bytes_[pos_] != 'X')
      failLoad(path_, std::string("missing X after the ") + what);
    ++pos_;
  }
  uint64_t remaining() const { return bytes_.size() - pos_; }
  const uint8_t* take(uint64_t count, const std::string& what) {
    if (count > bytes_.size() - pos_)
      failLoad(path_, what + " needs " + std::to_string(count) + " bytes but only " +
                          std::to_string(bytes_.size() - pos_) + " remain (truncated file?)");
    const uint8_t* p = bytes_.data() + pos_;
    pos_ += size_t(count);
    return p;
  }

 private:
  void skipSpace() {
    while (pos_ < bytes_.size() && std::isspace(bytes_[pos_])) ++pos_;
  }
  const std::string& path_;
  const std::vector<uint8_t>& bytes_;
  size_t pos_ = 0;
};

// Run-length decoding: a count byte (high bit: that many literal bytes follow; else one byte
// repeated), a zero count ends the slice. Fills exactly `out.size()` bytes or fails.
void decodeSlice(const std::string& path, const uint8_t* in, size_t inSize, uint8_t* out,
                 size_t outSize, int64_t slice) {
  size_t i = 0, o = 0;
  const auto fail = [&](const char* problem) {
    failLoad(path, "slice " + std::to_string(slice) + ": " + problem);
  };
  while (true) {
    if (i >= inSize) fail("run-length data ends without an end mark");
    const uint8_t head = in[i++];
    const size_t count = head & 0x7f;
    if (count == 0) break;
    if (count > outSize - o) fail("run-length data decodes to more than a slice");
    if (head & 0x80) {
      if (count > inSize - i) fail("run-length data is truncated");
      std::copy(in + i, in + i + count, out + o);
      i += count;
    } else {
      if (i >= inSize) fail("run-length data is truncated");
      std::fill(out + o, out + o + count, in[i++]);
    }
    o += count;
  }
  if (o != outSize)
    fail(("run-length data decodes to " + std::to_string(o) + " of " + std::to_string(outSize) +
          " bytes")
             .c_str());
}

}  // namespace

Volume loadSlc(const std::string& path) {
  const uint64_t fileSize = regularFileSize(path);
  checkAllocation(path, fileSize, "file");
  const std::vector<uint8_t> bytes = readFileRange(path, 0, fileSize, "file");
  SlcScanner in(path, bytes);
  if (in.integer("magic number") != 11111) failLoad(path, "not an SLC file (magic is not 11111)");
  VolumeLayout layout;
  for (int a = 0; a < 3; ++a) layout.dims[a] = in.integer("size");
  const int64_t bits = in.integer("bits per voxel");
  if (bits != 8) failLoad(path, "unsupported " + std::to_string(bits) + " bits per voxel (need 8)");
  for (int a = 0; a < 3; ++a) layout.spacing[a] = in.number("spacing");
  in.integer("unit type");
  in.integer("data source");
  in.integer("data modification");
  const int64_t compression = in.integer("data compression");
  if (compression != 0 && compression != 1)
    failLoad(path, "unknown compression " + std::to_string(compression) + " (need 0 or 1)");
  const uint64_t total = dataByteCount(path, layout.dims, FileScalar::UInt8);

  const int64_t iconWidth = in.integer("icon width"), iconHeight = in.integer("icon height");
  in.marker("icon size");
  if (iconWidth < 0 || iconHeight < 0 || iconWidth > (1 << 20) || iconHeight > (1 << 20))
    failLoad(path, "bad icon size");
  in.take(3 * uint64_t(iconWidth) * uint64_t(iconHeight), "icon");  // R, G and B planes

  // The slices must be able to hold the voxels before a buffer is sized by the header: byte for
  // byte raw, and at most 127 bytes from each 2-byte run (plus each slice's size line) encoded.
  if (compression == 0 ? total > in.remaining() : total > 64 * in.remaining())
    failLoad(path, "the file's " + std::to_string(in.remaining()) +
                       " bytes of slices cannot hold " + std::to_string(total) +
                       " voxels (truncated file or wrong sizes?)");
  const size_t plane = size_t(layout.dims[0]) * size_t(layout.dims[1]);
  std::vector<uint8_t> voxels(total);
  for (int64_t z = 0; z < layout.dims[2]; ++z) {
    uint8_t* out = voxels.data() + size_t(z) * plane;
    const std::string what = "slice " + std::to_string(z);
    if (compression == 0) {
      const uint8_t* p = in.take(plane, what);
      std::copy(p, p + plane, out);
    } else {
      const int64_t packed = in.integer("compressed slice size");
      in.marker("compressed slice size");
      if (packed < 0) failLoad(path, what + ": negative compressed size");
      decodeSlice(path, in.take(uint64_t(packed), what), size_t(packed), out, plane, z);
    }
  }
  return makeVolume(path, layout, std::move(voxels));
}

}  // namespace ewa
