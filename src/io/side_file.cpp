// Bounded, non-blocking reads of side files (transfer functions, bookmarks, settings).
#include "io/side_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <new>
#include <stdexcept>

namespace ewa {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& why) {
  throw std::runtime_error(path + ": " + why);
}

std::string sizeText(uint64_t bytes) {
  return bytes >= (1u << 20) ? std::to_string(bytes >> 20) + " MiB"
                             : std::to_string(bytes) + " bytes";
}

}  // namespace

std::string problemText(const std::exception& e) {
  if (dynamic_cast<const std::bad_alloc*>(&e)) return "out of memory";
  std::string what = e.what();
  const size_t close = what.find("] ");
  if (what.rfind("[json.exception.", 0) == 0 && close != std::string::npos)
    what = what.substr(close + 2);
  for (char& c : what)
    if (c == '\n' || c == '\r') c = ' ';
  return what;
}

std::string readSideFile(const std::string& path, const std::string& what, uint64_t maxBytes) {
  // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer forever.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) fail(path, "cannot open: " + std::string(std::strerror(errno)));
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    const std::string why = std::strerror(errno);
    ::close(fd);
    fail(path, "cannot read: " + why);
  }
  if (!S_ISREG(st.st_mode)) {
    ::close(fd);
    fail(path, std::string(S_ISDIR(st.st_mode) ? "is a directory" : "is not a regular file") +
                   ", not a " + what);
  }
  if (uint64_t(st.st_size) > maxBytes) {
    ::close(fd);
    fail(path, "is " + sizeText(uint64_t(st.st_size)) + ", too big for a " + what + " (at most " +
                   sizeText(maxBytes) + ")");
  }
  std::string text(size_t(st.st_size), '\0');
  size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::read(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const std::string why = std::strerror(errno);
      ::close(fd);
      fail(path, "cannot read: " + why);
    }
    if (n == 0) break;  // shrank while read: what is there
    done += size_t(n);
  }
  ::close(fd);
  text.resize(done);
  return text;
}

}  // namespace ewa
