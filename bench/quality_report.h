// The filter-quality benchmark's outputs: a Markdown table and a montage image per scene.
#pragma once

#include <string>
#include <vector>

#include "bench/quality_benchmark.h"
#include "io/png_io.h"

namespace ewa {

// One Markdown table of every scene and mode.
std::string qualityTable(const std::vector<SceneQuality>& scenes);

// Top row: reference, ewa, swan, plain. Bottom row: the regions (reference darkened, beyond k
// tinted blue, anisotropic kernels tinted green, the distance k drawn in yellow), then each
// mode's |difference| from the reference amplified `gain` times. Tiles are separated by a
// gray gap.
Image8 qualityMontage(const SceneQuality& scene, double gain = 4.0);

}  // namespace ewa
