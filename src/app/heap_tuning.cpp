// Heap tuning for llvmpipe: glibc's trim threshold raised, and huge pages asked for.
#include "app/heap_tuning.h"

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

#if defined(__GLIBC__)
#include <malloc.h>
#include <unistd.h>
#endif

namespace ewa {

bool keepFreedHeapForReuse() {
#if defined(__GLIBC__)
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (std::getenv("MALLOC_TRIM_THRESHOLD_") ||
      (tunables && std::strstr(tunables, "malloc.trim_threshold")))
    return false;
  constexpr int kTrimThreshold = 1 << 30;
  return mallopt(M_TRIM_THRESHOLD, kTrimThreshold) == 1;
#else
  return false;
#endif
}

namespace {

// The kernel's transparent-huge-page mode: "always", "madvise", "never" (empty if unknown).
std::string hugePageMode() {
  std::ifstream file("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string line;
  if (!std::getline(file, line)) return "";
  const size_t open = line.find('['), close = line.find(']');
  return open < close && close != std::string::npos ? line.substr(open + 1, close - open - 1) : "";
}

}  // namespace

std::string hugePageTunables(const char* tunables) {
#if defined(__GLIBC__) && defined(__linux__)
  if (tunables && std::strstr(tunables, "malloc.hugetlb")) return "";  // chosen, or done already
  if (hugePageMode() != "madvise") return "";
  std::string value = tunables && *tunables ? std::string(tunables) + ":" : std::string();
  return value + "glibc.malloc.hugetlb=1";
#else
  (void)tunables;
  return "";
#endif
}

void askForHugePages(char** argv) {
#if defined(__GLIBC__) && defined(__linux__)
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  const std::string value = hugePageTunables(tunables);
  if (value.empty()) return;
  const std::string before = tunables ? tunables : "";
  if (setenv("GLIBC_TUNABLES", value.c_str(), 1) != 0) return;
  execv("/proc/self/exe", argv);
  // Not run again (no /proc, say): go on as before, without the tunable.
  if (tunables)
    setenv("GLIBC_TUNABLES", before.c_str(), 1);
  else
    unsetenv("GLIBC_TUNABLES");
#else
  (void)argv;
#endif
}

bool hugePagesInUse() {
#if defined(__GLIBC__) && defined(__linux__)
  const std::string mode = hugePageMode();
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  return mode == "always" ||
         (mode == "madvise" && tunables && std::strstr(tunables, "glibc.malloc.hugetlb=1"));
#else
  return false;
#endif
}

}  // namespace ewa
