// Fuzz target: the image stack loader through stb_image (a ".png"; stb_image picks the format
// by content, so JPEG, BMP and PNM inputs reach their decoders too).
#include "fuzz_case.h"
#include "volume_checks.h"

EWA_FUZZ_TARGET(image) {
  ewa::fuzz::fuzzVolumeFile(data, size, ".png");
}
