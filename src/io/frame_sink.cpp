// Turntable outputs: numbered PNG frames through frame_names, or a video through VideoWriter.
#include "io/frame_sink.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>

#include "io/frame_names.h"
#include "io/video_writer.h"

namespace ewa {

namespace {

// Each frame its own PNG, written atomically.
class PngFrameSink : public FrameSink {
 public:
  PngFrameSink(FrameNaming naming, int count) : naming_(std::move(naming)), count_(count) {}
  void add(const Image8& frame, int index) override { writePng(fileOf(index), frame); }
  void finish() override {}
  std::string description() const override { return naming_.text; }
  std::string fileOf(int index) const override { return frameFileName(naming_, index, count_); }

 private:
  FrameNaming naming_;
  int count_;
};

class VideoFrameSink : public FrameSink {
 public:
  VideoFrameSink(const std::string& path, int fps) : path_(path), writer_(path, fps) {}
  void add(const Image8& frame, int) override { writer_.add(frame); }
  void finish() override { writer_.finish(); }
  std::string description() const override { return path_; }
  std::string fileOf(int) const override { return path_; }

 private:
  std::string path_;
  VideoWriter writer_;
};

}  // namespace

namespace {

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

}  // namespace

bool isVideoPath(const std::string& path) {
  const std::string ext = lowerExtension(path);
  return ext == ".mp4" || ext == ".webm";
}

std::unique_ptr<FrameSink> openFrameSink(const std::string& output, int count, int fps) {
  if (count < 1) throw std::invalid_argument("--turntable: needs at least 1 frame");
  if (isVideoPath(output)) return std::make_unique<VideoFrameSink>(output, fps);
  // Other video names would otherwise become folders of PNGs, which is never what was meant.
  for (const char* ext : {".avi", ".mov", ".mkv", ".gif", ".m4v", ".mpg", ".ogv"})
    if (lowerExtension(output) == ext)
      throw std::runtime_error(output + ": not a video format ewaview writes (use .mp4 or .webm)");
  const FrameNaming naming = parseFrameNaming(output);
  const std::filesystem::path folder =
      naming.pattern ? std::filesystem::path(frameFileName(naming, 0, count)).parent_path()
                     : std::filesystem::path(naming.text);
  if (!folder.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (!std::filesystem::is_directory(folder))
      throw std::runtime_error(folder.string() + ": cannot create the turntable folder");
  }
  return std::make_unique<PngFrameSink>(naming, count);
}

}  // namespace ewa
