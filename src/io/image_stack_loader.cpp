// Slices from ordinary images (PNG, JPEG, BMP, PGM/PPM) through stb_image, as scanners and
// microscopes export them: one image a slice, in natural name order.
#include <stb_image.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/parallel_chunks.h"
#include "io/byte_order.h"
#include "io/file_bytes.h"
#include "io/file_listing.h"
#include "io/format_loaders.h"
#include "io/jpeg_header_check.h"
#include "io/load_failure.h"
#include "io/png_chunk_check.h"
#include "io/volume_layout.h"

namespace ewa {

namespace {

namespace fs = std::filesystem;

constexpr size_t kMaxSlices = 100000;

// What stb_image says an image holds, before decoding it.
struct ImageShape {
  int width = 0, height = 0, components = 0;
  bool sixteen = false;
  bool operator==(const ImageShape& o) const {
    return width == o.width && height == o.height && components == o.components &&
           sixteen == o.sixteen;
  }
  std::string text() const {
    static const char* kKinds[] = {"", "grey", "grey and alpha", "RGB", "RGBA"};
    return std::to_string(width) + " x " + std::to_string(height) + " " +
           kKinds[std::clamp(components, 0, 4)] + (sixteen ? " 16-bit" : " 8-bit");
  }
};

enum class ImageKind { Png, Jpeg, Bmp, Pnm };

// The format by its first bytes. Only the four named are given to stb_image, which would
// otherwise pick any of its decoders (GIF, PSD, HDR, PIC, TGA) by the content.
ImageKind imageKind(const std::string& file, const std::vector<uint8_t>& b) {
  static const uint8_t kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (b.size() >= 8 && std::equal(kPng, kPng + 8, b.begin())) return ImageKind::Png;
  if (b.size() >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF) return ImageKind::Jpeg;
  if (b.size() >= 2 && b[0] == 'B' && b[1] == 'M') return ImageKind::Bmp;
  if (b.size() >= 2 && b[0] == 'P' && (b[1] == '5' || b[1] == '6')) return ImageKind::Pnm;
  failLoad(file, "not a PNG, JPEG, BMP or binary PGM/PPM image (by its first bytes)");
}

ImageShape shapeOf(const std::string& file, const std::vector<uint8_t>& bytes) {
  if (bytes.size() > size_t(INT32_MAX)) failLoad(file, "image file is too large");
  const ImageKind kind = imageKind(file, bytes);
  // stb_image asserts on a scan whose tables no segment defined (found by fuzzing).
  if (kind == ImageKind::Jpeg)
    if (const std::string problem = jpegScanTablesProblem(bytes.data(), bytes.size());
        !problem.empty())
      failLoad(file, "corrupt JPEG: " + problem);
  // stb_image sizes its buffer by an IDAT chunk's claimed length before reading it.
  if (kind == ImageKind::Png)
    if (const std::string problem = pngChunksProblem(bytes.data(), bytes.size()); !problem.empty())
      failLoad(file, "corrupt PNG: " + problem);
  ImageShape s;
  const auto* data = bytes.data();
  const int size = int(bytes.size());
  if (!stbi_info_from_memory(data, size, &s.width, &s.height, &s.components))
    failLoad(file, std::string("not an image stb_image reads (") +
                       (stbi_failure_reason() ? stbi_failure_reason() : "unknown format") + ")");
  s.sixteen = stbi_is_16_bit_from_memory(data, size) != 0;
  if (s.width <= 0 || s.height <= 0 || s.components < 1 || s.components > 4)
    failLoad(file, "bad image size or components");
  // stb_image fills what a cut file lacks, so a header alone could make a huge image: the
  // pixels must fit in the file's bytes, or their compression stay within deflate's 1032:1
  // (JPEG's flattest blocks compress less far). BMP and PNM are not compressed (1-bit BMP
  // rows: 8 pixels a byte).
  const bool plain = kind == ImageKind::Bmp || kind == ImageKind::Pnm;
  const double pixels = double(s.width) * double(s.height) * s.components * (s.sixteen ? 2 : 1);
  if (pixels > double(bytes.size() + 1024) * (plain ? 24.0 : 1032.0))
    failLoad(file, "its header promises " + s.text() + " pixels, more than its " +
                       std::to_string(bytes.size()) + " bytes can hold (truncated or corrupt?)");
  return s;
}

// The images of the folder `path` is or lies in, in natural order.
std::vector<std::string> sliceFiles(const std::string& path, bool folder) {
  const fs::path dir = folder ? fs::path(path) : fs::path(path).parent_path();
  const std::vector<std::string> files =
      sliceFilesIn(dir.empty() ? "." : dir.string(), sliceImageExtensions());
  if (files.size() > kMaxSlices)
    failLoad(path, "more than " + std::to_string(kMaxSlices) + " images in the folder");
  if (files.empty()) failLoad(path, "no PNG, JPEG, BMP or PGM/PPM image in the folder");
  return files;
}

// One component of every pixel of a decoded image, written to `out`; false when the image's
// colour components differ somewhere (it is not grey stored as colour).
bool copyComponent(const uint8_t* pixels, const ImageShape& s, int component, uint8_t* out) {
  const size_t bytes = s.sixteen ? 2 : 1, stride = bytes * size_t(s.components);
  const size_t count = size_t(s.width) * size_t(s.height);
  bool grey = true;
  for (size_t i = 0; i < count; ++i) {
    const uint8_t* p = pixels + i * stride;
    if (s.components >= 3)
      grey = grey && std::equal(p, p + bytes, p + bytes) && std::equal(p, p + bytes, p + 2 * bytes);
    std::copy(p + component * bytes, p + (component + 1) * bytes, out + i * bytes);
  }
  return grey;
}

// Reads and decodes one slice into `out` (its place in the volume), after checking that it
// agrees with the first; returns whether it is grey (copyComponent).
bool readSlice(const std::string& file, const ImageShape& first, const std::string& firstName,
               int channel, uint8_t* out) {
  const std::vector<uint8_t> data = readFileRange(file, 0, regularFileSize(file), "image");
  const ImageShape s = shapeOf(file, data);
  if (!(s == first))
    failLoad(file, "is " + s.text() + ", the first image (" + firstName + ") " + first.text() +
                       ": all slices must agree");
  int w = 0, h = 0, c = 0;
  // stb_image keeps its last reason, set by whichever format it tried; a decoder may fail
  // without setting one, so a reason unchanged by decoding is not shown.
  const char* before = stbi_failure_reason();
  const auto* in = data.data();
  const int size = int(data.size());
  std::unique_ptr<void, void (*)(void*)> pixels(
      s.sixteen ? static_cast<void*>(stbi_load_16_from_memory(in, size, &w, &h, &c, 0))
                : static_cast<void*>(stbi_load_from_memory(in, size, &w, &h, &c, 0)),
      stbi_image_free);
  if (!pixels) {
    const char* why = stbi_failure_reason();
    failLoad(file, std::string("cannot decode the image (") +
                       (why && why != before ? why : "corrupt or truncated data") + ")");
  }
  if (w != s.width || h != s.height || c != s.components)
    failLoad(file, "decodes to another size than its header says");
  return copyComponent(static_cast<const uint8_t*>(pixels.get()), s, channel, out);
}

}  // namespace

const std::vector<std::string>& sliceImageExtensions() {
  static const std::vector<std::string> kExtensions = {".png", ".jpg", ".jpeg",
                                                       ".bmp", ".pgm", ".ppm"};
  return kExtensions;
}

Volume loadImageStack(const std::string& path, int channel) {
  std::error_code ec;
  const bool folder = fs::is_directory(path, ec);
  const std::vector<std::string> files = sliceFiles(path, folder);
  // The first image says what every slice must be.
  const ImageShape first =
      shapeOf(files[0], readFileRange(files[0], 0, regularFileSize(files[0]), "image"));
  checkChannel(path, channel, first.components >= 3 ? 3 : 1);  // alpha is no channel
  VolumeLayout layout;
  layout.type = first.sixteen ? FileScalar::UInt16 : FileScalar::UInt8;
  layout.dims = {first.width, first.height, int64_t(files.size())};
  // The whole stack fits, before any image is decoded; slices are decoded on every core.
  const auto sliceBytes = size_t(dataByteCount(path, {first.width, first.height, 1}, layout.type));
  std::vector<uint8_t> bytes(size_t(dataByteCount(path, layout.dims, layout.type)));
  const std::string firstName = fs::path(files[0]).filename().string();
  const std::vector<char> greyChunks =
      parallelChunkResults<char>(files.size(), 1, 0, [&](size_t begin, size_t end) {
        bool grey = true;
        for (size_t n = begin; n < end; ++n)
          grey = readSlice(files[n], first, firstName, channel, &bytes[n * sliceBytes]) && grey;
        return char(grey);
      });
  const bool grey = std::all_of(greyChunks.begin(), greyChunks.end(), [](char g) { return g; });
  layout.bigEndian = hostIsBigEndian();  // stb_image gives native order
  layout.sourceFiles = files;
  layout.notes.push_back((files.size() == 1
                              ? std::string("1 image as a slice")
                              : std::to_string(files.size()) + " images as slices, in name order") +
                         "; images carry no slice spacing: 1 assumed");
  if (first.components >= 3 && !grey) {
    layout.channel = channel;
    layout.channelCount = 3;
    layout.notes.push_back("colour images; showing channel " + std::to_string(channel) +
                           " (--channel N picks another of 3)");
  } else if (first.components >= 3) {
    layout.notes.push_back("grey images stored as colour: one channel read");
  }
  return makeVolume(path, layout, std::move(bytes));
}

}  // namespace ewa
