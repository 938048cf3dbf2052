// VolumeLoadJob: std::async around the opener and the coarse levels.
#include "ui/volume_loading.h"

namespace ewa {

void VolumeLoadJob::start(const std::string& path, const LoadOptions& load, VolumeOpener opener) {
  path_ = path;
  started_ = std::chrono::steady_clock::now();
  future_ = std::async(std::launch::async, [path, load, opener = std::move(opener)] {
    LoadedVolume loaded = opener(path, load);
    if (loaded.coarse.levels.empty() && loaded.volume)
      loaded.coarse = buildLodVolumes(*loaded.volume);
    return loaded;
  });
}

double VolumeLoadJob::elapsedSeconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
}

bool VolumeLoadJob::poll(std::optional<LoadedVolume>* result, std::string* error) {
  if (!future_.valid()) return false;
  if (future_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return false;
  try {
    *result = future_.get();
  } catch (const std::exception& e) {
    result->reset();
    *error = e.what();
  }
  future_ = {};
  return true;
}

}  // namespace ewa
