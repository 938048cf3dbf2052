// Scoped binds: set a piece of GL binding state for one block and restore the previous value.
#pragma once

#include "gl/gl_api.h"

namespace ewa::gl {

// Binds a framebuffer (0 = default) as GL_FRAMEBUFFER and sets the viewport to
// (0, 0, width, height); restores the previous draw/read framebuffers and viewport.
class ScopedFramebufferBind {
 public:
  ScopedFramebufferBind(GLuint framebuffer, GLsizei width, GLsizei height) {
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previousDraw_);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previousRead_);
    glGetIntegerv(GL_VIEWPORT, previousViewport_);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glViewport(0, 0, width, height);
  }
  ~ScopedFramebufferBind() {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(previousDraw_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(previousRead_));
    glViewport(previousViewport_[0], previousViewport_[1], previousViewport_[2],
               previousViewport_[3]);
  }
  ScopedFramebufferBind(const ScopedFramebufferBind&) = delete;
  ScopedFramebufferBind& operator=(const ScopedFramebufferBind&) = delete;

 private:
  GLint previousDraw_ = 0, previousRead_ = 0;
  GLint previousViewport_[4] = {0, 0, 0, 0};
};

// glUseProgram for one block.
class ScopedProgramUse {
 public:
  explicit ScopedProgramUse(GLuint program) {
    glGetIntegerv(GL_CURRENT_PROGRAM, &previous_);
    glUseProgram(program);
  }
  ~ScopedProgramUse() { glUseProgram(static_cast<GLuint>(previous_)); }
  ScopedProgramUse(const ScopedProgramUse&) = delete;
  ScopedProgramUse& operator=(const ScopedProgramUse&) = delete;

 private:
  GLint previous_ = 0;
};

// glBindVertexArray for one block.
class ScopedVertexArrayBind {
 public:
  explicit ScopedVertexArrayBind(GLuint vertexArray) {
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &previous_);
    glBindVertexArray(vertexArray);
  }
  ~ScopedVertexArrayBind() { glBindVertexArray(static_cast<GLuint>(previous_)); }
  ScopedVertexArrayBind(const ScopedVertexArrayBind&) = delete;
  ScopedVertexArrayBind& operator=(const ScopedVertexArrayBind&) = delete;

 private:
  GLint previous_ = 0;
};

}  // namespace ewa::gl
