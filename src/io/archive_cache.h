// ArchiveCache: the last archive unpacked, kept while it stays the same file, so that paging
// its frames, channels or series does not unpack it again.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>

#include "io/archive_extract.h"

namespace ewa {

class ArchiveCache {
 public:
  // The archive at `path` unpacked: the one kept when it is the same file (absolute path,
  // size and modification time), else unpacked now, replacing it (whose folder goes once no
  // load holds it). Thread-safe. Throws LoadError as extractArchive does.
  std::shared_ptr<const ExtractedArchive> unpack(const std::string& path);
  uint64_t extractions() const;  // how many times an archive was unpacked

 private:
  mutable std::mutex mutex_;
  std::string key_;
  std::shared_ptr<const ExtractedArchive> kept_;
  uint64_t extractions_ = 0;
};

}  // namespace ewa
