// Atomic whole-file writes: mkstemp beside the target, write, fsync, rename.
#include "io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace ewa {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& why) {
  throw std::runtime_error(path + ": cannot write: " + why);
}

// The process umask, read without changing it for longer than two calls.
mode_t currentUmask() {
  const mode_t mask = ::umask(022);
  ::umask(mask);
  return mask;
}

// Writes `bytes` straight into a FIFO, character device or open file (`-o /dev/null`,
// `/dev/stdout`): renaming a file over one would replace the device node or link, not feed it.
void writeStraightInto(const std::string& path, std::string_view bytes) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) fail(path, std::strerror(errno));
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string why = n < 0 ? std::strerror(errno) : "no space written";
      ::close(fd);
      fail(path, why);
    }
    done += static_cast<size_t>(n);
  }
  if (::close(fd) != 0) fail(path, std::strerror(errno));
}

// What stands at `path` (links followed): nothing or a regular file is replaced by rename.
enum class Target { Replace, Stream, Folder, Other };

// A name of one of this process's open files (`/dev/stdout`, `/dev/fd/1`, a link into
// /proc/self/fd): whatever it is open on, even a regular file, is written into, so that
// `-o /dev/stdout > f.png` neither replaces the link nor misses the file.
bool namesAnOpenFile(const std::string& path) {
  const auto under = [](const std::string& p, const char* prefix) {
    return p.rfind(prefix, 0) == 0;
  };
  const auto open = [&](const std::string& p) {
    return under(p, "/dev/fd/") || under(p, "/proc/self/fd/") || p == "/dev/stdout" ||
           p == "/dev/stderr";
  };
  if (open(path)) return true;
  char target[256] = {};
  const ssize_t n = ::readlink(path.c_str(), target, sizeof target - 1);
  return n > 0 && open(std::string(target, size_t(n)));
}

Target targetKind(const std::string& path) {
  if (namesAnOpenFile(path)) return Target::Stream;
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || S_ISREG(st.st_mode)) return Target::Replace;
  if (S_ISDIR(st.st_mode)) return Target::Folder;
  if (S_ISFIFO(st.st_mode) || S_ISCHR(st.st_mode)) return Target::Stream;
  return Target::Other;  // block devices, sockets
}

}  // namespace

void writeFileAtomically(const std::string& path, std::string_view bytes, bool makeParents) {
  if (path.empty()) throw std::runtime_error("cannot write a file with an empty name");
  if (makeParents) {
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    std::error_code ec;
    if (!parent.empty()) std::filesystem::create_directories(parent, ec);
    if (ec) throw std::runtime_error(path + ": cannot create folder: " + ec.message());
  }
  switch (targetKind(path)) {
    case Target::Folder:
      fail(path, "is a directory");
    case Target::Other:
      fail(path, "not a regular file, FIFO or character device");
    case Target::Stream:
      return writeStraightInto(path, bytes);
    case Target::Replace:
      break;
  }
  const std::filesystem::path target(path);
  const std::filesystem::path folder = target.parent_path().empty() ? "." : target.parent_path();
  std::string temp = (folder / ("." + target.filename().string() + ".XXXXXX")).string();
  const int fd = ::mkstemp(temp.data());
  if (fd < 0) fail(path, std::strerror(errno));
  const auto cleanUp = [&](const std::string& why) {
    ::close(fd);
    ::unlink(temp.c_str());
    fail(path, why);
  };
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) cleanUp(n < 0 ? std::strerror(errno) : "no space written");
    done += static_cast<size_t>(n);
  }
  if (::fchmod(fd, 0666 & ~currentUmask()) != 0) cleanUp(std::strerror(errno));
  if (::fsync(fd) != 0) cleanUp(std::strerror(errno));
  if (::close(fd) != 0) {
    const std::string why = std::strerror(errno);
    ::unlink(temp.c_str());
    fail(path, why);
  }
  if (::rename(temp.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    ::unlink(temp.c_str());
    fail(path, why);
  }
}

std::string createTemporaryBeside(const std::string& path) {
  // A stream (a video) is renamed into place, so only over a regular file or nothing.
  if (targetKind(path) != Target::Replace) fail(path, "not a regular file");
  const std::filesystem::path target(path);
  const std::filesystem::path folder = target.parent_path().empty() ? "." : target.parent_path();
  std::string temp = (folder / ("." + target.filename().string() + ".XXXXXX")).string();
  const int fd = ::mkstemp(temp.data());
  if (fd < 0) fail(path, std::strerror(errno));
  const bool ok = ::fchmod(fd, 0666 & ~currentUmask()) == 0;
  const std::string why = ok ? "" : std::strerror(errno);
  ::close(fd);
  if (!ok) {
    ::unlink(temp.c_str());
    fail(path, why);
  }
  return temp;
}

bool sameExistingFile(const std::string& a, const std::string& b) {
  struct stat sa {
  }, sb{};
  if (::stat(a.c_str(), &sa) != 0 || ::stat(b.c_str(), &sb) != 0) return false;
  return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

std::string readTextFile(const std::string& path) {
  if (std::filesystem::is_directory(path)) throw std::runtime_error(path + ": is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open: " + std::strerror(errno));
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace ewa
