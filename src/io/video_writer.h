// VideoWriter: RGB frames to an MP4 (H.264) or WebM (VP9) file through FFmpeg's libraries.
#pragma once

#include <memory>
#include <string>

#include "io/png_io.h"

namespace ewa {

class VideoWriter {
 public:
  // Opens a temporary file beside `path` now (making missing folders), so a bad path fails
  // before any frame is rendered; finish() renames it into place. The container and encoder
  // follow the extension: .mp4 is H.264 (libx264), .webm is VP9 (libvpx-vp9), both 4:2:0 with
  // BT.709 colours at a high quality setting. Throws std::runtime_error("path: problem"),
  // also when this FFmpeg has no such encoder.
  VideoWriter(const std::string& path, int fps);
  ~VideoWriter();  // without finish(): the temporary file is removed
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  // Encodes the next frame (RGB or RGBA, top row first). The first frame sets the video's size,
  // rounded down to even numbers (4:2:0 needs them: an odd last row or column is dropped);
  // later frames of another size are scaled to it.
  void add(const Image8& frame);
  // Flushes the encoder, writes the trailer and moves the file into place.
  void finish();

  int width() const;
  int height() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace ewa
