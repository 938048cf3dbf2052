// RenderTargets: the float slab, accumulation, stencil and 8-bit output images of one viewport
// size.
#pragma once

#include <cstddef>

#include "gl/framebuffer.h"
#include "gl/texture.h"

namespace ewa {

struct RenderTargets {
  int width = 0;
  int height = 0;
  gl::Texture slab;  // RGBA32F: (sum of colour * optical depth, sum of optical depth)
  // RGBA16F, post-classified with voxel normals: sum of weight * normal (colour attachment 1 of
  // the slab framebuffers). Absent otherwise: a slab framebuffer's draw buffers are its
  // attachments (gl::Framebuffer::attachColor), so the splats write it and the back halves only
  // where they are used.
  gl::Texture slabNormal;
  gl::Texture accum;    // RGBA32F: premultiplied colour and opacity, front to back
  gl::Texture output;   // RGBA8: the final picture over the background
  gl::Texture stencil;  // DEPTH24_STENCIL8, shared by slab and accumulation: opaque pixels
  gl::Framebuffer slabFbo;
  gl::Framebuffer accumFbo;
  gl::Framebuffer outputFbo;
  // Pre-integration between slabs: a second slab image, so that consecutive slabs alternate
  // between the two and the slab pass reads the one before (same normal and stencil images).
  gl::Texture slabOther;
  gl::Framebuffer slabOtherFbo;
  // Paired slabs in quarters: each slab image's back half, (weight * value, weight) of its
  // third and fourth quarters (RGBA32F, colour attachment 2); the image itself then holds the
  // first and second quarters.
  gl::Texture slabBack;
  gl::Texture slabOtherBack;

  // (Re)creates the images when the size changes, the second slab image when `pairedSlabs`
  // asks for it, the back halves when `quarters` does and the normal sums when `normalSums`
  // does (freed when not); throws gl::GlError if incomplete.
  void resize(int w, int h, bool pairedSlabs = false, bool quarters = false,
              bool normalSums = false);
  bool pairedSlabs() const { return bool(slabOther); }
  bool quarters() const { return bool(slabBack); }
  bool normalSums() const { return bool(slabNormal); }
  // Slab image `i` (0 or 1), its back half and its framebuffer; 1 only with paired slabs.
  const gl::Texture& slabImage(int i) const { return i ? slabOther : slab; }
  const gl::Texture& slabBackImage(int i) const { return i ? slabOtherBack : slabBack; }
  gl::Framebuffer& slabTarget(int i) { return i ? slabOtherFbo : slabFbo; }
  // Bytes the images hold: two RGBA32F (three with paired slabs, five in quarters), one
  // RGBA8, one depth-stencil (4 bytes) per pixel, and the RGBA16F normal sums if any.
  size_t bytes() const {
    return size_t(width) * size_t(height) *
           (16 + 16 + 4 + 4 + (normalSums() ? 8 : 0) + (pairedSlabs() ? 16 : 0) +
            (quarters() ? 32 : 0));
  }

 private:
  void createImages(int w, int h);
  // The framebuffer of one slab image: the image, the normal sums and its back half if any,
  // the stencil.
  gl::Framebuffer slabFramebuffer(const gl::Texture& image, const gl::Texture& back);
};

}  // namespace ewa
