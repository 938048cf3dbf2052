// Turntable outputs: numbered PNG frames through frame_names, or a video through VideoWriter.
#include "io/frame_sink.h"

#include <algorithm>
#include <cctype>
#include <condition_variable>
#include <deque>
#include <exception>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

#include "io/frame_names.h"
#include "io/video_writer.h"

namespace ewa {

namespace {

// Each frame its own PNG, written atomically, encoded on worker threads: a frame's encoding
// costs several times what a GPU takes to render it, so the next frames render meanwhile. A few
// frames wait at most; a failed frame's error comes from the next add() or from finish().
class PngFrameSink : public FrameSink {
 public:
  PngFrameSink(FrameNaming naming, int count)
      : naming_(std::move(naming)),
        count_(count),
        workers_(std::clamp(std::thread::hardware_concurrency(), 2u, 9u) - 1u) {}
  // Frames handed over are written even when the run ends in an error: each is a picture
  // rendered, as before it the frames were written one by one.
  ~PngFrameSink() override {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    changed_.notify_all();
    for (std::thread& t : threads_) t.join();
  }
  void add(const Image8& frame, int index) override {
    std::pair<int, Image8> item(index, frame);  // copied before the workers are held up
    std::unique_lock<std::mutex> lock(mutex_);
    if (threads_.empty())
      for (unsigned i = 0; i < workers_; ++i) threads_.emplace_back([this] { work(); });
    changed_.wait(lock, [&] { return waiting_.size() < workers_ || failure_; });
    if (failure_) std::rethrow_exception(failure_);
    waiting_.push_back(std::move(item));
    changed_.notify_all();
  }
  void finish() override {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return (waiting_.empty() && writing_ == 0) || failure_; });
    if (failure_) std::rethrow_exception(failure_);
  }
  std::string description() const override { return naming_.text; }
  std::string fileOf(int index) const override { return frameFileName(naming_, index, count_); }

 private:
  void work() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      changed_.wait(lock, [&] { return stop_ || !waiting_.empty(); });
      if (waiting_.empty()) return;  // stopped, nothing left
      auto [index, frame] = std::move(waiting_.front());
      waiting_.pop_front();
      ++writing_;
      lock.unlock();
      std::exception_ptr failure;
      try {
        writePng(fileOf(index), frame);
      } catch (...) {
        failure = std::current_exception();
      }
      lock.lock();
      --writing_;
      if (failure && !failure_) failure_ = failure;
      changed_.notify_all();
    }
  }

  FrameNaming naming_;
  int count_;
  unsigned workers_;  // threads, and frames that may wait for them
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::pair<int, Image8>> waiting_;
  int writing_ = 0;
  bool stop_ = false;
  std::exception_ptr failure_;  // the first frame that failed
  std::vector<std::thread> threads_;
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
