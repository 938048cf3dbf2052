// PNG reading and writing (stb), RGBA8 or RGB8 images.
#pragma once

#include <string>

#include "core/image8.h"

namespace ewa {

// Writes `image` to `path` through a temporary file renamed into place, so a crash never
// leaves half a PNG. Throws std::runtime_error("path: problem") on failure.
void writePng(const std::string& path, const Image8& image);
// The PNG file's bytes in memory (for Jupyter and the like). Throws std::runtime_error.
std::string encodePng(const Image8& image);
// Reads a PNG as RGBA8 (channels = 4). Throws std::runtime_error("path: problem").
Image8 readPng(const std::string& path);

}  // namespace ewa
