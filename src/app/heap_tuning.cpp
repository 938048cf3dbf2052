// keepFreedHeapForReuse: glibc's trim threshold raised for llvmpipe's draw-sized allocations.
#include "app/heap_tuning.h"

#include <cstdlib>
#include <cstring>

#if defined(__GLIBC__)
#include <malloc.h>
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

}  // namespace ewa
