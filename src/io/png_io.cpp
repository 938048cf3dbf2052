// PNG reading and writing through stb_image / stb_image_write.
#include "io/png_io.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include <stb_image.h>
#include <stb_image_write.h>

namespace ewa {

void writePng(const std::string& path, const Image8& image) {
  if (image.width <= 0 || image.height <= 0 || (image.channels != 3 && image.channels != 4) ||
      image.pixels.size() != size_t(image.width) * image.height * image.channels)
    throw std::runtime_error(path + ": image to write has inconsistent size");
  const std::string tmp = path + ".tmp";
  if (!stbi_write_png(tmp.c_str(), image.width, image.height, image.channels,
                      image.pixels.data(), image.width * image.channels)) {
    std::remove(tmp.c_str());
    throw std::runtime_error(path + ": cannot write PNG");
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(tmp.c_str());
    throw std::runtime_error(path + ": cannot write PNG: " + why);
  }
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
