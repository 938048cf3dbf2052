// Reading a video's frames back as RGB images through FFmpeg's libraries (tests, checks).
#pragma once

#include <string>
#include <vector>

#include "io/png_io.h"

namespace ewa {

struct DecodedVideo {
  std::string codec;           // the decoder's name, e.g. "h264", "vp9"
  double fps = 0.0;            // the stream's average frame rate
  std::vector<Image8> frames;  // RGB (channels 3), top row first, in display order
};

// Decodes every frame of the first video stream, converting with the colour matrix and range the
// stream is tagged with. Throws std::runtime_error("path: problem").
DecodedVideo readVideo(const std::string& path);

}  // namespace ewa
