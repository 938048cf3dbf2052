// GradientTexture: the volume's gradient as a 3D texture (core/gradient_volume.h), built on
// first use for shaded post-classified frames whose normals are read along each pixel's ray.
#pragma once

#include <cstddef>

#include "core/splat_attributes.h"
#include "core/volume.h"
#include "gl/texture.h"

namespace ewa {

class GradientTexture {
 public:
  // Makes the texture hold `volume`'s gradients under `mode` unless it does already (false);
  // throws gl::GlError when an axis exceeds GL_MAX_3D_TEXTURE_SIZE or the GL runs out of memory.
  bool sync(const Volume& volume, GradientMode mode);
  // The volume's voxels may have changed: the next sync builds again.
  void invalidate() { volume_ = nullptr; }
  // Frees the texture (frames that do not read it).
  void release();
  void bindUnit(unsigned unit) const;
  // GPU bytes held: 4 a voxel while it is in use.
  size_t bytes() const;

 private:
  gl::Texture texture_;
  const Volume* volume_ = nullptr;
  GradientMode mode_ = GradientMode::Central;
};

}  // namespace ewa
