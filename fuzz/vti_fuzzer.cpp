// Fuzz target: the .vti loader (loadVolume on a ".vti" file, data files as data.N sections).
#include "fuzz_case.h"
#include "volume_checks.h"

EWA_FUZZ_TARGET(vti) {
  ewa::fuzz::fuzzVolumeFile(data, size, ".vti");
}
