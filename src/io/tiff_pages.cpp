// TIFF pages through libtiff: opening a file, a page's format, one channel of its samples.
#include "io/tiff_pages.h"

#include <algorithm>
#include <cstdarg>
#include <cstring>

#include "io/file_bytes.h"
#include "io/load_failure.h"
#include "io/memory_limit.h"

namespace ewa {

// libtiff's messages go into the open file's record instead of stderr.
int keepFirstTiffMessage(TIFF*, void* user, const char*, const char* fmt, va_list args) {
  auto* message = static_cast<std::string*>(user);
  if (message->empty()) {
    char text[256];
    std::vsnprintf(text, sizeof text, fmt, args);
    *message = text;
  }
  return 1;
}

int ignoreTiffMessage(TIFF*, void*, const char*, const char*, va_list) {
  return 1;
}

TiffFile::TiffFile(const std::string& path) : path_(path), size_(regularFileSize(path)) {
  TIFFOpenOptions* options = TIFFOpenOptionsAlloc();
  TIFFOpenOptionsSetErrorHandlerExtR(options, &keepFirstTiffMessage, &error_);
  TIFFOpenOptionsSetWarningHandlerExtR(options, &ignoreTiffMessage, nullptr);
  TIFFOpenOptionsSetMaxSingleMemAlloc(
      options, tmsize_t(std::min<uint64_t>(physicalMemoryBytes(), INT64_MAX / 2)));
  tiff_.reset(TIFFOpenExt(path.c_str(), "rm", options));
  TIFFOpenOptionsFree(options);
  if (!tiff_) fail("not a readable TIFF file");
}

void TiffFile::fail(const std::string& problem) const {
  failLoad(path_, problem + (error_.empty() ? "" : " (" + oneLine(error_) + ")"));
}

namespace {

// The page's samples must fit in its strips or tiles before anything is sized by the header:
// all of them when uncompressed, and at most kMaxRatio times the stored bytes when compressed
// (LZW, the loosest of TIFF's codecs, stays under it).
constexpr uint64_t kMaxRatio = 4096;

void checkStoredBytes(const TiffFile& file, const PageFormat& f) {
  TIFF* t = file.get();
  const bool tiled = TIFFIsTiled(t);
  const std::string block = tiled ? "tile" : "strip";
  uint16_t compression = COMPRESSION_NONE;
  TIFFGetFieldDefaulted(t, TIFFTAG_COMPRESSION, &compression);
  uint64_t* counts = nullptr;
  if (!TIFFGetField(t, tiled ? TIFFTAG_TILEBYTECOUNTS : TIFFTAG_STRIPBYTECOUNTS, &counts) ||
      !counts)
    file.fail("a page has no " + block + " byte counts");
  uint64_t stored = 0;
  const uint32_t n = tiled ? TIFFNumberOfTiles(t) : TIFFNumberOfStrips(t);
  for (uint32_t s = 0; s < n; ++s)
    if (__builtin_add_overflow(stored, counts[s], &stored))
      file.fail("bad " + block + " byte counts");
  if (stored > file.size())
    file.fail(block + " byte counts of " + std::to_string(stored) + " exceed the file's " +
              std::to_string(file.size()) + " bytes");
  const unsigned __int128 samples =
      (unsigned __int128)f.width * f.height * f.samples * std::max<uint16_t>(f.bits, 1) / 8;
  if (compression == COMPRESSION_NONE ? samples > stored
                                      : samples > (unsigned __int128)stored * kMaxRatio + 65536)
    file.fail("a page of " + std::to_string(f.width) + " x " + std::to_string(f.height) +
              " does not fit in its " + std::to_string(stored) + " bytes of " + block + "s" +
              " (truncated?)");
}

}  // namespace

PageFormat pageFormat(const TiffFile& file) {
  PageFormat f;
  TIFF* t = file.get();
  if (!TIFFGetField(t, TIFFTAG_IMAGEWIDTH, &f.width) ||
      !TIFFGetField(t, TIFFTAG_IMAGELENGTH, &f.height))
    file.fail("a page has no image size");
  TIFFGetFieldDefaulted(t, TIFFTAG_BITSPERSAMPLE, &f.bits);
  TIFFGetFieldDefaulted(t, TIFFTAG_SAMPLESPERPIXEL, &f.samples);
  TIFFGetFieldDefaulted(t, TIFFTAG_SAMPLEFORMAT, &f.sampleFormat);
  TIFFGetFieldDefaulted(t, TIFFTAG_PLANARCONFIG, &f.planar);
  if (TIFFIsTiled(t)) {
    if (!TIFFGetField(t, TIFFTAG_TILEWIDTH, &f.tileWidth) ||
        !TIFFGetField(t, TIFFTAG_TILELENGTH, &f.tileHeight) || f.tileWidth == 0 ||
        f.tileHeight == 0)
      file.fail("a tiled page has no tile size");
    // Tiles overhang the page up to their size's multiple of 16; a tile much bigger than the
    // page would size the tile buffer from the header alone.
    const auto bytesOf = [&](uint64_t w, uint64_t h) {
      return (unsigned __int128)w * h * f.samples * std::max<uint16_t>(f.bits, 8) / 8;
    };
    const unsigned __int128 limit =
        std::max<unsigned __int128>(4 * bytesOf(f.width, f.height), 4u << 20);
    if (bytesOf(f.tileWidth, f.tileHeight) > limit)
      file.fail("tiles of " + std::to_string(f.tileWidth) + " x " + std::to_string(f.tileHeight) +
                " for a page of " + std::to_string(f.width) + " x " + std::to_string(f.height));
  }
  checkStoredBytes(file, f);
  return f;
}

FileScalar scalarOf(const TiffFile& file, const PageFormat& f) {
  // (libtiff hands samples over in native byte order; makeVolume makes the wide ones float32.)
  struct Kind {
    uint16_t format, bits;
    FileScalar type;
  };
  static const Kind kKinds[] = {{SAMPLEFORMAT_UINT, 8, FileScalar::UInt8},
                                {SAMPLEFORMAT_INT, 8, FileScalar::Int8},
                                {SAMPLEFORMAT_UINT, 16, FileScalar::UInt16},
                                {SAMPLEFORMAT_INT, 16, FileScalar::Int16},
                                {SAMPLEFORMAT_UINT, 32, FileScalar::UInt32},
                                {SAMPLEFORMAT_INT, 32, FileScalar::Int32},
                                {SAMPLEFORMAT_UINT, 64, FileScalar::UInt64},
                                {SAMPLEFORMAT_INT, 64, FileScalar::Int64},
                                {SAMPLEFORMAT_IEEEFP, 32, FileScalar::Float32},
                                {SAMPLEFORMAT_IEEEFP, 64, FileScalar::Float64}};
  for (const Kind& k : kKinds)
    if (f.sampleFormat == k.format && f.bits == k.bits) return k.type;
  file.fail("unsupported TIFF samples (" + std::to_string(f.bits) + "-bit, format " +
            std::to_string(f.sampleFormat) +
            "; supported: 8- to 64-bit integers, 32- and 64-bit floats)");
}

namespace {

// Copies channel `channel` of the current page, stored in strips, into `out`.
void readStrips(const TiffFile& file, const PageFormat& f, int channel, uint8_t* out) {
  TIFF* t = file.get();
  const size_t bytes = f.bits / 8;
  const tmsize_t lineSize = TIFFScanlineSize(t);
  const bool planar = f.planar == PLANARCONFIG_SEPARATE;
  const uint64_t need = uint64_t(f.width) * bytes * (planar ? 1 : f.samples);
  if (lineSize <= 0 || uint64_t(lineSize) < need) file.fail("bad scanline size");
  std::vector<uint8_t> line(static_cast<size_t>(lineSize));
  for (uint32_t y = 0; y < f.height; ++y) {
    if (TIFFReadScanline(t, line.data(), y, planar ? uint16_t(channel) : 0) < 0)
      file.fail("cannot read row " + std::to_string(y) + " (truncated or corrupt file?)");
    copyInterleaved(line.data() + (planar ? 0 : size_t(channel) * bytes), planar ? 1 : f.samples,
                    bytes, f.width, out + size_t(y) * f.width * bytes);
  }
}

// The same from tiles (microscopy's big planes, GeoTIFF-style writers): each tile decoded once,
// its part inside the page copied.
void readTiles(const TiffFile& file, const PageFormat& f, int channel, uint8_t* out) {
  TIFF* t = file.get();
  const size_t bytes = f.bits / 8;
  const bool planar = f.planar == PLANARCONFIG_SEPARATE;
  const size_t stride = planar ? 1 : f.samples;
  const tmsize_t tileSize = TIFFTileSize(t);
  const uint64_t need = uint64_t(f.tileWidth) * f.tileHeight * bytes * stride;
  if (tileSize <= 0 || uint64_t(tileSize) < need) file.fail("bad tile size");
  std::vector<uint8_t> tile(static_cast<size_t>(tileSize));
  for (uint32_t y0 = 0; y0 < f.height; y0 += f.tileHeight)
    for (uint32_t x0 = 0; x0 < f.width; x0 += f.tileWidth) {
      const uint32_t index = TIFFComputeTile(t, x0, y0, 0, planar ? uint16_t(channel) : 0);
      std::fill(tile.begin(), tile.end(), uint8_t(0));
      if (TIFFReadEncodedTile(t, index, tile.data(), tileSize) < 0)
        file.fail("cannot read the tile at " + std::to_string(x0) + ", " + std::to_string(y0) +
                  " (truncated or corrupt file?)");
      const uint32_t w = std::min(f.tileWidth, f.width - x0);
      const uint32_t h = std::min(f.tileHeight, f.height - y0);
      for (uint32_t r = 0; r < h; ++r)
        copyInterleaved(
            tile.data() +
                (size_t(r) * f.tileWidth * stride + (planar ? 0 : size_t(channel))) * bytes,
            stride, bytes, w, out + (size_t(y0 + r) * f.width + x0) * bytes);
    }
}

}  // namespace

// Copies channel `channel` of the current page into `out` (width * height samples).
void readPage(const TiffFile& file, const PageFormat& f, int channel, uint8_t* out) {
  if (f.tileWidth > 0)
    readTiles(file, f, channel, out);
  else
    readStrips(file, f, channel, out);
}

}  // namespace ewa
