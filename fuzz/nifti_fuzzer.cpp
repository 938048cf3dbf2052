// Fuzz target: the NIfTI loader (".nii", or ".nii.gz" when the input starts like gzip).
#include "fuzz_case.h"
#include "volume_checks.h"

EWA_FUZZ_TARGET(nifti) {
  const bool gzip = size >= 2 && data[0] == 0x1f && data[1] == 0x8b;
  ewa::fuzz::fuzzVolumeFile(data, size, gzip ? ".nii.gz" : ".nii");
}
