// Fuzz target: the .mhd loader (loadVolume on a ".mhd" file, data files as data.N sections).
#include "fuzz_case.h"
#include "volume_checks.h"

EWA_FUZZ_TARGET(metaimage) {
  ewa::fuzz::fuzzVolumeFile(data, size, ".mhd");
}
