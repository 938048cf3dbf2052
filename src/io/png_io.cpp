// PNG reading and writing through stb_image / stb_image_write.
#include "io/png_io.h"

#include <string_view>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include <stb_image.h>
#include <stb_image_write.h>

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
