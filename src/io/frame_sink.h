// FrameSink: where a turntable's frames go, numbered PNGs or one video file.
#pragma once

#include <memory>
#include <string>

#include "io/png_io.h"

namespace ewa {

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  // Stores the next frame; `index` counts from 0. Throws std::runtime_error("path: problem").
  virtual void add(const Image8& frame, int index) = 0;
  // Completes the output (a video's trailer); without it a video is discarded.
  virtual void finish() = 0;
  // Where the frames go, for messages: the folder, the pattern or the video file.
  virtual std::string description() const = 0;
  // The file frame `index` went to (the video file for a video).
  virtual std::string fileOf(int index) const = 0;
};

// True for the outputs written as a video: a name ending in .mp4 or .webm (any case).
bool isVideoPath(const std::string& path);

// The sink --output names for `count` frames: a video for isVideoPath (at `fps` frames per
// second), else numbered PNGs (see io/frame_names.h). The folder, pattern's folder or video
// file is checked or made now, so a bad path fails before any frame is rendered. Throws
// std::runtime_error / std::invalid_argument with one line "path: problem".
std::unique_ptr<FrameSink> openFrameSink(const std::string& output, int count, int fps);

}  // namespace ewa
