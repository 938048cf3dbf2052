// VolumeSaveJob: writes the volume on screen (NRRD, NIfTI, MetaImage or TIFF), with its transfer
// function beside it, on a worker thread, so the window keeps drawing while it is compressed.
#pragma once

#include <chrono>
#include <future>
#include <memory>
#include <optional>
#include <string>

#include "core/transfer_function.h"
#include "core/volume.h"
#include "core/volume_crop.h"

namespace ewa {

class VolumeSaveJob {
 public:
  // Starts writing `volume` (only `crop`'s voxels when given: cropVolume) to `path` (writeVolume,
  // atomically) and then `tf` to the sidecar the file is opened with again
  // (sidecarTransferFunctionPath), so it reopens looking the same.
  void start(std::shared_ptr<const Volume> volume, TransferFunction tf, const std::string& path,
             std::optional<VoxelRange> crop = std::nullopt);
  bool running() const { return future_.valid(); }
  const std::string& path() const { return path_; }
  double elapsedSeconds() const;
  // Once the work is done: true, with `text` saying what was written ("saved PATH (N MB) and
  // its transfer function in T s", then "; " and each thing the format left out:
  // savedVolumeLosses), or the one-line problem with `failed` set. False while still
  // running (or when nothing was started).
  bool poll(std::string* text, bool* failed);

 private:
  struct Saved {
    std::string text;    // "saved PATH ..."
    std::string losses;  // "; ..." for each, or ""
  };
  std::future<Saved> future_;
  std::string path_;
  std::chrono::steady_clock::time_point started_;
};

}  // namespace ewa
