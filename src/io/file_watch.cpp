// FileWatch: stamps from std::filesystem, compared at most every interval.
#include "io/file_watch.h"

#include <filesystem>

namespace ewa {

std::optional<FileStamp> fileStamp(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) return std::nullopt;
  FileStamp stamp;
  const fs::file_time_type time = fs::last_write_time(path, ec);
  if (ec) return std::nullopt;
  stamp.modified = int64_t(time.time_since_epoch().count());
  if (fs::is_regular_file(status)) {
    stamp.size = fs::file_size(path, ec);
    if (ec) return std::nullopt;
  }
  return stamp;
}

void FileWatch::watch(const std::string& path) {
  path_ = path;
  loaded_ = path.empty() ? std::nullopt : fileStamp(path);
  pending_.reset();
  lastLook_ = -1e300;
}

bool FileWatch::changed(double nowSeconds, double intervalSeconds) {
  if (path_.empty() || nowSeconds - lastLook_ < intervalSeconds) return false;
  lastLook_ = nowSeconds;
  const std::optional<FileStamp> now = fileStamp(path_);
  if (!now || now == loaded_) {  // missing (being replaced), or as loaded
    pending_.reset();
    return false;
  }
  if (now != pending_) {  // a new stamp: look again before taking it
    pending_ = now;
    return false;
  }
  loaded_ = now;
  pending_.reset();
  return true;
}

}  // namespace ewa
