// lowerThisThreadPriority: setpriority on the calling thread's id (Linux schedules threads
// apart, and a nice value is per thread there).
#include "core/thread_priority.h"

#if defined(__linux__)
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace ewa {

void lowerThisThreadPriority() {
#if defined(__linux__)
  const auto tid = static_cast<id_t>(syscall(SYS_gettid));
  if (getpriority(PRIO_PROCESS, tid) < kBackgroundNice)
    setpriority(PRIO_PROCESS, tid, kBackgroundNice);  // raising a nice value needs no rights
#endif
}

}  // namespace ewa
