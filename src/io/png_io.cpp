// PNG reading and writing through stb_image / stb_image_write, the writer's deflate zlib's.
#include "io/png_io.h"

#include <stb_image.h>
#include <zlib.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string_view>

namespace {

// zlib's deflate in place of stb_image_write's own (its documented hook): on rendered pictures
// zlib's level 3 is faster than stb's level 8 and makes smaller files, and on a GPU encoding,
// not rendering, is what bounds a turntable. Allocated with malloc: stb frees it.
unsigned char* zlibForStb(unsigned char* data, int size, int* outSize, int /*quality*/) {
  constexpr int kLevel = 3;
  uLongf capacity = compressBound(uLong(size));
  auto* out = static_cast<unsigned char*>(std::malloc(capacity));
  if (!out) return nullptr;
  if (compress2(out, &capacity, data, uLong(size), kLevel) != Z_OK) {
    std::free(out);
    return nullptr;
  }
  *outSize = int(capacity);
  return out;
}

}  // namespace

// The writer compiled here, static (no clash with libstb's copy), to take the hook above.
#define STBIW_ZLIB_COMPRESS zlibForStb
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb_image_write.h>
#pragma GCC diagnostic pop

#include "io/atomic_file.h"

namespace ewa {

std::string encodePng(const Image8& image) {
  if (image.width <= 0 || image.height <= 0 || (image.channels != 3 && image.channels != 4) ||
      image.pixels.size() != size_t(image.width) * image.height * image.channels)
    throw std::runtime_error("image to write has inconsistent size");
  std::string png;
  const auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), size_t(size));
  };
  if (!stbi_write_png_to_func(append, &png, image.width, image.height, image.channels,
                              image.pixels.data(), image.width * image.channels))
    throw std::runtime_error("cannot encode PNG");
  return png;
}

void writePng(const std::string& path, const Image8& image) {
  // Encode in memory first: an encoder failure then never touches the file system.
  std::string png;
  try {
    png = encodePng(image);
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
  writeFileAtomically(path, png);
}

Image8 readPng(const std::string& path) {
  int w = 0, h = 0, n = 0;
  stbi_uc* data = stbi_load(path.c_str(), &w, &h, &n, 4);
  if (!data) {
    const char* why = stbi_failure_reason();
    throw std::runtime_error(path + ": cannot read PNG: " + (why ? why : "unknown error"));
  }
  Image8 img;
  img.width = w;
  img.height = h;
  img.channels = 4;
  img.pixels.assign(data, data + size_t(w) * h * 4);
  stbi_image_free(data);
  return img;
}

}  // namespace ewa
