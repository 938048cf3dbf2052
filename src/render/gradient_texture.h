// GradientTexture: the volume's gradient as a 3D texture (core/gradient_volume.h) for shaded
// post-classified frames whose normals are read along each pixel's ray, or kept in memory for
// the CPU splatter, packed on a worker thread so a window's UI frames go on while it is built.
#pragma once

#include <chrono>
#include <cstddef>
#include <future>

#include "core/gradient_volume.h"
#include "core/splat_attributes.h"
#include "core/volume.h"
#include "gl/texture.h"

namespace ewa {

// Where the gradients go: up to a texture for the slab pass, or kept in memory for the CPU
// splatter (no texture).
enum class GradientUse { Texture, Memory };

class GradientTexture {
 public:
  GradientTexture() = default;
  ~GradientTexture();
  GradientTexture(const GradientTexture&) = delete;
  GradientTexture& operator=(const GradientTexture&) = delete;

  // Starts packing `volume`'s gradients under `mode` for `use` on a worker thread unless they
  // are held so or that build is under way (a build of others is waited for and dropped). The
  // volume must stay alive and unchanged until ready() or invalidate(). Throws gl::GlError when
  // an axis exceeds GL_MAX_3D_TEXTURE_SIZE (for a texture).
  void request(const Volume& volume, GradientMode mode, GradientUse use = GradientUse::Texture);
  // Whether the gradients are held as request() last asked for, uploading a finished build
  // (on the GL thread) in parts. Spends at most about `budgetMs` waiting for the worker and
  // uploading (infinity: until it is done), so a window's refinement step stays within its
  // budget. Throws gl::GlError when the GL runs out of memory.
  bool ready(double budgetMs);
  // True when `volume`'s gradients under `mode` are held for `use` (nothing to wait for).
  bool holds(const Volume& volume, GradientMode mode,
             GradientUse use = GradientUse::Texture) const {
    return volume_ == &volume && mode_ == mode && use_ == use &&
           (use == GradientUse::Memory || texture_);
  }
  // GradientUse::Memory: the gradients held (ready() true), unchanged until the next request,
  // invalidate() or release().
  const PackedGradients& packed() const { return packed_; }
  // release() unless the worker is still packing (waiting for it would hold a UI frame): then
  // nothing, and a later call frees it.
  void releaseWhenIdle();
  // The volume's voxels may change or go: waits for a build under way and forgets it, so the
  // next request builds again.
  void invalidate();
  // The same, and frees the texture (frames that do not read it).
  void release();
  void bindUnit(unsigned unit) const;
  // GPU bytes held: 4 a voxel while a texture is in use (in memory they count in the RSS).
  size_t bytes() const;

 private:
  // Uploads parts of packed_ from slice uploaded_ on until all are up (true) or `budgetMs` has
  // passed since `start`.
  bool uploadParts(double budgetMs, std::chrono::steady_clock::time_point start);
  // The build asked for is the one held.
  void holdPending();

  gl::Texture texture_;
  const Volume* volume_ = nullptr;  // what texture_ holds
  GradientMode mode_ = GradientMode::Central;
  GradientUse use_ = GradientUse::Texture;
  std::future<PackedGradients> pending_;  // the worker's build of pendingVolume_'s
  const Volume* pendingVolume_ = nullptr;
  GradientMode pendingMode_ = GradientMode::Central;
  GradientUse pendingUse_ = GradientUse::Texture;
  PackedGradients packed_;  // a finished build going up in parts, or held in memory
  int64_t uploaded_ = 0;    // slices of it uploaded
  bool uploading_ = false;
};

}  // namespace ewa
