// VolumeSaveJob: std::async around writeVolume and saveTransferFunction.
#include "ui/volume_save_job.h"

#include <cstdio>
#include <filesystem>

#include "io/transfer_function_io.h"
#include "io/volume_writer.h"

namespace ewa {

void VolumeSaveJob::start(std::shared_ptr<const Volume> volume, TransferFunction tf,
                          const std::string& path, std::optional<VoxelRange> crop) {
  path_ = path;
  started_ = std::chrono::steady_clock::now();
  // The volume is shared, not copied: the window may open another meanwhile.
  future_ =
      std::async(std::launch::async, [volume = std::move(volume), tf = std::move(tf), path, crop] {
        if (crop)
          writeVolume(path, cropVolume(*volume, *crop));
        else
          writeVolume(path, *volume);  // not copied
        const std::string sidecar = sidecarTransferFunctionPath(path);
        saveTransferFunction(sidecar, tf);
        std::error_code ec;
        const auto bytes = std::filesystem::file_size(path, ec);
        char size[48];
        std::snprintf(size, sizeof size, " (%.1f MB)", ec ? 0.0 : double(bytes) / 1e6);
        return "saved " + path + size + " and its transfer function " +
               std::filesystem::path(sidecar).filename().string();
      });
}

double VolumeSaveJob::elapsedSeconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
}

bool VolumeSaveJob::poll(std::string* text, bool* failed) {
  if (!future_.valid()) return false;
  if (future_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return false;
  const double seconds = elapsedSeconds();
  try {
    char took[32];
    std::snprintf(took, sizeof took, " in %.1f s", seconds);
    *text = future_.get() + took;
    *failed = false;
  } catch (const std::exception& e) {
    *text = e.what();
    *failed = true;
  }
  future_ = {};
  return true;
}

}  // namespace ewa
