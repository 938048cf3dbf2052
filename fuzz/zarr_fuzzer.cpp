// Fuzz target: a Zarr v2 array, its .zarray (the input's first section) and chunks 0.0.0, 0.0.1,
// 0.1.0 and 1.0.0 (the data sections, each decoded by the array's compressor).
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <string>

#include "fuzz_case.h"
#include "io/volume_loader.h"
#include "io/zarr_metadata.h"
#include "volume_checks.h"

namespace {

constexpr const char* kChunkNames[] = {"0.0.0", "0.0.1", "0.1.0", "1.0.0"};
// Missing chunks hold the fill value, so a few bytes of metadata may ask for a volume as large
// as the machine's memory, which the loader allows; the fuzzer's memory is 2 GiB.
constexpr uint64_t kMaxFuzzedBytes = uint64_t{64} << 20;

// A private folder holding in.zarr/ with the fixed names above, removed at exit.
class ZarrScratch {
 public:
  ZarrScratch() {
    for (const char* base : {"/dev/shm", "/tmp"}) {
      std::string folder = std::string(base) + "/ewa_fuzz_zarr_XXXXXX";
      if (::mkdtemp(folder.data())) {
        folder_ = folder;
        break;
      }
    }
    ::mkdir(array().c_str(), 0700);
  }
  ~ZarrScratch() {
    for (const char* name : kChunkNames) ::unlink((array() + "/" + name).c_str());
    ::unlink((array() + "/.zarray").c_str());
    ::rmdir(array().c_str());
    ::rmdir(folder_.c_str());
  }
  std::string array() const { return folder_ + "/in.zarr"; }

 private:
  std::string folder_;
};

void writeWhole(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(bytes.data(), std::streamsize(bytes.size()));
}

}  // namespace

EWA_FUZZ_TARGET(zarr) {
  static ZarrScratch scratch;
  const std::vector<std::string> sections = ewa::fuzz::splitSections(data, size);
  const std::string array = scratch.array();
  writeWhole(array + "/.zarray", sections[0]);
  for (size_t i = 0; i < 4; ++i) {
    const std::string chunk = array + "/" + kChunkNames[i];
    if (i + 1 < sections.size())
      writeWhole(chunk, sections[i + 1]);
    else
      ::unlink(chunk.c_str());
  }
  try {
    const ewa::ZarrArrayMeta meta = ewa::parseZarrArray(array + "/.zarray", sections[0]);
    uint64_t bytes = meta.chunkBytes / uint64_t(meta.chunks[0]);  // the item size, at least
    for (const int64_t n : meta.shape)
      if (__builtin_mul_overflow(bytes, uint64_t(n), &bytes)) return;
    if (bytes > kMaxFuzzedBytes || meta.chunkBytes > kMaxFuzzedBytes) return;
    ewa::fuzz::checkVolume(ewa::loadVolume(array));
  } catch (const ewa::LoadError& e) {
    const std::string message = e.what();
    EWA_FUZZ_CHECK(message.rfind(array, 0) == 0);
    EWA_FUZZ_CHECK(message.find('\n') == std::string::npos);
  }
}
