// Framebuffer: a move-only owner of one GL framebuffer object with texture attachments (DSA).
#pragma once

#include <cstddef>
#include <vector>

#include "gl/gl_api.h"

namespace ewa::gl {

class Texture;

class Framebuffer {
 public:
  // An empty handle (id 0); no GL call.
  Framebuffer() = default;
  // Creates a framebuffer object without attachments.
  static Framebuffer create();

  ~Framebuffer();
  Framebuffer(Framebuffer&& other) noexcept;
  Framebuffer& operator=(Framebuffer&& other) noexcept;
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;

  // Attaches `level` of `texture` as GL_COLOR_ATTACHMENT0 + index and makes the draw buffers
  // list every attached colour index, so fragment output `index` lands in that texture.
  // The framebuffer does not own the texture, which must outlive its use here.
  void attachColor(GLuint index, const Texture& texture, GLint level = 0);
  // Attaches a depth (or depth-stencil) texture: GL_DEPTH_ATTACHMENT and the like.
  void attachDepth(const Texture& texture, GLenum attachment = GL_DEPTH_ATTACHMENT,
                   GLint level = 0);
  // Fragment outputs land only in the first `count` attached colour indices; the rest are
  // GL_NONE, so a pass that does not need them does not blend into them (a software
  // rasterizer blends every draw buffer, even where the output is zero). Attaching resets it.
  void setDrawBufferCount(size_t count);

  // glCheckNamedFramebufferStatus for the draw target.
  GLenum status() const;
  // Throws GlError "Framebuffer incomplete: GL_FRAMEBUFFER_INCOMPLETE_..." unless complete.
  void checkComplete() const;

  // Clears colour attachment `index` of this framebuffer to `rgba` (4 floats).
  void clearColor(GLint index, const GLfloat* rgba);
  void clearDepth(GLfloat depth = 1.0f);
  // Binds as GL_FRAMEBUFFER.
  void bind() const;

  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }

 private:
  void release();
  void applyDrawBuffers(size_t count);

  GLuint id_ = 0;
  std::vector<GLenum> drawBuffers_;
  size_t activeBuffers_ = 0;  // how many of drawBuffers_ receive output
};

}  // namespace ewa::gl
