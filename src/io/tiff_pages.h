// TIFF pages through libtiff: an open file, what a page holds, and reading one channel of it.
#pragma once

#include <tiffio.h>

#include <cstdarg>
#include <cstdint>
#include <memory>
#include <string>

#include "io/volume_layout.h"

namespace ewa {

// libtiff message handlers (TIFFOpenOptionsSet...HandlerExtR): the first message into the
// std::string `user` points to, or none at all.
int keepFirstTiffMessage(TIFF*, void* user, const char*, const char* fmt, va_list args);
int ignoreTiffMessage(TIFF*, void*, const char*, const char*, va_list);

struct TiffCloser {
  void operator()(TIFF* t) const { TIFFClose(t); }
};

// An open TIFF file and the first error libtiff reported about it. Throws LoadError
// ("<path>: not a readable TIFF file (...)") when it cannot be opened.
class TiffFile {
 public:
  explicit TiffFile(const std::string& path);
  TIFF* get() const { return tiff_.get(); }
  uint64_t size() const { return size_; }
  const std::string& path() const { return path_; }
  [[noreturn]] void fail(const std::string& problem) const;

 private:
  std::string path_;
  uint64_t size_ = 0;
  std::string error_;
  std::unique_ptr<TIFF, TiffCloser> tiff_;
};

// What a page holds; pages of one stack must agree on all of it.
struct PageFormat {
  uint32_t width = 0, height = 0;
  uint16_t bits = 0, samples = 1, sampleFormat = SAMPLEFORMAT_UINT, planar = PLANARCONFIG_CONTIG;
  uint32_t tileWidth = 0, tileHeight = 0;  // 0: stored in strips
  // Strips or tiles may differ from page to page; the samples may not.
  bool operator==(const PageFormat& o) const {
    return width == o.width && height == o.height && bits == o.bits && samples == o.samples &&
           sampleFormat == o.sampleFormat && planar == o.planar;
  }
  std::string text() const {
    return std::to_string(width) + " x " + std::to_string(height) + ", " + std::to_string(bits) +
           "-bit, " + std::to_string(samples) + " sample(s)";
  }
};

// The current page's format; throws LoadError for pages ewaview cannot read or whose strips or
// tiles cannot hold its samples.
PageFormat pageFormat(const TiffFile& file);
// The voxel type of pages of format `f`.
FileScalar scalarOf(const TiffFile& file, const PageFormat& f);
// Copies channel `channel` of the current page into `out` (width * height samples).
void readPage(const TiffFile& file, const PageFormat& f, int channel, uint8_t* out);

}  // namespace ewa
