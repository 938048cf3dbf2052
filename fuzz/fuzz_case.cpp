// Shared fuzzing plumbing: the target registry, scratch files in tmpfs, and invariant checks.
#include "fuzz_case.h"

#include <fcntl.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <string_view>

namespace ewa::fuzz {

std::map<std::string, TargetFn>& fuzzTargets() {
  // Filled by static registrations before main; read-only afterwards.
  static std::map<std::string, TargetFn> targets;
  return targets;
}

void check(bool ok, const char* what) {
  if (!ok) throw InvariantError(std::string("fuzz invariant failed: ") + what);
}

namespace {

std::string makeFolder() {
  const char* bases[] = {"/dev/shm", std::getenv("TMPDIR"), "/tmp"};
  for (const char* base : bases) {
    if (!base || !*base) continue;
    std::string templ = std::string(base) + "/ewa-fuzz-XXXXXX";
    if (::mkdtemp(templ.data())) return templ;
  }
  throw std::runtime_error("fuzz: cannot create a scratch folder");
}

void writeWhole(const std::string& path, std::string_view bytes) {
  // O_EXCL after unlink: never follow a link someone put there.
  ::unlink(path.c_str());
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) throw std::runtime_error("fuzz: cannot create " + path);
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n <= 0) {
      ::close(fd);
      throw std::runtime_error("fuzz: cannot write " + path);
    }
    done += static_cast<size_t>(n);
  }
  ::close(fd);
}

std::string dataName(int index) {
  return "data." + std::to_string(index);
}

}  // namespace

std::vector<std::string> splitSections(const uint8_t* data, size_t size) {
  const std::string_view all(reinterpret_cast<const char*>(data), size);
  const std::string_view marker(ScratchFiles::kFileMarker);
  std::vector<std::string> sections;
  size_t pos = 0;
  while (sections.size() < size_t{ScratchFiles::kMaxDataFiles}) {
    const size_t at = all.find(marker, pos);
    if (at == std::string_view::npos) break;
    sections.emplace_back(all.substr(pos, at - pos));
    pos = at + marker.size();
  }
  sections.emplace_back(all.substr(pos));  // the last section keeps any further markers
  return sections;
}

ScratchFiles::ScratchFiles() : folder_(makeFolder()) {}

ScratchFiles::~ScratchFiles() {
  ::unlink((folder_ + "/main").c_str());
  for (const char* ext : {".nrrd", ".nhdr", ".mhd", ".mha", ".dat", ".vti", ".raw", ".json"})
    ::unlink((folder_ + "/in" + ext).c_str());
  for (int i = 0; i < kMaxDataFiles; ++i) ::unlink((folder_ + "/" + dataName(i)).c_str());
  ::rmdir(folder_.c_str());
}

std::string ScratchFiles::write(const uint8_t* data, size_t size, const std::string& mainName) {
  const std::vector<std::string> sections = splitSections(data, size);
  const std::string mainPath = folder_ + "/" + mainName;
  writeWhole(mainPath, sections[0]);
  for (int i = 0; i < kMaxDataFiles; ++i) {
    const std::string path = folder_ + "/" + dataName(i);
    if (size_t(i) + 1 < sections.size())
      writeWhole(path, sections[size_t(i) + 1]);
    else
      ::unlink(path.c_str());
  }
  return mainPath;
}

}  // namespace ewa::fuzz
