// Fuzz target: the TIFF stack loader through libtiff (a multi-page ".tif").
#include "fuzz_case.h"
#include "volume_checks.h"

EWA_FUZZ_TARGET(tiff) {
  ewa::fuzz::fuzzVolumeFile(data, size, ".tif");
}
