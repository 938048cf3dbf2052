// Fuzz target: the .dat loader (loadVolume on a ".dat" file, data files as data.N sections).
#include "fuzz_case.h"
#include "volume_checks.h"

EWA_FUZZ_TARGET(dat) {
  ewa::fuzz::fuzzVolumeFile(data, size, ".dat");
}
