// Synthetic test volumes: Marschner-Lobb, a ball, a box, Swan's checkerboard, Zwicker's zebra.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/transfer_function.h"
#include "core/volume.h"

namespace ewa {

struct SyntheticVolume {
  Volume volume;
  std::optional<TransferFunction> transferFunction;  // a function that shows it as intended
  std::string name;                                  // canonical spec, e.g. "sphere:64"
};

// spec (world units are voxels, origin 0):
//   "marschner-lobb[:N]"  N³ float32 Marschner-Lobb signal (fM = 6, alpha = 0.25) over [-1,1]³,
//                         default N 41; TF shows the region above the 0.5 iso-surface.
//   "sphere[:N]"          N³ uint8, 255 inside radius 0.4 N with a ~1.5-voxel smooth edge,
//                         default N 64; TF: a semi-transparent orange ball.
//   "box[:N]"             N³ uint8, all 255 (a homogeneous medium), default N 32; TF: faint fog.
//   "checkerboard[:S]"    Swan's Fig. 7: a 400×400×1 uint8 sheet of S×S-voxel squares (default
//                         S 10) holding 1 (red) and 2 (white), starting with 1 at the origin.
//   "zebra[:RATIO]"       Zwicker's Fig. 8: a (256·RATIO)×256×1 float32 sheet with spacing
//                         (1/RATIO, 1, 1), black/white wavy stripes across x whose frequency rises
//                         along x; RATIO 1..16, default 4.
// N must lie in [2, 512]. Throws std::invalid_argument("--synthetic <spec>: problem") for unknown
// names, malformed or out-of-range numbers.
SyntheticVolume makeSyntheticVolume(const std::string& spec);
// A synthetic volume made box by box (a distributed run's bricks): the whole volume's dims, and
// the voxels lo <= (i, j, k) < hi where the whole volume has them (origin at lo), the same
// values makeSyntheticVolume gives them. Only Marschner-Lobb is evaluated voxel by voxel; the
// others (sheets, or made whole) give nothing. Throws as makeSyntheticVolume.
struct SyntheticRegionSource {
  std::array<int64_t, 3> dims{0, 0, 0};
  std::function<SyntheticVolume(const std::array<int64_t, 3>& lo, const std::array<int64_t, 3>& hi)>
      make;
};
std::optional<SyntheticRegionSource> syntheticRegionSource(const std::string& spec);

// The specs' forms, "marschner-lobb[:N]", ... in the order above (the --synthetic help).
std::vector<std::string> syntheticVolumeForms();

// The Marschner-Lobb test signal at (x, y, z) in [-1, 1]³ (fM = 6, alpha = 0.25), in [0, 1].
double marschnerLobb(double x, double y, double z);

}  // namespace ewa
