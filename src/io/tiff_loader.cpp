// TIFF stacks through libtiff: a multi-page file or a folder of single-page files, one channel.
#include <tiffio.h>

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>

#include "io/byte_order.h"
#include "io/file_bytes.h"
#include "io/format_loaders.h"
#include "io/length_unit.h"
#include "io/load_failure.h"
#include "io/memory_limit.h"
#include "io/text_fields.h"
#include "io/tiff_planes.h"
#include "io/volume_layout.h"

namespace ewa {

namespace {

// libtiff's messages go into the open file's record instead of stderr.
int keepMessage(TIFF*, void* user, const char*, const char* fmt, va_list args) {
  auto* message = static_cast<std::string*>(user);
  if (message->empty()) {
    char text[256];
    std::vsnprintf(text, sizeof text, fmt, args);
    *message = text;
  }
  return 1;
}

int ignoreMessage(TIFF*, void*, const char*, const char*, va_list) {
  return 1;
}

struct TiffCloser {
  void operator()(TIFF* t) const { TIFFClose(t); }
};

// An open TIFF file and the first error libtiff reported about it.
class TiffFile {
 public:
  explicit TiffFile(const std::string& path) : path_(path), size_(regularFileSize(path)) {
    TIFFOpenOptions* options = TIFFOpenOptionsAlloc();
    TIFFOpenOptionsSetErrorHandlerExtR(options, &keepMessage, &error_);
    TIFFOpenOptionsSetWarningHandlerExtR(options, &ignoreMessage, nullptr);
    TIFFOpenOptionsSetMaxSingleMemAlloc(
        options, tmsize_t(std::min<uint64_t>(physicalMemoryBytes(), INT64_MAX / 2)));
    tiff_.reset(TIFFOpenExt(path.c_str(), "r", options));
    TIFFOpenOptionsFree(options);
    if (!tiff_) fail("not a readable TIFF file");
  }
  TIFF* get() const { return tiff_.get(); }
  uint64_t size() const { return size_; }
  const std::string& path() const { return path_; }
  [[noreturn]] void fail(const std::string& problem) const {
    failLoad(path_, problem + (error_.empty() ? "" : " (" + oneLine(error_) + ")"));
  }

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
  if (f.sampleFormat == SAMPLEFORMAT_IEEEFP && f.bits == 32) return FileScalar::Float32;
  if (f.sampleFormat == SAMPLEFORMAT_UINT && f.bits == 8) return FileScalar::UInt8;
  if (f.sampleFormat == SAMPLEFORMAT_INT && f.bits == 8) return FileScalar::Int8;
  if (f.sampleFormat == SAMPLEFORMAT_UINT && f.bits == 16) return FileScalar::UInt16;
  if (f.sampleFormat == SAMPLEFORMAT_INT && f.bits == 16) return FileScalar::Int16;
  file.fail("unsupported TIFF samples (" + std::to_string(f.bits) + "-bit, format " +
            std::to_string(f.sampleFormat) + "; supported: 8/16-bit integers, 32-bit float)");
}

// Copies one sample (`bytes` wide) of each of `count` pixels from `src`, `stride` samples a
// pixel apart, to `dst` (contiguous).
void copyChannel(const uint8_t* src, size_t stride, size_t bytes, uint32_t count, uint8_t* dst) {
  for (uint32_t x = 0; x < count; ++x)
    std::memcpy(dst + x * bytes, src + x * stride * bytes, bytes);
}

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
    copyChannel(line.data() + (planar ? 0 : size_t(channel) * bytes), planar ? 1 : f.samples, bytes,
                f.width, out + size_t(y) * f.width * bytes);
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
        copyChannel(tile.data() +
                        (size_t(r) * f.tileWidth * stride + (planar ? 0 : size_t(channel))) * bytes,
                    stride, bytes, w, out + (size_t(y0 + r) * f.width + x0) * bytes);
    }
}

// Copies channel `channel` of the current page into `out` (width * height samples).
void readPage(const TiffFile& file, const PageFormat& f, int channel, uint8_t* out) {
  if (f.tileWidth > 0)
    readTiles(file, f, channel, out);
  else
    readStrips(file, f, channel, out);
}

