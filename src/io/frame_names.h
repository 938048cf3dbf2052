// Names of output images: turntable frames from a pattern or a folder, screenshot files.
#pragma once

#include <ctime>
#include <functional>
#include <string>

namespace ewa {

// How --output names the frames of a turntable.
struct FrameNaming {
  bool pattern = false;  // true: a printf pattern with one integer conversion ("f_%03d.png")
  std::string text;      // the pattern, or the folder
};

// An --output containing '%' is a pattern: exactly one conversion %d or %0Nd (%% for a
// literal '%'), ending in ".png". Anything else is a folder (made when missing), whose frames
// are frame_000.png, frame_001.png, ... Throws std::invalid_argument("output: problem").
FrameNaming parseFrameNaming(const std::string& output);
// File of frame `index` (0-based) of `count`: the pattern filled in, or
// folder/frame_NNN.png with at least 3 digits (more when count needs them).
std::string frameFileName(const FrameNaming& naming, int index, int count);

// "dir/BASE.EXT" (dir empty: the current folder, `extension` with its dot); when that file
// exists, or `taken` says the name is promised to a file not written yet, "dir/BASE-2.EXT",
// "-3"...: a name nothing is written to yet.
std::string unusedFileName(const std::string& dir, const std::string& base,
                           const std::string& extension,
                           const std::function<bool(const std::string&)>& taken = nullptr);

// "dir/ewaview-STEM-YYYYMMDD-HHMMSS.png" (dir empty: the current folder); when that file
// exists or is `taken`, "-2", "-3"... is added before ".png" (unusedFileName).
std::string screenshotFileName(const std::string& dir, const std::string& volumeName,
                               std::time_t when,
                               const std::function<bool(const std::string&)>& taken = nullptr);

}  // namespace ewa
