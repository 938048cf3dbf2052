// ArchiveCache: the last archive unpacked, kept while it stays the same file.
#include "io/archive_cache.h"

#include <filesystem>

namespace ewa {

namespace {

// What tells one file from its later versions: where it is, its size and when it changed.
std::string fileKey(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path absolute = fs::absolute(path, ec);
  const uintmax_t size = fs::file_size(path, ec);
  if (ec) return "";
  const auto changed = fs::last_write_time(path, ec).time_since_epoch().count();
  if (ec) return "";
  return absolute.string() + "\n" + std::to_string(size) + "\n" + std::to_string(changed);
}

}  // namespace

std::shared_ptr<const ExtractedArchive> ArchiveCache::unpack(const std::string& path) {
  const std::string key = fileKey(path);
  std::lock_guard<std::mutex> lock(mutex_);
  if (!key.empty() && key == key_ && kept_) return kept_;
  kept_.reset();  // the old folder goes first, unless a load still holds it
  key_.clear();
  auto unpacked = std::make_shared<const ExtractedArchive>(extractArchive(path));
  ++extractions_;
  if (!key.empty()) {
    key_ = key;
    kept_ = unpacked;
  }
  return unpacked;
}

uint64_t ArchiveCache::extractions() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return extractions_;
}

}  // namespace ewa