// The pixel size, slice spacing and unit: OME-XML's physical sizes; else, in ImageJ's files (its
// unit) or with no unit, the resolution tags (inch and centimetre resolutions are print sizes,
// 72 dpi, not the sample's) and ImageJ's spacing=.
void placePixels(const TiffFile& tiff, const TiffPlaneOrder& order, VolumeLayout& layout) {
  if (order.kind == "OME") {
    if (order.sizeX > 0.0) layout.spacing.x = order.sizeX;
    if (order.sizeY > 0.0) layout.spacing.y = order.sizeY;
  } else {
    uint16_t resolutionUnit = RESUNIT_INCH;
    TIFFGetFieldDefaulted(tiff.get(), TIFFTAG_RESOLUTIONUNIT, &resolutionUnit);
    float xres = 0.0f, yres = 0.0f;
    if (order.kind == "ImageJ" || resolutionUnit == RESUNIT_NONE) {
      if (TIFFGetField(tiff.get(), TIFFTAG_XRESOLUTION, &xres) && xres > 0.0f &&
          std::isfinite(1.0 / xres))
        layout.spacing.x = 1.0 / xres;
      if (TIFFGetField(tiff.get(), TIFFTAG_YRESOLUTION, &yres) && yres > 0.0f &&
          std::isfinite(1.0 / yres))
        layout.spacing.y = 1.0 / yres;
    }
  }
  if (order.sizeZ > 0.0)
    layout.spacing.z = order.sizeZ;
  else
    layout.notes.push_back("no slice spacing in the file: 1 assumed");
  if (layout.spacing.x == 1.0 && layout.spacing.y == 1.0)
    layout.notes.push_back("no pixel size in the file: 1 assumed");
  if (!order.unit.empty()) layout.notes.push_back("spacing unit: " + quoteText(order.unit, 20));
  layout.unit = lengthUnitName(order.unit);
}

// Pages in a file, or 0 when it is missing or not a TIFF file.
int64_t tiffPageCount(const std::string& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) return 0;
  try {
    TiffFile tiff(file);
    return int64_t(TIFFNumberOfDirectories(tiff.get()));
  } catch (const LoadError&) {
    return 0;
  }
}

// An OME-TIFF dataset over several files (its XML in `xmlFile`): each slice of `planeChannel`
// and `frame` from the file and page its TiffData names, every page like the first.
std::vector<uint8_t> readOmeDataset(const std::string& path, const std::string& xmlFile,
                                    const TiffPlaneOrder& order, const PageFormat& format,
                                    int64_t planeChannel, int sample, int64_t frame,
                                    VolumeLayout& layout) {
  const auto sources = omePlaneSources(xmlFile, order, planeChannel, frame, &tiffPageCount);
  const int64_t slices = std::max<int64_t>(order.slices, 1);
  for (int64_t z = 0; z < slices; ++z)  // at most one past the slices found
    if (!sources.count(z))
      failLoad(path, "slice " + std::to_string(z) + " of channel " + std::to_string(planeChannel) +
                         ", time point " + std::to_string(frame) +
                         " is in none of the OME-TIFF dataset's files");
  const size_t pageBytes = size_t(format.width) * format.height * fileScalarSize(layout.type);
  dataByteCount(xmlFile, {int64_t(format.width), int64_t(format.height), slices}, layout.type);
  std::vector<uint8_t> bytes(pageBytes * size_t(slices));
  std::unique_ptr<TiffFile> open;
  std::map<std::string, int> files;
  for (const auto& [z, source] : sources) {
    if (!open || open->path() != source.file) open = std::make_unique<TiffFile>(source.file);
    ++files[source.file];
    if (!TIFFSetDirectory(open->get(), tdir_t(source.ifd)))
      open->fail("has no page " + std::to_string(source.ifd));
    const PageFormat f = pageFormat(*open);
    if (!(f == format))
      open->fail("page " + std::to_string(source.ifd) + " is " + f.text() + ", the first " +
                 format.text() + ": all pages must agree");
    readPage(*open, f, sample, bytes.data() + size_t(z) * pageBytes);
  }
  layout.notes.push_back("an OME-TIFF dataset: " + std::to_string(slices) + " slices from " +
                         std::to_string(files.size()) + " files");
  return bytes;
}

}  // namespace

