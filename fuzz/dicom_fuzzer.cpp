// Fuzz target: the DICOM series loader through GDCM (in.dcm, further slices as data.N sections).
#include "fuzz_case.h"
#include "volume_checks.h"

EWA_FUZZ_TARGET(dicom) {
  ewa::fuzz::fuzzVolumeFile(data, size, ".dcm");
}
