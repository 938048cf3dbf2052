// Unit tests of the background threads' lower priority.
#include "core/thread_priority.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <thread>

#if defined(__linux__)
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace ewa {
namespace {

#if defined(__linux__)
int thisThreadNice() {
  return getpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)));
}

TEST(ThreadPriority, TheCallingThreadAndItsNewThreadsRunLower) {
  const int before = thisThreadNice();
  int lowered = -100, inherited = -100;
  std::thread worker([&] {
    lowerThisThreadPriority();
    lowered = thisThreadNice();
    std::thread child([&] { inherited = thisThreadNice(); });
    child.join();
  });
  worker.join();
  EXPECT_EQ(lowered, std::max(before, kBackgroundNice));
  EXPECT_EQ(inherited, lowered);
  EXPECT_EQ(thisThreadNice(), before) << "the other threads keep theirs";
}
#endif

}  // namespace
}  // namespace ewa
