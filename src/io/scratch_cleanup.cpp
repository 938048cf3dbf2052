// Signal handlers that remove registered scratch folders with async-signal-safe calls only.
#include "io/scratch_cleanup.h"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <cstring>
#include <mutex>

namespace ewa {

namespace {

constexpr int kSlots = 16;
constexpr int kMaxDepth = 48;  // deeper trees are left to the next run's clean-up
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};

// A signal handler can reach only static storage: the registered folders live here, each an
// owned copy published through an atomic pointer (the handler never allocates or locks).
std::atomic<char*>& slot(int i) {
  static std::atomic<char*> slots[kSlots];
  return slots[i];
}

std::mutex& registryMutex() {
  static std::mutex m;
  return m;
}

struct LinuxDirent64 {
  ino64_t d_ino;
  off64_t d_off;
  unsigned short d_reclen;
  unsigned char d_type;
  char d_name[1];
};

// Removes `name` under `dirfd`, a folder's contents first; openat, getdents64, unlinkat and
// close are async-signal-safe. A listing read while its entries are removed may miss some, so
// a folder that is not empty yet is listed again (a few passes at most).
void removeTree(int dirfd, const char* name, int depth) {
  if (::unlinkat(dirfd, name, 0) == 0 || depth > kMaxDepth) return;
  for (int pass = 0; pass < 4; ++pass) {
    const int fd = ::openat(dirfd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0) return;
    alignas(8) char buffer[2048];
    long n = 0;
    while ((n = ::syscall(SYS_getdents64, fd, buffer, sizeof buffer)) > 0) {
      for (long at = 0; at < n;) {
        const auto* entry = reinterpret_cast<const LinuxDirent64*>(buffer + at);
        at += entry->d_reclen;
        if (std::strcmp(entry->d_name, ".") != 0 && std::strcmp(entry->d_name, "..") != 0)
          removeTree(fd, entry->d_name, depth + 1);
      }
    }
    ::close(fd);
    if (::unlinkat(dirfd, name, AT_REMOVEDIR) == 0) return;
  }
}

void onSignal(int signal) {
  for (int i = 0; i < kSlots; ++i)
    if (const char* folder = slot(i).exchange(nullptr)) removeTree(AT_FDCWD, folder, 0);
  // End the process as the signal would have.
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  ::sigaction(signal, &dfl, nullptr);
  ::raise(signal);
}

void installHandlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (const int s : kSignals) {
      struct sigaction old {};
      ::sigaction(s, nullptr, &old);
      // Leave a signal someone chose to ignore (nohup) or handle alone.
      if (old.sa_handler != SIG_DFL) continue;
      struct sigaction act {};
      act.sa_handler = onSignal;
      sigemptyset(&act.sa_mask);
      for (const int other : kSignals) sigaddset(&act.sa_mask, other);
      ::sigaction(s, &act, nullptr);
    }
  });
}

}  // namespace

void registerScratchFolder(const std::string& folder) {
  installHandlers();
  std::lock_guard<std::mutex> lock(registryMutex());
  for (int i = 0; i < kSlots; ++i) {
    if (slot(i).load() == nullptr) {
      slot(i).store(::strdup(folder.c_str()));
      return;
    }
  }
}

void unregisterScratchFolder(const std::string& folder) {
  std::lock_guard<std::mutex> lock(registryMutex());
  for (int i = 0; i < kSlots; ++i) {
    char* held = slot(i).load();
    if (held && folder == held && slot(i).compare_exchange_strong(held, nullptr)) {
      ::free(held);
      return;
    }
  }
}

}  // namespace ewa
