// Fuzz target: the legacy VTK loader (".vtk" STRUCTURED_POINTS, ASCII or binary).
#include "fuzz_case.h"
#include "volume_checks.h"

EWA_FUZZ_TARGET(vtk) {
  ewa::fuzz::fuzzVolumeFile(data, size, ".vtk");
}
