// Physical-memory bound on header-driven allocations, so a lying header fails fast.
#include "io/memory_limit.h"

#include <sys/resource.h>
#include <unistd.h>

#include <cstddef>
#include <limits>

#include "io/load_failure.h"

namespace ewa {

// Without this bound a header claiming terabytes would drive the machine into swap or the OOM
// killer before any size check against the data could fail.

uint64_t physicalMemoryBytes() {
  static const uint64_t bytes = [] {
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long pageSize = sysconf(_SC_PAGESIZE);
    if (pages <= 0 || pageSize <= 0) return uint64_t{1} << 40;  // unknown: 1 TiB
    const auto p = static_cast<uint64_t>(pages);
    const auto s = static_cast<uint64_t>(pageSize);
    if (p > std::numeric_limits<uint64_t>::max() / s) return std::numeric_limits<uint64_t>::max();
    return p * s;
  }();
  return bytes;
}

uint64_t usableMemoryBytes() {
  uint64_t bytes = physicalMemoryBytes();
  for (const int resource : {RLIMIT_AS, RLIMIT_DATA}) {
    struct rlimit limit {};
    if (getrlimit(resource, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY &&
        uint64_t(limit.rlim_cur) < bytes)
      bytes = uint64_t(limit.rlim_cur);
  }
  return bytes;
}

void checkAllocation(const std::string& path, uint64_t bytes, const std::string& what) {
  const uint64_t usable = usableMemoryBytes();
  if (bytes > std::numeric_limits<size_t>::max() || bytes > usable) {
    failLoad(path,
             what + " of " + std::to_string(bytes) + " bytes is more than this machine's memory (" +
                 std::to_string(usable) + " bytes " +
                 (usable < physicalMemoryBytes() ? "under this process's limit" : "in all") + ")");
  }
}

}  // namespace ewa
