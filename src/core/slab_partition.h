// SlabPartition: splats bucketed into view-aligned slabs by camera depth (a counting sort).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "core/splat_set.h"

namespace ewa {

struct Slab {
  double nearDepth = 0.0;  // camera depth of the slab's front plane
  uint32_t first = 0;      // offset into order()
  uint32_t count = 0;
};

class SlabPartition {
 public:
  // Buckets splats whose depth lies in (nearCull, inf) into slabs of `thickness` world units
  // starting at the smallest such depth. Splats at or behind nearCull are left out.
  // `view` maps world to camera space; voxel (i,j,k) sits at origin + (i,j,k) * spacing.
  void build(const SplatSet& splats, const glm::dvec3& origin, const glm::dvec3& spacing,
             const glm::dmat4& view, double thickness, double nearCull);

  const std::vector<uint32_t>& order() const { return order_; }
  // Slabs front (smallest depth) to back; empty slabs are dropped.
  const std::vector<Slab>& slabs() const { return slabs_; }

 private:
  std::vector<uint32_t> order_;
  std::vector<Slab> slabs_;
  std::vector<float> depth_;     // scratch, kept to avoid reallocating every frame
  std::vector<uint32_t> bucket_;
};

}  // namespace ewa
