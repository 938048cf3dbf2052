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
// splatter. Both may be held at once (frames of both splatters from one renderer).
enum class GradientUse { Texture, Memory };

class GradientTexture {
 public:
  GradientTexture() = default;
  ~GradientTexture();
  GradientTexture(const GradientTexture&) = delete;
  GradientTexture& operator=(const GradientTexture&) = delete;

  // Makes `volume`'s gradients under `mode` ready for `use`: nothing where they are held so;
  // packed on a worker thread, or (a texture) uploaded from those held in memory, otherwise.
  // Other gradients held or under way are dropped. The volume must stay alive and unchanged
  // until ready() or invalidate(). Throws gl::GlError when an axis exceeds
  // GL_MAX_3D_TEXTURE_SIZE (for a texture).
  void request(const Volume& volume, GradientMode mode, GradientUse use = GradientUse::Texture);
  // Whether the gradients are held as request() last asked for, uploading a finished build
  // (on the GL thread) in parts. Spends at most about `budgetMs` waiting for the worker and
  // uploading (infinity: until it is done), so a window's refinement step stays within its
  // budget. Throws gl::GlError when the GL runs out of memory.
  bool ready(double budgetMs);
  // True when `volume`'s gradients under `mode` are held for `use` (nothing to wait for).
  bool holds(const Volume& volume, GradientMode mode,
             GradientUse use = GradientUse::Texture) const {
    if (volume_ != &volume || mode_ != mode) return false;
    return use == GradientUse::Texture ? texture_ && !uploading_ : keepPacked_ && !pending_.valid();
  }
  // GradientUse::Memory: the gradients held (ready() true), unchanged until the next request
  // for other gradients, invalidate() or release().
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
  // Throws gl::GlError where `volume` is too large for a 3D texture.
  static void checkTextureSize(const Volume& volume);
  // Makes the texture for packed_ and starts its upload.
  void beginUpload();
  // Uploads parts of packed_ from slice uploaded_ on until all are up (true) or `budgetMs` has
  // passed since `start`.
  bool uploadParts(double budgetMs, std::chrono::steady_clock::time_point start);

  gl::Texture texture_;
  const Volume* volume_ = nullptr;  // whose gradients are held or under way
  GradientMode mode_ = GradientMode::Central;
  GradientUse use_ = GradientUse::Texture;  // what request() last asked for
  bool wantTexture_ = false;                // a texture was asked for
  bool keepPacked_ = false;                 // packed_ stays in memory (GradientUse::Memory)
  std::future<PackedGradients> pending_;    // the worker's build
  PackedGradients packed_;                  // held in memory, or a finished build going up in parts
  int64_t uploaded_ = 0;                    // slices of it uploaded
  bool uploading_ = false;
};

}  // namespace ewa
