// Fuzz targets: one file each (fuzz/<name>_fuzzer.cpp), run by libFuzzer or replayed by the tests.
//
// A target is written once with EWA_FUZZ_TARGET(name) { ... } and becomes
//  * with EWA_FUZZ_LIBFUZZER defined: the LLVMFuzzerTestOneInput of the `<name>_fuzzer`
//    program (CMake option EWA_FUZZ, clang), and
//  * otherwise: an entry in fuzzTargets(), which the unit tests use to replay every seed in
//    fuzz/corpus/<name>/ and every crash kept in tests/data/fuzz/<name>/ on every build.
// The body gets `data` and `size`. Expected failures (LoadError for bad files) are caught by
// the body; anything else escaping it, or a failed EWA_FUZZ_CHECK, is a bug.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace ewa::fuzz {

using TargetFn = void (*)(const uint8_t* data, size_t size);

// Thrown by EWA_FUZZ_CHECK: an invariant the code promises does not hold.
class InvariantError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

// Name -> body of every target linked into this program (replay mode only).
std::map<std::string, TargetFn>& fuzzTargets();

struct TargetRegistration {
  TargetRegistration(const char* name, TargetFn fn) { fuzzTargets()[name] = fn; }
};

// A fuzz input as files in a private folder: the input up to the first kFileMarker line is
// written to `mainName`; each later section to data.0, data.1, ... (at most kMaxDataFiles), so
// detached headers can name their data files. The folder lives in /dev/shm when it can (no disk
// traffic) and is removed with this object. Only these fixed names are ever written.
class ScratchFiles {
 public:
  static constexpr const char* kFileMarker = "\n--ewa-fuzz-file--\n";
  static constexpr int kMaxDataFiles = 4;

  ScratchFiles();
  ~ScratchFiles();
  ScratchFiles(const ScratchFiles&) = delete;
  ScratchFiles& operator=(const ScratchFiles&) = delete;

  // Writes the files for one input (removing data files a previous input left); returns the
  // path of the main file.
  std::string write(const uint8_t* data, size_t size, const std::string& mainName);
  const std::string& folder() const { return folder_; }

 private:
  std::string folder_;
};

// The input split at kFileMarker lines: [main, data.0, data.1, ...].
std::vector<std::string> splitSections(const uint8_t* data, size_t size);

// Throws InvariantError("what") unless `ok`.
void check(bool ok, const char* what);

}  // namespace ewa::fuzz

#define EWA_FUZZ_CHECK(cond) ::ewa::fuzz::check((cond), #cond)

#ifdef EWA_FUZZ_LIBFUZZER
#define EWA_FUZZ_TARGET(name)                                               \
  static void ewaFuzzBody_##name(const uint8_t* data, size_t size);         \
  extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) { \
    ewaFuzzBody_##name(data, size);                                         \
    return 0;                                                               \
  }                                                                         \
  static void ewaFuzzBody_##name(const uint8_t* data, size_t size)
#else
#define EWA_FUZZ_TARGET(name)                                                                   \
  static void ewaFuzzBody_##name(const uint8_t* data, size_t size);                             \
  static const ::ewa::fuzz::TargetRegistration ewaFuzzRegistration_##name(#name,                \
                                                                          &ewaFuzzBody_##name); \
  static void ewaFuzzBody_##name(const uint8_t* data, size_t size)
#endif
