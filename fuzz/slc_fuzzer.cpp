// Fuzz target: the VTK SLC loader (".slc", raw or run-length encoded slices).
#include "fuzz_case.h"
#include "volume_checks.h"

EWA_FUZZ_TARGET(slc) {
  ewa::fuzz::fuzzVolumeFile(data, size, ".slc");
}
