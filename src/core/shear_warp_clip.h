// Crop box and clipping planes for shear-warp: per row of a slice, the cells whose sample
// positions the region keeps (voxel space, so the compositing loops only narrow their runs).
#pragma once

#include <glm/vec4.hpp>
#include <vector>

#include "core/clip_region.h"
#include "core/shear_warp_factorization.h"
#include "core/volume.h"

namespace ewa {

class ShearWarpClip {
 public:
  ShearWarpClip() = default;
  // The region's half-spaces in the view's slice coordinates (x along axisI, y along axisJ, k
  // the slice index, in voxels).
  ShearWarpClip(const ClipRegion& region, const Volume& volume, const ShearWarpFactorization& view);

  bool active() const { return !planes_.empty(); }
  // Cells i of row j of slice k sample the slice at (i + fracI, j + fracJ); the ones in
  // [*first, *last) have their sample inside the region (empty: *first >= *last). Ranges
  // already narrower are only narrowed further.
  void keptCells(int k, int j, double fracI, double fracJ, int* first, int* last) const;
  // The positions x of row y of slice k that the region keeps lie in [*lo, *hi] (empty:
  // *lo > *hi); ranges already narrower are only narrowed further. keptCells and perspective
  // views' rows both ask it.
  void keptSpan(int k, double y, double* lo, double* hi) const;

 private:
  std::vector<glm::dvec4> planes_;  // (a_x, a_y, a_k, b): a . (x, y, k) + b >= 0 is kept
};

}  // namespace ewa
