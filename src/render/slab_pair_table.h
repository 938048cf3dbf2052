// SlabPairTable: the pre-integration texture of post-classified slabs (slab_preintegration.h),
// built on the CPU and uploaded when the transfer function or the slab thickness changes.
#pragma once

#include <cstddef>
#include <glm/vec4.hpp>
#include <vector>

#include "core/transfer_function.h"
#include "gl/texture.h"

namespace ewa {

class SlabPairTable {
 public:
  // Entries per axis: the shear-warp renderer's default, 1 MB of RGBA32F.
  static constexpr int kSize = 256;

  // The transfer function changed: the next prepare() builds the table again.
  void invalidate() { valid_ = false; }
  // Frees the texture (frames without pre-integration).
  void release() {
    texture_ = gl::Texture();
    prefix_ = gl::Texture();
    texels_ = {};
    prefixValues_ = {};
    valid_ = false;
  }
  // Makes the texture hold the table of `tf` over values [lo, hi] (mapped to texture
  // coordinates 0..1) for segments `distance` world units long (half a slab), unless it
  // already does. Returns the milliseconds it took (0 when the table was kept).
  double prepare(const TransferFunction& tf, double lo, double hi, double distance);
  // The pair table at `unit`, the extinction prefix (kExtinctionPrefixSize x 1, R32F) at
  // `prefixUnit`.
  void bindUnits(unsigned unit, unsigned prefixUnit) const {
    texture_.bindUnit(unit);
    prefix_.bindUnit(prefixUnit);
  }
  size_t bytes() const;
  // What the textures hold, for the CPU splatter's classification: slabPairTexels (kSize
  // squared) and the extinction prefix (kExtinctionPrefixSize).
  const std::vector<glm::vec4>& texels() const { return texels_; }
  const std::vector<float>& prefix() const { return prefixValues_; }

 private:
  gl::Texture texture_;
  gl::Texture prefix_;
  std::vector<glm::vec4> texels_;
  std::vector<float> prefixValues_;
  bool valid_ = false;
  double lo_ = 0.0, hi_ = 0.0, distance_ = 0.0;
};

}  // namespace ewa
