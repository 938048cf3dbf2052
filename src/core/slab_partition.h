// SlabPartition: splats bucketed into image-aligned slabs (planes of constant camera depth),
// each splat listed in every slab its depth extent overlaps (a counting sort).
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "core/kernel_reach.h"
#include "core/splat_attributes.h"
#include "core/splat_set.h"

namespace ewa {

struct Slab {
  double nearDepth = 0.0;  // camera depth of the slab's front plane
  double farDepth = 0.0;   // and of its back plane
  uint32_t first = 0;      // offset into order()
  uint32_t count = 0;
};

// True when one slab ends where the other begins (in either order): the pre-integrated
// segment runs on from the one to the other.
bool slabsAdjacent(const Slab& a, const Slab& b);

// What the partition needs to know of the kernels: their reach (kernel_reach.h), and the
// camera rotation, voxel spacing and kernel width that give each kernel's depth variance.
struct DepthExtent {
  KernelReach reach;
  glm::dmat3 rotation{1.0};  // W: world to camera
  glm::dvec3 spacing{1.0};
  double kernelWidth = 1.0;  // kernels' sigma = kernelWidth * spacing (kernelSigma)
  // Where the slab grid is anchored (camera depth), when finite: slab planes then lie at
  // anchorDepth + n * thickness, so that processes holding different parts of one volume cut
  // the same slabs (ewaview-mpi). NaN: at the front of the nearest kernel.
  double anchorDepth = NAN;
};

// The first slab plane of a grid of `thickness` for kernels whose extents start at `front`:
// `front` itself, or the grid plane through `anchor` at or in front of it when `anchor` is
// finite (SlabPartition and GpuSlabPartition both place their planes by it).
double slabGridStart(double front, double thickness, double anchor);

// The depth one voxel spans along the camera's view axis, the unit slab thicknesses are counted
// in (RenderSettings::slabThickness): sqrt((W S W^T)_zz) for S = diag(spacing^2), so that a slab
// holds as many voxel layers face-on to thick slices as to thin ones (7 mm slices of 0.86 mm
// pixels seen face-on: 7 mm, not 0.86). Rounded to eighth-octave steps above the smallest
// spacing, so that an orbiting camera changes it (and the pre-integration table built for it)
// only now and then; exactly the spacing for isotropic voxels.
double viewSpacing(const glm::dmat3& rotation, const glm::dvec3& spacing);

// Slabs of `voxels` voxel depths (RenderSettings::slabThickness, at least 0.25) in world units
// for a volume of this spacing seen through a camera of this rotation.
double slabThicknessAlongView(double voxels, const glm::dmat3& rotation, const glm::dvec3& spacing);

// Where SlabPartition::build's grid starts without an anchor for these splats: the smallest
// front (centre depth minus depth reach, rounded to float as build rounds it) of the splats
// whose centre lies beyond nearCull and that `keep` accepts (by index; all when empty);
// INFINITY when none. A distributed run takes the least of its bricks' own splats' fronts, so
// its shared grid starts where the whole volume's would.
double nearestKernelFront(const SplatSet& splats, const AttributeList& attributes,
                          const glm::dvec3& origin, const glm::dmat4& view, double nearCull,
                          const DepthExtent& extent,
                          const std::function<bool(size_t)>& keep = nullptr);

class SlabPartition {
 public:
  // Order entries carry the splat index in the low 30 bits and these flags: the slab is the
  // first (last) one of that splat, so its share integrates the open tail in front (behind).
  static constexpr uint32_t kFirstSlab = 1u << 31;
  static constexpr uint32_t kLastSlab = 1u << 30;
  static constexpr uint32_t kIndexMask = kLastSlab - 1u;

  // Buckets splats whose center depth lies in (nearCull, inf) into slabs of `thickness` world
  // units starting at the front of the nearest kernel (or on extent.anchorDepth's grid); each splat
  // goes to every slab its depth extent overlaps. `attributes` (may be empty) marks surface splats,
  // whose extent and center follow their normal. `view` maps world to camera space; voxel (i,j,k)
  // sits at origin + (i,j,k) * spacing. Splats at or behind nearCull are left out.
  void build(const SplatSet& splats, const AttributeList& attributes, const glm::dvec3& origin,
             const glm::dmat4& view, double thickness, double nearCull, const DepthExtent& extent);

  const std::vector<uint32_t>& order() const { return order_; }
  // Slabs front (smallest depth) to back; empty slabs are dropped.
  const std::vector<Slab>& slabs() const { return slabs_; }
  // Number of splats listed at least once.
  size_t splatCount() const { return splatCount_; }
  // Smallest center depth among them (footprints are largest there).
  double nearestCenter() const { return nearestCenter_; }

 private:
  std::vector<uint32_t> order_;
  std::vector<Slab> slabs_;
  std::vector<float> lo_, hi_;  // per-splat depth extent, scratch kept between frames
  std::vector<uint32_t> bucket_;
  size_t splatCount_ = 0;
  double nearestCenter_ = 0.0;
};

}  // namespace ewa
