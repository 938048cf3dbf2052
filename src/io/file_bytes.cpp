// File access for the loaders: POSIX open/pread with every size checked before a buffer exists.
#include "io/file_bytes.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include "io/load_failure.h"
#include "io/memory_limit.h"

namespace ewa {

namespace {

// An open regular file; closes itself.
class OpenFile {
 public:
  explicit OpenFile(const std::string& path) : path_(path) {
    if (path.empty()) failLoad(path, "empty file name");
    if (path.find('\0') != std::string::npos) failLoad(path, "file name contains a NUL byte");
    // O_NONBLOCK so that opening a FIFO cannot hang; it is then rejected as not regular.
    fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd_ < 0) {
      const int err = errno;
      if (err == ENOENT) failLoad(path, "no such file");
      if (err == ENOTDIR) failLoad(path, "no such file (a parent is not a folder)");
      if (err == EACCES) failLoad(path, "permission denied");
      failLoad(path, std::string("cannot open: ") + std::strerror(err));
    }
    struct stat st {};
    if (::fstat(fd_, &st) != 0) failLoad(path, std::string("cannot stat: ") + std::strerror(errno));
    if (S_ISDIR(st.st_mode)) failLoad(path, "is a directory, not a file");
    if (!S_ISREG(st.st_mode)) failLoad(path, "not a regular file");
    size_ = st.st_size < 0 ? 0 : static_cast<uint64_t>(st.st_size);
  }
  ~OpenFile() {
    if (fd_ >= 0) ::close(fd_);
  }
  OpenFile(const OpenFile&) = delete;
  OpenFile& operator=(const OpenFile&) = delete;

  uint64_t size() const { return size_; }

  // Reads exactly `length` bytes at `offset`; a file that shrank meanwhile is an error.
  void readAt(uint64_t offset, uint8_t* out, size_t length) const {
    while (length > 0) {
      const size_t chunk = std::min<size_t>(length, size_t{1} << 30);
      const ssize_t got = ::pread(fd_, out, chunk, static_cast<off_t>(offset));
      if (got < 0) {
        if (errno == EINTR) continue;
        failLoad(path_, std::string("read error: ") + std::strerror(errno));
      }
      if (got == 0) failLoad(path_, "file ended while reading (truncated or changing?)");
      out += got;
      offset += static_cast<uint64_t>(got);
      length -= static_cast<size_t>(got);
    }
  }

 private:
  std::string path_;
  int fd_ = -1;
  uint64_t size_ = 0;
};

std::string rangeProblem(const std::string& what, uint64_t offset, uint64_t length,
                         uint64_t available, const char* container = "the file") {
  return what + " needs " + std::to_string(length) + " bytes at offset " + std::to_string(offset) +
         ", but " + container + " has only " + std::to_string(available) +
         " bytes (truncated file or wrong sizes?)";
}

bool rangeFits(uint64_t offset, uint64_t length, uint64_t size) {
  return offset <= size && length <= size - offset;
}

}  // namespace

uint64_t regularFileSize(const std::string& path) {
  return OpenFile(path).size();
}

std::vector<uint8_t> readFileRange(const std::string& path, uint64_t offset, uint64_t length,
                                   const std::string& what) {
  OpenFile file(path);
  if (!rangeFits(offset, length, file.size()))
    failLoad(path, rangeProblem(what, offset, length, file.size()));
  checkAllocation(path, length, what);
  std::vector<uint8_t> bytes(static_cast<size_t>(length));
  file.readAt(offset, bytes.data(), bytes.size());
  return bytes;
}

void readFileRangeInto(const std::string& path, uint64_t offset, uint64_t length, uint8_t* out,
                       const std::string& what) {
  OpenFile file(path);
  if (!rangeFits(offset, length, file.size()))
    failLoad(path, rangeProblem(what, offset, length, file.size()));
  file.readAt(offset, out, static_cast<size_t>(length));
}

std::string readFilePrefix(const std::string& path, uint64_t limit,
                           const std::function<bool(std::string_view)>& isComplete) {
  OpenFile file(path);
  const uint64_t end = std::min(limit, file.size());
  checkAllocation(path, end, "header");
  std::string text;
  uint64_t want = std::min<uint64_t>(end, 64 * 1024);
  while (true) {
    const size_t have = text.size();
    text.resize(static_cast<size_t>(want));
    file.readAt(have, reinterpret_cast<uint8_t*>(text.data()) + have, text.size() - have);
    if (want >= end || isComplete(text)) return text;
    want = want > end / 4 ? end : want * 4;
  }
}

uint64_t skipLines(const std::string& path, uint64_t offset, int64_t lines) {
  if (lines <= 0) return offset;
  OpenFile file(path);
  std::vector<uint8_t> chunk(64 * 1024);
  int64_t left = lines;
  uint64_t pos = offset;
  while (pos < file.size()) {
    const size_t n = static_cast<size_t>(std::min<uint64_t>(chunk.size(), file.size() - pos));
    file.readAt(pos, chunk.data(), n);
    for (size_t i = 0; i < n; ++i) {
      if (chunk[i] == '\n' && --left == 0) return pos + i + 1;
    }
    pos += n;
  }
  failLoad(path, "line skip of " + std::to_string(lines) + " lines goes past the end of the file");
}

std::string siblingPath(const std::string& headerPath, const std::string& name) {
  const std::filesystem::path file(name);
  if (file.is_absolute()) return name;
  const std::filesystem::path folder = std::filesystem::path(headerPath).parent_path();
  if (folder.empty()) return name;
  return (folder / file).string();
}

void checkDataFileScope(const std::string& headerPath, const std::string& dataPath,
                        DataFileScope scope) {
  if (scope == DataFileScope::Anywhere) return;
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path folderName = fs::path(headerPath).parent_path();
  const fs::path folder = fs::weakly_canonical(folderName.empty() ? "." : folderName, ec);
  std::error_code ec2;
  const fs::path data = fs::weakly_canonical(dataPath, ec2);
  bool inside = !ec && !ec2;
  if (inside) {
    const fs::path relative = data.lexically_relative(folder);
    inside = !relative.empty() && *relative.begin() != ".." && relative.is_relative();
  }
  if (!inside)
    failLoad(headerPath, "names the data file " + quoteText(dataPath) +
                             " outside its own folder (--allow-outside-data opens it)");
}

FileSource::FileSource(std::string path, uint64_t base) : path_(std::move(path)), base_(base) {
  const uint64_t fileSize = regularFileSize(path_);
  if (base_ > fileSize) failLoad(path_, "data starts past the end of the file");
  size_ = fileSize - base_;
}

std::vector<uint8_t> FileSource::read(uint64_t offset, uint64_t length,
                                      const std::string& what) const {
  // Report file offsets, not offsets into the window.
  if (!rangeFits(offset, length, size_))
    failLoad(path_, rangeProblem(what, base_ + offset, length, base_ + size_));
  return readFileRange(path_, base_ + offset, length, what);
}

std::vector<uint8_t> MemorySource::read(uint64_t offset, uint64_t length,
                                        const std::string& what) const {
  if (!rangeFits(offset, length, bytes_.size()))
    failLoad(path_, rangeProblem(what, offset, length, bytes_.size(), "the decoded data"));
  checkAllocation(path_, length, what);
  const auto first = bytes_.begin() + static_cast<std::ptrdiff_t>(offset);
  return std::vector<uint8_t>(first, first + static_cast<std::ptrdiff_t>(length));
}

}  // namespace ewa
