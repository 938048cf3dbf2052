// VolumeSaveJob: std::async around writeVolume and saveTransferFunction.
#include "ui/volume_save_job.h"

#include <cstdio>
#include <filesystem>
#include <vector>

#include "io/transfer_function_io.h"
#include "io/volume_writer.h"

namespace ewa {

namespace {

// "; TIFF keeps no patient axes ...; ..." after the message, or "".
std::string lossText(const std::vector<std::string>& losses) {
  std::string out;
  for (const std::string& loss : losses) out += "; " + loss;
  return out;
}

}  // namespace

void VolumeSaveJob::start(std::shared_ptr<const Volume> volume, TransferFunction tf,
                          const std::string& path, std::optional<VoxelRange> crop) {
  path_ = path;
  started_ = std::chrono::steady_clock::now();
  // The volume is shared, not copied: the window may open another meanwhile.
  future_ =
      std::async(std::launch::async, [volume = std::move(volume), tf = std::move(tf), path, crop] {
        // The volume itself is not copied.
        const std::vector<std::string> losses =
            crop ? writeVolumeAndLosses(path, cropVolume(*volume, *crop), volume->sourceFiles())
                 : writeVolumeAndLosses(path, *volume);
        const std::string sidecar = sidecarTransferFunctionPath(path);
        saveTransferFunction(sidecar, tf);
        std::error_code ec;
        auto bytes = std::filesystem::file_size(path, ec);
        if (!ec && savedVolumeFormat(path) == SavedVolumeFormat::MetaImageHeader)
          bytes += std::filesystem::file_size(metaImageDataFileOf(path), ec);  // and its data
        char size[48];
        std::snprintf(size, sizeof size, " (%.1f MB)", ec ? 0.0 : double(bytes) / 1e6);
        return Saved{"saved " + path + size + " and its transfer function " +
                         std::filesystem::path(sidecar).filename().string(),
                     lossText(losses)};
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
    const Saved saved = future_.get();
    *text = saved.text + took + saved.losses;
    *failed = false;
  } catch (const std::exception& e) {
    *text = e.what();
    *failed = true;
  }
  future_ = {};
  return true;
}

}  // namespace ewa
