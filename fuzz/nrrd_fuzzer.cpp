// Fuzz target: the .nrrd loader (loadVolume on a ".nrrd" file, data files as data.N sections).
#include "fuzz_case.h"
#include "volume_checks.h"

EWA_FUZZ_TARGET(nrrd) {
  ewa::fuzz::fuzzVolumeFile(data, size, ".nrrd");
}
