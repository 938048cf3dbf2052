// OcclusionPyramid: the opacity pyramid occlusion culling tests splats against, and the
// counter of splats it culled (shaders/opacity_pyramid.comp.glsl, occlusion_test.glsl).
#pragma once

#include <cstddef>

#include "gl/buffer.h"
#include "gl/program.h"
#include "gl/shader_library.h"
#include "gl/texture.h"

namespace ewa {

class OcclusionPyramid {
 public:
  // Builds the compute program; a GL 4.5 context must be current. Throws gl::GlError.
  explicit OcclusionPyramid(const gl::ShaderLibrary& shaders);

  // (Re)allocates the pyramid for an image of width x height pixels: level 0 holds 2x2 pixel
  // blocks, padded to powers of two so that every level halves exactly.
  void resize(int width, int height);
  // Rebuilds every level from the accumulated image (`accum`, RGBA, alpha = opacity): a block
  // is opaque when all its pixels reached `threshold`. Call after the stencil marks the same
  // pixels, so that a culled splat is one whose fragments the stencil would all reject.
  void build(const gl::Texture& accum, float threshold);
  // Binds the pyramid to texture unit `unit` and the counter to the splat shaders' binding.
  void bindForDrawing(unsigned unit) const;
  // Sets the splat program's uniforms: whether a pyramid is bound, and its level count.
  void setUniforms(gl::Program& program, unsigned unit, bool enabled) const;
  // Zeroes the culled-splat counter; readCount() returns it (waits for the GPU).
  void resetCount();
  size_t readCount() const;
  size_t bytes() const;

 private:
  gl::Program program_;
  gl::Texture pyramid_;
  gl::Buffer counter_;
  int width_ = 0, height_ = 0;
  int levels_ = 0;
};

}  // namespace ewa
