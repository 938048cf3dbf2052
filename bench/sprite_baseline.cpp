// SpriteBaseline: one draw call of bare point sprites, timed with glFinish.
#include "bench/sprite_baseline.h"

#include <chrono>

#include "core/stopwatch.h"

namespace ewa {

SpriteBaseline::SpriteBaseline(const gl::ShaderLibrary& shaders)
    : program_(shaders.program("baseline_point.vert.glsl", "baseline_point.frag.glsl")),
      vao_(gl::VertexArray::create()) {}

void SpriteBaseline::setSprites(const std::vector<glm::vec3>& sprites) {
  count_ = sprites.size();
  buffer_.setData(GLsizeiptr(std::max<size_t>(1, count_) * sizeof(glm::vec3)),
                  count_ ? sprites.data() : nullptr, GL_STATIC_DRAW);
  vao_.setAttribute(0, 0, 3, GL_FLOAT, 0);
  vao_.setVertexBuffer(0, buffer_, 0, sizeof(glm::vec3));
}

double SpriteBaseline::draw(int width, int height, bool halfFloat) {
  if (target_.width() != width || target_.height() != height || halfFloat_ != halfFloat) {
    halfFloat_ = halfFloat;
    target_ = gl::Texture::create2D(halfFloat ? GL_RGBA16F : GL_RGBA32F, width, height);
    fbo_ = gl::Framebuffer::create();
    fbo_.attachColor(0, target_);
    fbo_.checkComplete();
  }
  glFinish();
  const auto start = std::chrono::steady_clock::now();
  const GLfloat zero[4] = {0, 0, 0, 0};
  fbo_.clearColor(0, zero);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, width, height);
  glEnable(GL_PROGRAM_POINT_SIZE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  program_.setVec2("uViewport", glm::vec2(width, height));
  glUseProgram(program_.id());
  glBindVertexArray(vao_.id());
  glDrawArrays(GL_POINTS, 0, GLsizei(count_));
  glDisable(GL_BLEND);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glFinish();
  return millisecondsSince(start);
}

}  // namespace ewa