Volume loadTiff(const std::string& path, int channel, int frame) {
  std::error_code ec;
  std::vector<std::string> files;
  if (std::filesystem::is_directory(path, ec)) {
    for (std::filesystem::directory_iterator it(path, ec), end; !ec && it != end;
         it.increment(ec)) {
      const std::string ext = toLower(it->path().extension().string());
      if ((ext == ".tif" || ext == ".tiff") && it->is_regular_file(ec))
        files.push_back(it->path().string());
    }
    if (files.empty()) failLoad(path, "no TIFF file in the folder");
    std::sort(files.begin(), files.end(), naturalLess);
  } else {
    files.push_back(path);
  }

  // Pages in order: every page of every file.
  VolumeLayout layout;
  PageFormat format;
  std::vector<uint8_t> bytes;
  int64_t pages = 0, pageChannel = 0;
  TiffPlaneOrder order;
  size_t pageBytes = 0;
  for (const std::string& file : files) {
    TiffFile tiff(file);
    do {
      const PageFormat f = pageFormat(tiff);
      if (pages == 0) {
        format = f;
        layout.type = scalarOf(tiff, f);
        char* description = nullptr;
        std::string text;
        if (TIFFGetField(tiff.get(), TIFFTAG_IMAGEDESCRIPTION, &description) && description)
          text = std::string(description).substr(0, 1 << 24);  // OME-XML of many files
        order = tiffPlaneOrder(file, text, f.samples);
        // Channels are the samples of a pixel (RGB), or pages (an ImageJ hyperstack, OME-TIFF).
        const int64_t channels = f.samples > 1 ? f.samples : order.channels;
        checkChannel(path, channel, channels);
        layout.channel = channel;
        layout.channelCount = int(channels);
        pageChannel = f.samples > 1 ? 0 : channel;
        checkFrame(path, frame, order.frames, "the file has", "time point");
        layout.frame = frame;
        layout.frameCount = int(order.frames);
        placePixels(tiff, order, layout);
        if (channels > 1)
          layout.notes.push_back(std::to_string(channels) + " channels; showing channel " +
                                 std::to_string(channel) + " (--channel N picks another)");
        if (order.frames > 1)
          layout.notes.push_back(std::to_string(order.frames) + " time points; showing frame " +
                                 std::to_string(frame) + " (--frame N picks another)");
        pageBytes = size_t(f.width) * f.height * fileScalarSize(layout.type);
        dataByteCount(file, {int64_t(f.width), int64_t(f.height), 1}, layout.type);
        if (!order.blocks.empty()) {  // the XML names other files: read what it says, once
          bytes = readOmeDataset(path, file, order, format, pageChannel,
                                 f.samples > 1 ? channel : 0, frame, layout);
          break;
        }
      } else if (!(f == format)) {
        tiff.fail("page " + std::to_string(pages) + " is " + f.text() + ", the first " +
                  format.text() + ": all pages must agree");
      }
      if (tiffSliceOfPage(order, pages, pageChannel, frame) >= 0) {
        const auto slices = int64_t(bytes.size() / std::max<size_t>(pageBytes, 1));
        dataByteCount(file, {int64_t(f.width), int64_t(f.height), slices + 1}, layout.type);
        bytes.resize(bytes.size() + pageBytes);
        readPage(tiff, f, f.samples > 1 ? channel : 0, bytes.data() + bytes.size() - pageBytes);
      }
      ++pages;
    } while (TIFFReadDirectory(tiff.get()));
    if (!order.blocks.empty()) break;
  }
  layout.dims = {int64_t(format.width), int64_t(format.height),
                 int64_t(bytes.size() / std::max<size_t>(pageBytes, 1))};
  layout.bigEndian = hostIsBigEndian();  // libtiff gives native order
  return makeVolume(path, layout, std::move(bytes));
}

}  // namespace ewa
