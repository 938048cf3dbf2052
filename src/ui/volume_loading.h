// VolumeLoadJob: opens a volume on a worker thread (file, transfer function, coarse levels),
// so the window keeps drawing the old one and shows progress meanwhile.
#pragma once

#include <chrono>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <string>

#include "core/transfer_function.h"
#include "core/volume.h"
#include "io/volume_loader.h"
#include "render/lod_renderer.h"

namespace ewa {

// A volume ready for the viewer.
struct LoadedVolume {
  std::shared_ptr<const Volume> volume;
  LodVolumes coarse;  // levels of detail for moving views
  TransferFunction tf;
  std::string name;                   // shown in the panel
  std::string path;                   // file it came from; empty for synthetic volumes
  std::optional<glm::dvec3> spacing;  // the spacing it was opened with in place of the file's
};

// Reads `path` (with `load`'s series and frame: --series, --frame) and picks its transfer
// function; throws std::exception("path: problem").
using VolumeOpener = std::function<LoadedVolume(const std::string& path, const LoadOptions& load)>;

class VolumeLoadJob {
 public:
  // Starts loading `path` (opener, then the coarse levels) on a worker thread.
  void start(const std::string& path, const LoadOptions& load, VolumeOpener opener);
  bool running() const { return future_.valid(); }
  const std::string& path() const { return path_; }
  double elapsedSeconds() const;
  // Once the work is done: the volume, or nothing with `error` set to its one-line message.
  // Returns false while still running (or when nothing was started).
  bool poll(std::optional<LoadedVolume>* result, std::string* error);

 private:
  std::future<LoadedVolume> future_;
  std::string path_;
  std::chrono::steady_clock::time_point started_;
};

}  // namespace ewa
