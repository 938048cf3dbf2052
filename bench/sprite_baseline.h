// SpriteBaseline: bare point sprites of given sizes with a trivial shader, the benchmark's
// yardstick.
#pragma once

#include <glm/vec3.hpp>
#include <vector>

#include "gl/buffer.h"
#include "gl/framebuffer.h"
#include "gl/program.h"
#include "gl/shader_library.h"
#include "gl/texture.h"
#include "gl/vertex_array.h"

namespace ewa {

class SpriteBaseline {
 public:
  explicit SpriteBaseline(const gl::ShaderLibrary& shaders);
  // Uploads (pixel x, pixel y, size) per sprite; not part of the timed draw.
  void setSprites(const std::vector<glm::vec3>& sprites);
  // Draws every sprite additively into a width x height image, RGBA16F with `halfFloat` (as the
  // splat renderer's slab images then are) else RGBA32F, and waits for the GPU; returns the
  // milliseconds the draw took.
  double draw(int width, int height, bool halfFloat);

 private:
  gl::Program program_;
  gl::VertexArray vao_;
  gl::Buffer buffer_;
  gl::Texture target_;
  gl::Framebuffer fbo_;
  bool halfFloat_ = false;  // target_'s format
  size_t count_ = 0;
};

}  // namespace ewa
