// Fuzz target: the MRC / CCP4 map loader (".mrc": a 1024-byte binary header, then the data).
#include "fuzz_case.h"
#include "volume_checks.h"

EWA_FUZZ_TARGET(mrc) {
  ewa::fuzz::fuzzVolumeFile(data, size, ".mrc");
}
