// TIFF stacks through libtiff: a multi-page file or a folder of single-page files, one channel.
#include <tiffio.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <optional>

#include "core/parallel_chunks.h"
#include "io/byte_order.h"
#include "io/file_bytes.h"
#include "io/file_listing.h"
#include "io/format_loaders.h"
#include "io/length_unit.h"
#include "io/load_failure.h"
#include "io/tiff_ome_dataset.h"
#include "io/tiff_pages.h"
#include "io/tiff_planes.h"
#include "io/volume_layout.h"

namespace ewa {

namespace {

// The pixel size, slice spacing, unit and origin: OME-XML's physical sizes and first plane's
// position; else, in ImageJ's files (its unit) or with no unit, the resolution tags (inch and
// centimetre resolutions are print sizes, 72 dpi, not the sample's) and ImageJ's spacing=.
// Notes say which sizes the file did not give.
void placePixels(const TiffFile& tiff, const TiffPlaneOrder& order, VolumeLayout& layout) {
  double sizeX = 0.0, sizeY = 0.0;  // 0: not in the file
  if (order.kind == "OME") {
    sizeX = order.sizeX;
    sizeY = order.sizeY;
    if (order.hasOrigin) layout.origin = {order.origin[0], order.origin[1], order.origin[2]};
  } else {
    uint16_t resolutionUnit = RESUNIT_INCH;
    TIFFGetFieldDefaulted(tiff.get(), TIFFTAG_RESOLUTIONUNIT, &resolutionUnit);
    if (order.kind == "ImageJ" || resolutionUnit == RESUNIT_NONE) {
      const auto size = [&](ttag_t tag) {
        float res = 0.0f;
        return TIFFGetField(tiff.get(), tag, &res) && res > 0.0f && std::isfinite(1.0 / res)
                   ? 1.0 / res
                   : 0.0;
      };
      sizeX = size(TIFFTAG_XRESOLUTION);
      sizeY = size(TIFFTAG_YRESOLUTION);
    }
  }
  // One of the two given: square pixels, as ImageJ and Bio-Formats assume.
  if (sizeX > 0.0 && !(sizeY > 0.0)) {
    sizeY = sizeX;
    layout.notes.push_back("no pixel height in the file: its width assumed");
  } else if (sizeY > 0.0 && !(sizeX > 0.0)) {
    sizeX = sizeY;
    layout.notes.push_back("no pixel width in the file: its height assumed");
  } else if (!(sizeX > 0.0)) {
    layout.notes.push_back("no pixel size in the file: 1 assumed");
  }
  if (sizeX > 0.0) layout.spacing.x = sizeX;
  if (sizeY > 0.0) layout.spacing.y = sizeY;
  if (order.sizeZ > 0.0)
    layout.spacing.z = order.sizeZ;
  else
    layout.notes.push_back("no slice spacing in the file: 1 assumed");
  if (!order.unit.empty()) layout.notes.push_back("spacing unit: " + quoteText(order.unit, 20));
  layout.unit = lengthUnitName(order.unit);
}

// The type, channels, time points, spacing and notes of a stack whose first page is the
// current page of `tiff`, as `order` lays its pages out; returns the channel of pages to read
// (0 when the channels are a pixel's samples).
int64_t describeStack(const std::string& path, const TiffFile& tiff, const PageFormat& f,
                      const TiffPlaneOrder& order, int channel, int frame, VolumeLayout& layout) {
  layout.type = scalarOf(tiff, f);
  // Channels are the samples of a pixel (RGB), or pages (an ImageJ hyperstack, OME-TIFF).
  const int64_t channels = f.samples > 1 ? f.samples : order.channels;
  checkChannel(path, channel, channels);
  layout.channel = channel;
  layout.channelCount = int(channels);
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
  return f.samples > 1 ? 0 : channel;
}

// An OME-XML file (a companion, `.companion.ome`) whose TiffData name the TIFF files.
Volume loadOmeXml(const std::string& path, const std::string& xmlFile, int channel, int frame) {
  constexpr uint64_t kMaxXml = uint64_t(64) << 20;
  const uint64_t size = regularFileSize(xmlFile);
  if (size > kMaxXml)
    failLoad(xmlFile, "an OME-XML file of " + std::to_string(size) + " bytes: more than 64 MiB");
  const std::vector<uint8_t> raw = readFileRange(xmlFile, 0, size, "OME-XML");
  const std::string text(raw.begin(), raw.end());
  TiffPlaneOrder order = tiffPlaneOrder(xmlFile, text, 1);
  if (order.kind != "OME") failLoad(xmlFile, "no OME-XML Pixels element in it");
  const auto named = std::find_if(order.blocks.begin(), order.blocks.end(),
                                  [](const TiffDataBlock& b) { return !b.file.empty(); });
  if (named == order.blocks.end())
    failLoad(xmlFile, "names no TIFF file (no TiffData with a UUID FileName)");
  // The first file named gives the pages' format; every other page must agree with it.
  TiffFile tiff(omeFileBeside(xmlFile, xmlFile, named->file, "a TiffData"));
  if (!TIFFSetDirectory(tiff.get(), tdir_t(named->ifd)))
    tiff.fail("has no page " + std::to_string(named->ifd));
  const PageFormat f = pageFormat(tiff);
  order = tiffPlaneOrder(xmlFile, text, f.samples);  // RGB planes count samples among SizeC
  VolumeLayout layout;
  const int64_t pageChannel = describeStack(path, tiff, f, order, channel, frame, layout);
  std::vector<uint8_t> bytes = readOmeDataset(path, xmlFile, order, f, pageChannel,
                                              f.samples > 1 ? channel : 0, frame, layout);
  const size_t pageBytes = size_t(f.width) * f.height * fileScalarSize(layout.type);
  layout.dims = {int64_t(f.width), int64_t(f.height), int64_t(bytes.size() / pageBytes)};
  layout.bigEndian = hostIsBigEndian();
  return makeVolume(path, layout, std::move(bytes));
}

// A folder of one-page files (the usual stack: a scanner's or microscope's slices), each file
// read and decoded on its own core; nullopt when a file holds several pages or OME-XML, or the
// first describes channels or time points over pages, which the general reading handles.
std::optional<Volume> loadSinglePages(const std::string& path,
                                      const std::vector<std::string>& files, int channel,
                                      int frame) {
  VolumeLayout layout;
  PageFormat format;
  {
    TiffFile first(files[0]);
    if (TIFFNumberOfDirectories(first.get()) != 1) return std::nullopt;
    format = pageFormat(first);
    char* description = nullptr;
    std::string text;
    if (TIFFGetField(first.get(), TIFFTAG_IMAGEDESCRIPTION, &description) && description)
      text = std::string(description).substr(0, 1 << 24);
    if (!omeMetadataFile(text).empty()) return std::nullopt;
    const TiffPlaneOrder order = tiffPlaneOrder(files[0], text, format.samples);
    if (order.kind == "OME" || order.channels > 1 || order.frames > 1) return std::nullopt;
    describeStack(path, first, format, order, channel, frame, layout);
  }
  layout.dims = {int64_t(format.width), int64_t(format.height), int64_t(files.size())};
  const auto pageBytes =
      size_t(dataByteCount(path, {layout.dims[0], layout.dims[1], 1}, layout.type));
  std::vector<uint8_t> bytes(size_t(dataByteCount(path, layout.dims, layout.type)));
  std::atomic<bool> severalPages{false};
  parallelChunks(files.size(), 1, 0, [&](size_t begin, size_t end, size_t) {
    for (size_t n = begin; n < end && !severalPages; ++n) {
      TiffFile tiff(files[n]);
      if (TIFFNumberOfDirectories(tiff.get()) != 1) {
        severalPages = true;
        return;
      }
      const PageFormat f = pageFormat(tiff);
      if (!(f == format))
        tiff.fail("page " + std::to_string(n) + " is " + f.text() + ", the first " + format.text() +
                  ": all pages must agree");
      readPage(tiff, f, f.samples > 1 ? channel : 0, bytes.data() + n * pageBytes);
    }
  });
  if (severalPages) return std::nullopt;
  layout.bigEndian = hostIsBigEndian();  // libtiff gives native order
  layout.sourceFiles = files;
  return makeVolume(path, layout, std::move(bytes));
}

// Where a page is: its file (an index into the list) and its directory's offset in it.
struct PagePlace {
  size_t file = 0;
  uint64_t offset = 0;
};

// Decodes `pages` into `out`, one after another (`pageBytes` each), on every core: each chunk
// of consecutive pages opens its files itself and jumps to each page by its offset.
void readPages(const std::vector<std::string>& files, const std::vector<PagePlace>& pages,
               int channel, size_t pageBytes, uint8_t* out) {
  parallelChunks(pages.size(), 1, 0, [&](size_t first, size_t last, size_t) {
    std::optional<TiffFile> tiff;
    size_t open = SIZE_MAX;
    for (size_t n = first; n < last; ++n) {
      if (pages[n].file != open) {
        tiff.emplace(files[pages[n].file]);
        open = pages[n].file;
      }
      if (!TIFFSetSubDirectory(tiff->get(), pages[n].offset))
        tiff->fail("cannot read page " + std::to_string(n) + " again");
      readPage(*tiff, pageFormat(*tiff), channel, out + n * pageBytes);  // strips may differ
    }
  });
}

}  // namespace

Volume loadOmeCompanion(const std::string& path, int channel, int frame) {
  return loadOmeXml(path, path, channel, frame);
}

Volume loadTiff(const std::string& path, int channel, int frame) {
  std::error_code ec;
  std::vector<std::string> files;
  if (std::filesystem::is_directory(path, ec)) {
    files = sliceFilesIn(path, {".tif", ".tiff"});
    if (files.empty()) failLoad(path, "no TIFF file in the folder");
  } else {
    files.push_back(path);
  }
  if (files.size() > 1)
    if (std::optional<Volume> volume = loadSinglePages(path, files, channel, frame))
      return std::move(*volume);

  // Pages in order: every page of every file, its format checked and, when wanted, its place
  // noted; the wanted pages are then decoded on every core.
  VolumeLayout layout;
  PageFormat format;
  std::vector<uint8_t> bytes;
  std::vector<PagePlace> wanted;
  int64_t pages = 0, pageChannel = 0;
  TiffPlaneOrder order;
  size_t pageBytes = 0;
  for (size_t fileIndex = 0; fileIndex < files.size(); ++fileIndex) {
    const std::string& file = files[fileIndex];
    TiffFile tiff(file);
    do {
      const PageFormat f = pageFormat(tiff);
      if (pages == 0) {
        format = f;
        char* description = nullptr;
        std::string text;
        if (TIFFGetField(tiff.get(), TIFFTAG_IMAGEDESCRIPTION, &description) && description)
          text = std::string(description).substr(0, 1 << 24);  // OME-XML of many files
        const std::string metadata = omeMetadataFile(text);
        if (!metadata.empty()) {  // the XML is in a companion file beside it
          const std::string companion = omeFileBeside(path, file, metadata, "its OME metadata");
          std::error_code missing;
          if (!std::filesystem::is_regular_file(companion, missing))
            failLoad(path, "its OME metadata file " + quoteText(metadata) + " is missing");
          return loadOmeXml(path, companion, channel, frame);
        }
        order = tiffPlaneOrder(file, text, f.samples);
        pageChannel = describeStack(path, tiff, f, order, channel, frame, layout);
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
        dataByteCount(file, {int64_t(f.width), int64_t(f.height), int64_t(wanted.size()) + 1},
                      layout.type);
        wanted.push_back({fileIndex, TIFFCurrentDirOffset(tiff.get())});
      }
      ++pages;
    } while (TIFFReadDirectory(tiff.get()));
    if (!order.blocks.empty()) break;
  }
  if (order.blocks.empty()) {
    bytes.resize(wanted.size() * pageBytes);
    readPages(files, wanted, format.samples > 1 ? channel : 0, pageBytes, bytes.data());
  }
  layout.dims = {int64_t(format.width), int64_t(format.height),
                 int64_t(bytes.size() / std::max<size_t>(pageBytes, 1))};
  layout.bigEndian = hostIsBigEndian();  // libtiff gives native order
  layout.sourceFiles = files;
  return makeVolume(path, layout, std::move(bytes));
}

}  // namespace ewa
