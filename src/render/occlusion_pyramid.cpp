// OcclusionPyramid: allocation, the per-level compute passes and the culled-splat counter.
#include "render/occlusion_pyramid.h"

#include <algorithm>
#include <cstdint>

#include "gl/gl_error.h"

namespace ewa {

namespace {

constexpr GLuint kCounterBinding = 4;  // Culled in shaders/occlusion_test.glsl
constexpr GLuint kGroup = 8;           // local size of opacity_pyramid.comp.glsl, per axis

int nextPowerOfTwo(int n) {
  int p = 1;
  while (p < n) p *= 2;
  return p;
}

}  // namespace

OcclusionPyramid::OcclusionPyramid(const gl::ShaderLibrary& shaders)
    : program_(shaders.computeProgram("opacity_pyramid.comp.glsl")),
      counter_(gl::Buffer::create(sizeof(uint32_t))) {}

void OcclusionPyramid::resize(int width, int height) {
  if (width == width_ && height == height_ && pyramid_) return;
  const int w0 = nextPowerOfTwo((width + 1) / 2), h0 = nextPowerOfTwo((height + 1) / 2);
  levels_ = 1;
  while ((std::max(w0, h0) >> (levels_ - 1)) > 1) ++levels_;
  pyramid_ = gl::Texture::create2D(GL_R8, w0, h0, levels_);
  pyramid_.setFilter(GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST);
  gl::checkGlError("occlusion pyramid");
  width_ = width;
  height_ = height;
}

void OcclusionPyramid::build(const gl::Texture& accum, float threshold) {
  glUseProgram(program_.id());
  accum.bindUnit(5);
  program_.setInt("uAccum", 5);
  program_.setFloat("uThreshold", threshold);
  program_.setIVec2("uImageSize", glm::ivec2(width_, height_));
  for (int level = 0; level < levels_; ++level) {
    const GLuint w = GLuint(std::max(1, pyramid_.width() >> level));
    const GLuint h = GLuint(std::max(1, pyramid_.height() >> level));
    program_.setInt("uLevel", level);
    glBindImageTexture(0, pyramid_.id(), std::max(0, level - 1), GL_FALSE, 0, GL_READ_ONLY, GL_R8);
    glBindImageTexture(1, pyramid_.id(), level, GL_FALSE, 0, GL_WRITE_ONLY, GL_R8);
    glDispatchCompute((w + kGroup - 1) / kGroup, (h + kGroup - 1) / kGroup, 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  }
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
}

void OcclusionPyramid::bindForDrawing(unsigned unit) const {
  if (pyramid_) pyramid_.bindUnit(unit);
  counter_.bindBase(GL_SHADER_STORAGE_BUFFER, kCounterBinding);
}

void OcclusionPyramid::setUniforms(gl::Program& program, unsigned unit, bool enabled) const {
  program.setInt("uOcclusion", enabled && pyramid_ ? 1 : 0);
  program.setInt("uOpaque", int(unit));
  program.setInt("uOpaqueLevels", levels_);
  program.setIVec2("uOpaqueSize", glm::ivec2(pyramid_.width(), pyramid_.height()));
}

void OcclusionPyramid::resetCount() {
  const uint32_t zero = 0;
  counter_.setSubData(0, sizeof zero, &zero);
}

size_t OcclusionPyramid::readCount() const {
  uint32_t n = 0;
  counter_.getSubData(0, sizeof n, &n);
  return n;
}

size_t OcclusionPyramid::bytes() const {
  size_t n = 0;
  for (int level = 0; level < levels_; ++level)
    n += size_t(std::max(1, pyramid_.width() >> level)) *
         size_t(std::max(1, pyramid_.height() >> level));
  return n + sizeof(uint32_t);
}

}  // namespace ewa
