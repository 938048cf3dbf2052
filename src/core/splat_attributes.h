// Per-splat attributes computed once per volume and classification: gradient normals for
// shading and the iso-surface voxels that become flat surface splats (EWA paper, section 5).
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/default_init_allocator.h"
#include "core/post_classification.h"
#include "core/splat_set.h"
#include "core/transfer_function.h"
#include "core/value_prefilter.h"
#include "core/volume.h"

namespace ewa {

enum class GradientMode { Central = 0, Smooth = 1 };
enum class SurfaceCriterion { None = 0, Value = 1, Opacity = 2 };

const char* gradientModeName(GradientMode mode);
bool parseGradientMode(const std::string& text, GradientMode* mode);
std::vector<std::string> gradientModeNames();  // every name parseGradientMode accepts

// What decides which voxels are splats, and of which kind. Changing it rebuilds the splats;
// the camera and the light never do.
struct Classification {
  GradientMode gradient = GradientMode::Central;
  // Value: voxels >= threshold with a 6-neighbour below it (the iso-surface's boundary layer).
  // Opacity: the same on the transfer function's opacity, among voxels whose gradient
  // magnitude times the smallest spacing is at least minGradient of the value range.
  SurfaceCriterion surface = SurfaceCriterion::None;
  double threshold = 0.5;
  double minGradient = 0.0;
  // Post: splats carry values, zero-opacity voxels within squared distance postMarginSquared
  // (in voxel steps) of visible ones (or of a transfer-function crossing) are kept, and there
  // are no surface splats.
  ClassificationMode mode = ClassificationMode::Pre;
  // Set from the kernel's reach (splatClassification in render/renderer.h).
  int postMarginSquared = 2;
  // Post: the splats' values are prefiltered with this strength (prefilteredValue), so the
  // reconstruction comes nearer interpolating the voxels; 0 keeps the data's values.
  double prefilter = kDefaultPrefilter;
  bool operator==(const Classification& o) const {
    return gradient == o.gradient && surface == o.surface && threshold == o.threshold &&
           minGradient == o.minGradient && mode == o.mode &&
           (mode == ClassificationMode::Pre ||
            (postMarginSquared == o.postMarginSquared && prefilter == o.prefilter));
  }
  bool operator!=(const Classification& o) const { return !(*this == o); }
};

// The viewer's default: post-classified (the fields above at their defaults otherwise).
inline Classification postClassification() {
  Classification c;
  c.mode = ClassificationMode::Post;
  return c;
}

// 8 bytes a splat, beside its PackedSplat: packHalf2x16(nx, ny), packHalf2x16(nz, kind).
// n is the unit outward normal -grad/|grad| in world space (0 where the gradient vanishes:
// unshaded). kind 0: a volume splat; kind in [2, 4]: a surface splat whose center moves by
// (kind - 3) * smallest spacing along n, onto the interpolated iso-surface.
struct PackedAttributes {
  uint32_t nxy;
  uint32_t nzKind;
};

// Filled in whole by classifySplats' parallel pass: not zeroed first on one thread.
using AttributeList = std::vector<PackedAttributes, DefaultInitAllocator<PackedAttributes>>;

struct UnpackedAttributes {
  glm::dvec3 normal{0.0};
  bool surface = false;
  double offset = 0.0;  // along the normal, in units of the smallest spacing
};

PackedAttributes packAttributes(const glm::dvec3& normal, bool surface, double offset);
UnpackedAttributes unpackAttributes(const PackedAttributes& a);

// The gradient of the volume at voxel (i,j,k) in value per world unit: central differences
// (one-sided at the border), or for Smooth the same smoothed by [1 2 1]/4 across each axis.
glm::dvec3 volumeGradient(const Volume& volume, int64_t i, int64_t j, int64_t k, GradientMode mode);

struct ClassifiedSplats {
  SplatSet splats;
  AttributeList attributes;  // one per splat, same order
  size_t surfaceCount = 0;
};

// The splats of `volume` under `tf` (voxels with opacity > 0, plus surface voxels whatever
// their opacity; post: plus postClassificationMask's margin, no surfaces), their normals and
// surface flags.
// Throws SplatLimitError when more than `maxSplats` voxels would be kept. Runs on `threads`
// threads as parallelChunks takes it (0: the machine's cores); the result is the same for any.
ClassifiedSplats classifySplats(const Volume& volume, const TransferFunction& tf,
                                const Classification& c, size_t maxSplats = SIZE_MAX,
                                unsigned threads = 0);

}  // namespace ewa
