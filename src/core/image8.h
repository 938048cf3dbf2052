// An 8-bit RGB or RGBA picture: what renderers read back and PNG files hold.
#pragma once

#include <cstdint>
#include <vector>

namespace ewa {

struct Image8 {
  int width = 0;
  int height = 0;
  int channels = 4;             // 3 (RGB) or 4 (RGBA)
  std::vector<uint8_t> pixels;  // row-major, top row first
};

}  // namespace ewa
