// Fuzz target: archives (libarchive: zip, tar, compressed tars, 7z) and what they hold.
#include "fuzz_case.h"
#include "volume_checks.h"

EWA_FUZZ_TARGET(archive) {
  ewa::fuzz::fuzzVolumeFile(data, size, ".zip");
}
